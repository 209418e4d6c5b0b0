// SPDX-License-Identifier: MIT
#pragma once
// osgvisbench --volume: visibility from a volume of viewpoints. The multifocal volume PVS
// (core/multifocal) of one box of eyes, timed, against the volume oracle (osgVis::oracle::
// VolumeOracle: eyes at the box's corners, face centres and random interior points, six cube
// faces each, objects and triangles): objects and triangles kept, culled and missing (must be 0),
// triangles facing away from every point of the box, and the efficacy on the others.
#include "BenchOptions.h"

#include <iosfwd>

namespace osgVis::bench
{
// Prints the table on `out` (and writes --json). Returns the exit status: 0, or 1 when the PVS
// lacks an object or triangle the oracle saw. Throws what loading the scene and the oracle throw.
int runVolumeBench(const BenchOptions& options, std::ostream& out);
} // namespace osgVis::bench
