// SPDX-License-Identifier: MIT
#pragma once
// ViewCellPvs in a version 2 `.pvs` file, the body of its view-cell section (docs/pvs-format.md):
// u32 total cells, u32 cell count n, then n cells of u32 absolute index, box and object bitset.
#include "PvsByteStream.h"

#include <osgVis/core/pvs/ViewCellPvs.h>

#include <cstdint>

namespace osgVis::core
{
// Parallel arrays of one length and bitsets of `objectCount` bits; throws "cannot encode .pvs: ...".
void checkViewCellsEncodable(const ViewCellPvs& cells, std::uint32_t objectCount);
void writeViewCells(PvsByteWriter& out, const ViewCellPvs& cells);
// Validates everything: indices strictly ascending below the total, boxes finite with min <= max,
// every bitset of `objectCount` bits.
ViewCellPvs readViewCells(PvsByteReader& in, std::uint32_t objectCount);
} // namespace osgVis::core
