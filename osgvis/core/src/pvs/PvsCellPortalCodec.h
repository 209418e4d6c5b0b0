// SPDX-License-Identifier: MIT
#pragma once
// CellPortalData in a `.pvs` file: the parts BNDS, CELL, NAME, KDTR, PORT, CPRT, SRCS and STAT
// (docs/pvs-format.md), version 1's sections after its model header and the payload of version 2's
// cell-portal section. Version 1's STAT also holds the bake seconds, which are read and dropped.
#include "PvsSections.h"

#include <osgVis/core/pvs/CellPortalData.h>

#include <cstdint>

namespace osgVis::core
{
// What must hold before writing (counts that fit, one portal list, source and name per cell,
// bitset capacities); throws PvsFormatError "cannot encode .pvs: ...".
void checkCellPortalEncodable(const CellPortalData& data);
void writeCellPortalParts(PvsByteWriter& out, const CellPortalData& data);
// Reads the parts into `data`, whose objectCount the model header gave.
void readCellPortalParts(PvsByteReader& in, CellPortalData& data, std::uint32_t version);
} // namespace osgVis::core
