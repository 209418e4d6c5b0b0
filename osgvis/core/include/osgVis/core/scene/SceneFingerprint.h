// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A model's identity for the data baked from it (a `.pvs` file refuses a model that does not match).
#include <osgVis/core/scene/Scene.h>

#include <cstdint>

namespace osgVis::core
{
/// Identifies a model for its baked data: FNV-1a 64 over the object count and, per object, its
/// bounds, triangle count and static flags (DYNAMIC, TRANSPARENT, ALWAYS_VISIBLE, NO_AUTO_OCCLUDER,
/// CULL_*). Triangles are not hashed, so an extraction without them fingerprints the same.
std::uint64_t sceneFingerprint(const Scene& scene);
} // namespace osgVis::core
