// SPDX-License-Identifier: MIT
// Master/worker distribution of bake units over MPI (the scheme of Valve's vvis: units many more than
// ranks, handed out on demand, so fast and slow ranks both stay busy); see MpiBake.h for the protocol.
#include "MpiBake.h"

#include <osgVis/core/pvs/PvsFormat.h>

#include <mpi.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

namespace osgVis::pvstool
{
namespace
{
enum Tag : int
{
    TagRequest = 1,
    TagResult = 2,
    TagFailure = 3,
    TagUnit = 4,
    TagStop = 5,
};

void sendUnit(int rank, const BakeUnit& unit)
{
    const std::uint32_t cells[2] = {unit.first, unit.end};
    MPI_Send(cells, 2, MPI_UINT32_T, rank, TagUnit, MPI_COMM_WORLD);
}

void sendStop(int rank)
{
    MPI_Send(nullptr, 0, MPI_BYTE, rank, TagStop, MPI_COMM_WORLD);
}

// The message `status` announced, as bytes.
std::vector<std::uint8_t> receiveBytes(const MPI_Status& status)
{
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    std::vector<std::uint8_t> bytes(std::size_t(std::max(count, 0)));
    MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return bytes;
}

// Checks a rank's result for `unit` and stores it; the reason when it is not the unit's result.
std::string storeResult(const BakeJob& job, BakeState& state, const std::vector<std::uint8_t>& message,
                        BakeUnit& unit)
{
    if (message.size() < 8)
        return "a result message of " + std::to_string(message.size()) + " bytes";
    std::memcpy(&unit.first, message.data(), 4);
    std::memcpy(&unit.end, message.data() + 4, 4);
    try
    {
        const core::PvsFile file = core::decodePvs(message.data() + 8, message.size() - 8);
        if (std::string why = job.mismatch(file, unit); !why.empty())
            return why;
        state.store(unit, file);
        return "";
    }
    catch (const std::exception& e)
    {
        return e.what();
    }
}
} // namespace

bool MpiBake::launchedByMpirun()
{
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(name))
            return true;
    return false;
}

MpiBake::MpiBake(int& argc, char**& argv)
{
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &_size);
}

MpiBake::~MpiBake()
{
    MPI_Finalize();
}

int MpiBake::localSize() const
{
    MPI_Comm local;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, _rank, MPI_INFO_NULL, &local);
    int size = 1;
    MPI_Comm_size(local, &size);
    MPI_Comm_free(&local);
    return size;
}

void MpiBake::dispatch(const BakeJob& job, UnitQueue& queue, BakeState& state, UnitProgress& progress,
                       unsigned threads, UnitFailure& failure)
{
    // Rank 0's own share runs beside the dispatch loop; it calls no MPI.
    std::thread own([&] { bakeUnitsHere(job, queue, state, progress, 1, threads, failure); });
    // Each rank holds two units: the one it bakes and the next, already in its queue, so that it
    // never waits for rank 0 between units. A rank is done once told to stop with nothing in flight.
    constexpr int UnitsAhead = 2;
    std::vector<int> inFlight(std::size_t(_size), 0);
    std::vector<char> stopped(std::size_t(_size), 0);
    int working = _size - 1;
    const auto handOut = [&](int to)
    {
        if (stopped[to])
            return;
        if (const std::optional<BakeUnit> next = queue.next())
        {
            sendUnit(to, *next);
            ++inFlight[to];
        }
        else
        {
            sendStop(to);
            stopped[to] = 1;
        }
    };
    auto idle = std::chrono::microseconds(20);
    while (working > 0)
    {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived)
        {
            // Blocking receives spin a core in Open MPI; a short sleep leaves it to the bake.
            std::this_thread::sleep_for(idle);
            idle = std::min(idle * 2, std::chrono::microseconds(250));
            continue;
        }
        idle = std::chrono::microseconds(20);
        const int from = status.MPI_SOURCE;
        const std::vector<std::uint8_t> message = receiveBytes(status);
        if (status.MPI_TAG == TagFailure)
        {
            failure.record("rank " + std::to_string(from) + ": " + std::string(message.begin(), message.end()));
            queue.stop();
            stopped[from] = 1; // it has left: nothing more comes from it
            inFlight[from] = 0;
            --working;
            continue;
        }
        if (status.MPI_TAG == TagResult)
        {
            --inFlight[from];
            BakeUnit unit;
            if (const std::string why = storeResult(job, state, message, unit); why.empty())
                progress.finished(unit);
            else
            {
                failure.record("rank " + std::to_string(from) + " sent a bad result for cells " +
                               std::to_string(unit.first) + ":" + std::to_string(unit.end) + ": " + why);
                queue.stop();
            }
            handOut(from);
        }
        else // the first request
            for (int k = 0; k < UnitsAhead; ++k)
                handOut(from);
        if (stopped[from] && inFlight[from] == 0)
            --working;
    }
    own.join();
}

void MpiBake::stopAll()
{
    for (int stopped = 0; stopped < _size - 1; ++stopped)
    {
        MPI_Status status;
        MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
        receiveBytes(status);
        if (status.MPI_TAG != TagFailure)
            sendStop(status.MPI_SOURCE);
    }
}

void MpiBake::serve(const BakeJob& job, unsigned threads)
{
    tbb::task_arena arena(int(std::max(threads, 1u)));
    MPI_Send(nullptr, 0, MPI_BYTE, 0, TagRequest, MPI_COMM_WORLD);
    // The tests' stand-in for a failing rank: it fails on its second unit, after its first result
    // went out, so some finished unit is kept whichever rank the coordinator hears from first.
    const char* failRank = std::getenv("OSGVISPVS_FAIL_RANK");
    const bool injectFailure = failRank && std::atoi(failRank) == _rank;
    unsigned unitsServed = 0;
    for (;;)
    {
        MPI_Status status;
        std::uint32_t cells[2] = {0, 0};
        MPI_Recv(cells, 2, MPI_UINT32_T, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
        if (status.MPI_TAG == TagStop)
            return;
        try
        {
            if (injectFailure && unitsServed++ == 1)
                throw std::runtime_error("failure injected by OSGVISPVS_FAIL_RANK");
            core::PvsFile file;
            arena.execute([&] { file = job.bakeUnit(cells[0], cells[1]); });
            std::vector<std::uint8_t> message(8);
            std::memcpy(message.data(), &cells[0], 4);
            std::memcpy(message.data() + 4, &cells[1], 4);
            const std::vector<std::uint8_t> bytes = core::encodePvs(file);
            message.insert(message.end(), bytes.begin(), bytes.end());
            MPI_Send(message.data(), int(message.size()), MPI_BYTE, 0, TagResult, MPI_COMM_WORLD);
        }
        catch (const std::exception& e)
        {
            reportFailure("cells " + std::to_string(cells[0]) + ":" + std::to_string(cells[1]) + ": " + e.what());
            return;
        }
    }
}

void MpiBake::reportFailure(const std::string& message)
{
    MPI_Send(message.data(), int(message.size()), MPI_BYTE, 0, TagFailure, MPI_COMM_WORLD);
}
} // namespace osgVis::pvstool
