// SPDX-License-Identifier: MIT
#pragma once
// Which objects may give occluders, and their triangles: shared by the polygon builder and the
// solid sections.
#include <osgVis/core/scene/Scene.h>

#include <utility>

namespace osgVis::core
{
/// Static, opaque, bounded, with a drawn side; stated occluders always, other objects when
/// `sceneGeometry` and not OBJECT_NO_AUTO_OCCLUDER.
bool isEligible(const SceneObject& object, bool sceneGeometry);
/// Triangles [first, end) of an object, clipped to what the scene holds.
std::pair<std::size_t, std::size_t> triangleRange(const Scene& scene, const SceneObject& object);
} // namespace osgVis::core
