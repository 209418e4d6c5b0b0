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

class BakeJob;
/// Rank 0's part (or the only process's) for a job already made: resume from the state folder,
/// bake what is missing (over the ranks with `mpi`), join, write o.pvsFile, report.
int leadBake(const PvsToolOptions& o, const BakeJob& job, MpiBake* mpi);
/// MPI for the life of the process when it runs under mpirun (and osgvispvs has MPI); else none.
class MpiSession
{
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiBake* ranks() const { return _ranks; }
    /// This process is a rank other than 0, which only serves units.
    bool worker() const;

private:
    MpiBake* _ranks = nullptr;
};

/// Threads a rank bakes with: --threads, else the cores divided among the ranks on its machine.
unsigned threadsPerRank(const PvsToolOptions& o, MpiBake* mpi);
} // namespace osgVis::pvstool
