// SPDX-License-Identifier: MIT
#pragma once
// SceneTiles in a version 2 `.pvs` file, the body of its tile-key section (docs/pvs-format.md):
// the root fingerprint, the tiles (file, fingerprint, owner) and each object's tile.
#include "PvsByteStream.h"

#include <osgVis/core/scene/SceneTiles.h>

#include <cstdint>

namespace osgVis::core
{
// Keys of a complete database, one per object, locals their ranks in id order; throws
// "cannot encode .pvs: ...".
void checkTilesEncodable(const SceneTiles& tiles, std::uint32_t objectCount);
void writeTiles(PvsByteWriter& out, const SceneTiles& tiles);
// Validates everything: file names non-empty and distinct, owners among the objects, ownership
// without cycles (a tile's owner lies in another tile, and so on up to the root), every object's
// tile among the tiles. Locals are numbered as they were written; `complete` is set.
SceneTiles readTiles(PvsByteReader& in, std::uint32_t objectCount);
} // namespace osgVis::core
