// SPDX-License-Identifier: MIT
#include "BakeCommand.h"
#include "SubdivisionExplanation.h"

#include "BakeJob.h"
#include "BakeRun.h"
#include "BakeState.h"
#include "ToolFiles.h"
#ifdef OSGVIS_WITH_MPI
#include "MpiBake.h"
#endif

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

namespace osgVis::pvstool
{
namespace
{
struct PreparedBake
{
    LoadedModel loaded;
    std::unique_ptr<BakeJob> job;
};

PreparedBake prepare(const PvsToolOptions& o, bool quiet)
{
    PreparedBake prepared;
    prepared.loaded = loadModelToBake(o, quiet);
    const core::Scene& scene = prepared.loaded.extracted->scene;
    if (o.explain && !quiet && o.method != "multifocal")
        explainSubdivision(scene, o.bake.subdivision, std::cout);
    prepared.job = o.method == "multifocal" ? makeViewCellJob(o, scene) : makeCellPortalJob(o, scene);
    return prepared;
}

unsigned hardwareThreads()
{
    return std::max(1u, std::thread::hardware_concurrency());
}

} // namespace

int leadBake(const PvsToolOptions& o, const BakeJob& job, MpiBake* mpi)
{
    const auto start = std::chrono::steady_clock::now();
    // Until the dispatch starts, other ranks wait for their first answer: a failure here stops them.
    struct ReleaseRanks
    {
        MpiBake* mpi;
        ~ReleaseRanks()
        {
#ifdef OSGVIS_WITH_MPI
            if (mpi && mpi->size() > 1 && std::uncaught_exceptions() > 0)
                mpi->stopAll();
#endif
        }
    } release{mpi};
    int rankCount = 1;
#ifdef OSGVIS_WITH_MPI
    if (mpi)
        rankCount = mpi->size();
#endif
    const unsigned threads = threadsPerRank(o, mpi);
    const auto [first, end] = job.cellsToBake();
    const std::uint32_t unitCount = std::max(job.defaultUnitCount(), std::uint32_t(4 * rankCount));
    const std::uint32_t cellsPerUnit = o.unitCells ? o.unitCells : cellsPerUnitFor(job.cellCount(), unitCount);
    const std::vector<BakeUnit> units = splitIntoUnits(first, end, cellsPerUnit);

    BakeState state(o.pvsFile);
    state.open();
    std::vector<std::string> redone;
    const std::vector<bool> finished = state.finished(job, units, redone);
    for (const std::string& note : redone)
        std::cerr << "osgvispvs: baking again " << note << "\n";
    BakeProgressBar bar(stderr, o.forceProgress || isatty(fileno(stderr)));
    UnitProgress progress(bar, units.size(), end - first);
    std::vector<BakeUnit> pending;
    for (std::size_t i = 0; i < units.size(); ++i)
        if (finished[i])
            progress.resumed(units[i]);
        else
            pending.push_back(units[i]);
    const std::size_t resumed = units.size() - pending.size();
    if (resumed != 0)
        std::cerr << "osgvispvs: resuming: " << resumed << " of " << units.size() << " units finished in '"
                  << state.folder().string() << "'\n";
    orderByCost(pending, job.cellCosts());

    UnitQueue queue(std::move(pending));
    UnitFailure failure;
    release.mpi = nullptr; // the dispatch stops every rank itself
#ifdef OSGVIS_WITH_MPI
    if (mpi && mpi->size() > 1)
        mpi->dispatch(job, queue, state, progress, threads, failure);
    else
#endif
        bakeUnitsHere(job, queue, state, progress, threads, 1, failure);
    if (failure.failed())
    {
        bar.interrupt();
        throw ToolError("the bake failed (" + failure.message + "); the units finished so far stay in '" +
                        state.folder().string() + "': run the same command again to bake the rest");
    }

    const auto joinStart = std::chrono::steady_clock::now();
    core::PvsFile output = job.join(state.read(units), o.pvsFile);
    try
    {
        core::writePvsFile(o.pvsFile, output);
    }
    catch (const std::exception& e)
    {
        throw ToolError("cannot write the .pvs file '" + o.pvsFile + "': " + e.what());
    }
    state.remove(units);
    BakeRunFigures figures;
    const auto now = std::chrono::steady_clock::now();
    figures.seconds = std::chrono::duration<double>(now - start).count();
    figures.joinSeconds = std::chrono::duration<double>(now - joinStart).count();
    figures.unitsBaked = std::uint32_t(progress.unitsBaked());
    figures.unitsResumed = std::uint32_t(resumed);
    figures.ranks = rankCount;
    bar.finish(end - first, figures.seconds);
    std::fprintf(stderr, "joined %zu units (%zu baked now, %zu resumed, %d rank%s) in %.3f s\n", units.size(),
                 std::size_t(figures.unitsBaked), resumed, rankCount, rankCount == 1 ? "" : "s", figures.joinSeconds);
    job.report(output, figures);
    return 0;
}

MpiSession::MpiSession(int& argc, char**& argv)
{
#ifdef OSGVIS_WITH_MPI
    if (MpiBake::launchedByMpirun())
        _ranks = new MpiBake(argc, argv);
#else
    (void)argc;
    (void)argv;
#endif
}

MpiSession::~MpiSession()
{
#ifdef OSGVIS_WITH_MPI
    delete _ranks;
#endif
}

bool MpiSession::worker() const
{
#ifdef OSGVIS_WITH_MPI
    return _ranks && _ranks->rank() != 0;
#else
    return false;
#endif
}

unsigned threadsPerRank(const PvsToolOptions& o, MpiBake* mpi)
{
    if (o.bake.threads)
        return o.bake.threads;
#ifdef OSGVIS_WITH_MPI
    if (mpi)
        return std::max(1u, hardwareThreads() / unsigned(std::max(mpi->localSize(), 1)));
#endif
    return hardwareThreads();
}

int runBake(const PvsToolOptions& o, MpiBake* mpi)
{
#ifdef OSGVIS_WITH_MPI
    if (mpi && mpi->rank() != 0)
    {
        PreparedBake prepared;
        try
        {
            prepared = prepare(o, true);
        }
        catch (const std::exception& e)
        {
            mpi->reportFailure(std::string("cannot prepare the bake: ") + e.what());
            return 0; // see below
        }
        const unsigned threads = o.bake.threads ? o.bake.threads
                                                : std::max(1u, hardwareThreads() / unsigned(std::max(mpi->localSize(), 1)));
        // A rank's failure reached rank 0, which reports it and exits with 1. Exiting with 1 here
        // would make mpirun kill rank 0 before it could say so or keep what it received.
        mpi->serve(*prepared.job, threads);
        return 0;
    }
    if (mpi)
    {
        PreparedBake prepared;
        try
        {
            prepared = prepare(o, false);
        }
        catch (...)
        {
            if (mpi->size() > 1)
                mpi->stopAll();
            throw;
        }
        return leadBake(o, *prepared.job, mpi);
    }
#endif
    const PreparedBake prepared = prepare(o, false);
    return leadBake(o, *prepared.job, mpi);
}
} // namespace osgVis::pvstool
