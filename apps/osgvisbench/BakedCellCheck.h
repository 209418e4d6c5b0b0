// SPDX-License-Identifier: MIT
#pragma once
// osgvisbench --scene FILE.pvs --volume-cells N: the view cells a multifocal bake wrote, checked
// against the volume oracle (objects): per cell, the objects some sampled eye of the cell sees that
// its PVS lacks (must be none), and the triangles of the PVS's objects over those of the objects
// seen (how much more than the sampled exact union the PVS draws).
#include "BenchOptions.h"

#include <iosfwd>

namespace osgVis::bench
{
// Prints a line per cell and the summary on `out` (and writes --json). Returns 0, or 1 when a PVS
// lacks an object the oracle saw. Throws for a .pvs without view cells or one the plugin refused.
int runBakedCellCheck(const BenchOptions& options, std::ostream& out);
} // namespace osgVis::bench
