// SPDX-License-Identifier: MIT
#pragma once
// `osgvispvs MODEL -o OUT.pvs --method multifocal`: view cells (a grid, the cells a walk passes
// through, the model's osgVis::Cell markers) and the multifocal PVS of each, or of a range of
// them, written as a version 2 .pvs with view cells and no portals.
#include "PvsToolOptions.h"

namespace osgVis::pvstool
{
// Exit status 0; throws ToolError (exit 1) for files that cannot be read or written, an empty
// scene, a bad cell layout or a range outside it.
int bakeViewCells(const PvsToolOptions& options);
} // namespace osgVis::pvstool
