// SPDX-License-Identifier: MIT
#include "BakeRun.h"

#include <tbb/task_arena.h>

#include <thread>

namespace osgVis::pvstool
{
std::optional<BakeUnit> UnitQueue::next()
{
    const std::lock_guard<std::mutex> lock(_mutex);
    if (_stopped || _next == _pending.size())
        return std::nullopt;
    return _pending[_next++];
}

void UnitQueue::stop()
{
    const std::lock_guard<std::mutex> lock(_mutex);
    _stopped = true;
}

UnitProgress::UnitProgress(BakeProgressBar& bar, std::size_t units, std::size_t cells)
    : _bar(bar), _units(units), _cells(cells)
{
}

void UnitProgress::resumed(const BakeUnit& unit)
{
    const std::lock_guard<std::mutex> lock(_mutex);
    ++_unitsDone;
    _cellsDone += unit.cells();
}

void UnitProgress::finished(const BakeUnit& unit)
{
    const std::lock_guard<std::mutex> lock(_mutex);
    ++_unitsDone;
    ++_unitsBaked;
    _cellsDone += unit.cells();
    _cellsBaked += unit.cells();
    _bar.updateUnits(_unitsDone, _units, _cellsDone, _cells, _cellsBaked);
}

void UnitFailure::record(const std::string& text)
{
    const std::lock_guard<std::mutex> lock(mutex);
    if (message.empty())
        message = text;
}

bool UnitFailure::failed()
{
    const std::lock_guard<std::mutex> lock(mutex);
    return !message.empty();
}

void bakeUnitsHere(const BakeJob& job, UnitQueue& queue, BakeState& state, UnitProgress& progress, unsigned workers,
                   unsigned threadsPerUnit, UnitFailure& failure)
{
    const auto work = [&]
    {
        tbb::task_arena arena(int(std::max(threadsPerUnit, 1u)));
        while (const std::optional<BakeUnit> unit = queue.next())
        {
            try
            {
                core::PvsFile file;
                arena.execute([&] { file = job.bakeUnit(unit->first, unit->end); });
                state.store(*unit, file);
                progress.finished(*unit);
            }
            catch (const std::exception& e)
            {
                failure.record("cells " + std::to_string(unit->first) + ":" + std::to_string(unit->end) + ": " +
                               e.what());
                queue.stop();
            }
        }
    };
    std::vector<std::thread> threads;
    for (unsigned w = 1; w < std::max(workers, 1u); ++w)
        threads.emplace_back(work);
    work();
    for (std::thread& thread : threads)
        thread.join();
}
} // namespace osgVis::pvstool
