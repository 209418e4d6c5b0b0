// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A model's identity for the data baked from it (a `.pvs` file refuses a model that does not match).
#include <osgVis/core/scene/Scene.h>

#include <cstdint>

namespace osgVis::core
{
struct SceneTiles;

/// Identifies a model for its baked data: FNV-1a 64 over the object count and, per object, its
/// bounds, triangle count and static flags (DYNAMIC, TRANSPARENT, ALWAYS_VISIBLE, NO_AUTO_OCCLUDER,
/// CULL_*). Triangles are not hashed, so an extraction without them fingerprints the same.
/// What version 1 `.pvs` files store; sceneGeometryFingerprint also sees edits inside an object.
std::uint64_t sceneFingerprint(const Scene& scene);

/// sceneFingerprint's fields plus every triangle's vertices, in order, quantized to a grid of
/// step L * 2^-20 from the min corner of scene.bounds(), L its largest extent (step 1 for a scene
/// without extent): a hole cut into a wall changes it though the wall keeps its bounds, triangle
/// count and flags, while a vertex moved by much less than a step keeps its hash unless it lies
/// near a grid boundary. Non-finite coordinates hash as one marker. Needs the scene's triangles:
/// throws std::invalid_argument when an object's triangles are not in scene.triangles (a scene
/// extracted without them). docs/pvs-format.md says why this grid.
std::uint64_t sceneGeometryFingerprint(const Scene& scene);

/// sceneFingerprint's fields of one tile's objects (SceneTiles.h), in id order, after their count:
/// equal for a tile loaded again whatever else is loaded and whatever ids its objects got.
std::uint64_t tileFingerprint(const Scene& scene, const SceneTiles& tiles, std::uint32_t tile);
} // namespace osgVis::core
