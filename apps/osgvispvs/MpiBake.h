// SPDX-License-Identifier: MIT
#pragma once
// A bake over MPI ranks (built with OSGVIS_WITH_MPI): rank 0 hands out units dearest first as ranks
// ask, bakes units itself on a worker thread meanwhile, checks and stores every result in the state
// folder and writes the output; the other ranks ask, bake and send back until told to stop.
// Only the main thread of a rank calls MPI (MPI_THREAD_FUNNELED).
//
// Messages: a rank sends REQUEST (first ask), RESULT (first cell, end cell, the unit's .pvs bytes;
// also the next ask) or FAILURE (text); rank 0 answers UNIT (first, end) or STOP, two UNITs to the
// first request, so that every rank has its next unit queued while it bakes one (no wait between
// units). After STOP a rank finishes the unit it still holds.
#include "BakeRun.h"

#include <string>

namespace osgVis::pvstool
{
class MpiBake
{
public:
    /// True when the process runs under mpirun (its environment says so): only then is MPI started.
    static bool launchedByMpirun();

    MpiBake(int& argc, char**& argv);
    ~MpiBake();
    MpiBake(const MpiBake&) = delete;
    MpiBake& operator=(const MpiBake&) = delete;

    int rank() const { return _rank; }
    int size() const { return _size; }
    /// Ranks on this machine (for the threads each may use).
    int localSize() const;

    /// Rank 0: runs the bake's units over all ranks until the queue is empty (or a unit failed: then
    /// the units in flight finish and every rank is stopped), `threads` per unit.
    void dispatch(const BakeJob& job, UnitQueue& queue, BakeState& state, UnitProgress& progress, unsigned threads,
                  UnitFailure& failure);
    /// Rank 0 when it cannot bake at all: stops every other rank once it asks.
    void stopAll();
    /// Other ranks: bakes units rank 0 hands out until it says stop, or until one fails (its message
    /// goes to rank 0, which decides the exit status).
    void serve(const BakeJob& job, unsigned threads);
    /// Other ranks that could not prepare the bake: tells rank 0 why.
    void reportFailure(const std::string& message);

private:
    int _rank = 0, _size = 1;
};
} // namespace osgVis::pvstool
