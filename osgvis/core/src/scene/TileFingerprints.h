// SPDX-License-Identifier: MIT
#pragma once
// Internal: every tile's fingerprint (SceneFingerprint.h, tileFingerprint) in one pass over the
// objects, the root's last: what each extraction of a paged scene computes (finishSceneTiles).
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
// tiles.files.size() + 1 values: tile 0, 1, ..., then RootTile.
std::vector<std::uint64_t> tileFingerprintsOf(const Scene& scene, const SceneTiles& tiles);
} // namespace osgVis::core
