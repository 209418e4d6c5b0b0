// SPDX-License-Identifier: MIT
#pragma once
// Which objects may give occluders: shared by the polygon builder and the solid sections.
#include <osgVis/core/scene/Scene.h>


namespace osgVis::core
{
/// Static, opaque, bounded, with a drawn side; stated occluders always, other objects when
/// `sceneGeometry` and not OBJECT_NO_AUTO_OCCLUDER.
bool isEligible(const SceneObject& object, bool sceneGeometry);
} // namespace osgVis::core
