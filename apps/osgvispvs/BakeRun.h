// SPDX-License-Identifier: MIT
#pragma once
// Running a bake's units in this process: the queue of units still to bake (dearest first), the
// count of finished ones behind the progress bar, and worker threads that bake units one at a time
// each and store them in the state folder.
#include "BakeJob.h"
#include "BakeProgressBar.h"
#include "BakeState.h"
#include "BakeUnits.h"

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace osgVis::pvstool
{
class UnitQueue
{
public:
    explicit UnitQueue(std::vector<BakeUnit> pending) : _pending(std::move(pending)) {}
    /// The next unit to bake; none once all are handed out or after stop().
    std::optional<BakeUnit> next();
    /// Hands out nothing more (a unit failed): the units in flight still finish.
    void stop();

private:
    std::mutex _mutex;
    std::vector<BakeUnit> _pending;
    std::size_t _next = 0;
    bool _stopped = false;
};

/// The finished units of the whole bake, as the bar on stderr shows them.
class UnitProgress
{
public:
    UnitProgress(BakeProgressBar& bar, std::size_t units, std::size_t cells);
    void resumed(const BakeUnit& unit); ///< found finished in the state folder
    void finished(const BakeUnit& unit);
    std::size_t unitsBaked() const { return _unitsBaked; }

private:
    BakeProgressBar& _bar;
    std::mutex _mutex;
    std::size_t _units, _cells;
    std::size_t _unitsDone = 0, _cellsDone = 0, _unitsBaked = 0, _cellsBaked = 0;
};

/// The first failure of a unit, and what it says.
struct UnitFailure
{
    std::mutex mutex;
    std::string message; ///< empty: none
    void record(const std::string& text);
    bool failed();
};

/// Bakes the units of `queue` on `workers` threads until it is empty, each unit in a task arena of
/// `threadsPerUnit` threads, stores each in `state` and counts it in `progress`. A unit that throws
/// stops the queue; its message goes to `failure`.
void bakeUnitsHere(const BakeJob& job, UnitQueue& queue, BakeState& state, UnitProgress& progress, unsigned workers,
                   unsigned threadsPerUnit, UnitFailure& failure);
} // namespace osgVis::pvstool
