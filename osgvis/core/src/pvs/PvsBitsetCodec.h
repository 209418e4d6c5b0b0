// SPDX-License-Identifier: MIT
#pragma once
// Run-length coding of a VisibleSet for the `.pvs` file: the number of runs, then alternating runs
// of clear and set bits (the first run is clear and may be empty, every later run is non-empty) as
// LEB128 varints. A PVS is a few clustered ranges of ids, so it shrinks to a few bytes per cell,
// and an empty or full set takes two or three bytes whatever its capacity.
#include "PvsByteStream.h"

#include <osgVis/core/scene/VisibleSet.h>

namespace osgVis::core
{
void encodeBitset(const VisibleSet& set, PvsByteWriter& out);
// Reads a set of `capacity` bits; throws PvsFormatError unless the runs are canonical and sum to
// exactly `capacity`. Validates before allocating, so a wrong capacity costs no memory.
VisibleSet decodeBitset(PvsByteReader& in, std::uint64_t capacity);
} // namespace osgVis::core
