// SPDX-License-Identifier: MIT
#pragma once
// `osgvispvs MODEL -o OUT.pvs`: the bake of either method in resumable units, in this process or
// over MPI ranks, joined into OUT.pvs (see BakeJob.h, BakeState.h, MpiBake.h).
#include "PvsToolOptions.h"

namespace osgVis::pvstool
{
class MpiBake;

/// The exit status: 0 baked, 1 a file, a scene or a unit failed (finished units stay in the state
/// folder). `mpi`: the ranks when launched by mpirun, else null.
int runBake(const PvsToolOptions& o, MpiBake* mpi);
} // namespace osgVis::pvstool
