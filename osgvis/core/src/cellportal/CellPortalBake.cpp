// SPDX-License-Identifier: MIT
#include <osgVis/core/cellportal/CellPortalBake.h>

#include <osgVis/core/cellportal/PortalStabbing.h>

#include "CellObjects.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <charconv>
#include <deque>
#include <mutex>

namespace osgVis::core
{
namespace
{
// What every source cell's search reads.
struct BakeContext
{
    const CellGraph& graph;
    const CellObjects& objects;
    const std::vector<Aabb>& objectBounds;
    double tolerance;
    std::uint32_t budget;
};

// The stab tree of one source cell (Teller & Séquin's constrained depth-first search): a portal
// sequence grows only while a sightline may still stab all of it, the cell each sequence reaches is
// visible from the source, and what lies in that cell inside the sequence's funnel joins the PVS.
class SourceCellSearch
{
public:
    SourceCellSearch(const BakeContext& context, SourceCellVisibility& out)
        : _graph(context.graph), _objects(context.objects), _objectBounds(context.objectBounds),
          _tolerance(context.tolerance), _budget(context.budget), _out(out), _onPath(context.graph.cells.size(), 0)
    {
        _out.cellToCell.reset(_graph.cells.size());
        _out.cellToObject.reset(_objectBounds.size());
    }

    void run(std::uint32_t source)
    {
        reachCell(source);
        addAllObjects(source);
        _onPath[source] = 1;
        _out.budgetExceeded = !extend(source, NoStabParent);
        if (_out.budgetExceeded)
            markEverythingReachable(source);
        for (ObjectId id : _objects.everywhere)
            _out.cellToObject.set(id);
    }

private:
    // Depth-first over the portals of `cell`; false once the budget is spent.
    bool extend(std::uint32_t cell, std::uint32_t parent)
    {
        for (std::uint32_t portalIndex : _graph.cellPortals[cell])
        {
            const CellPortal& portal = _graph.portals[portalIndex];
            const std::uint32_t next = portal.otherCell(cell);
            // A line meets a convex cell at most once, so no sightline returns to a cell on its path.
            if (next == NoCell || _onPath[next])
                continue;
            _sequence.push_back({portal.rect, next == portal.highCell});
            if (_sequence.size() > 1 &&
                !portalSequenceStabbable(_sequence.data(), _sequence.size(), _tolerance))
            {
                _sequence.pop_back();
                continue;
            }
            if (_out.stabTree.size() >= _budget)
            {
                _sequence.pop_back();
                return false;
            }
            const auto index = static_cast<std::uint32_t>(_out.stabTree.size());
            _out.stabTree.push_back({portalIndex, next, parent, 0});
            reachCell(next);
            if (_sequence.size() == 1)
                addAllObjects(next); // neighbour cells are always in the PVS
            else
                addObjectsInFunnel(next);
            _onPath[next] = 1;
            const bool withinBudget = extend(next, index);
            _onPath[next] = 0;
            _sequence.pop_back();
            _out.stabTree[index].subtreeEnd = static_cast<std::uint32_t>(_out.stabTree.size());
            if (!withinBudget)
                return false;
        }
        return true;
    }

    void reachCell(std::uint32_t cell) { _out.cellToCell.set(cell); }

    void addAllObjects(std::uint32_t cell)
    {
        for (ObjectId id : _objects.perCell[cell])
            _out.cellToObject.set(id);
    }

    // Objects of `cell` (clipped to it) that a line through the whole current sequence may reach.
    void addObjectsInFunnel(std::uint32_t cell)
    {
        bool haveFunnel = false;
        for (ObjectId id : _objects.perCell[cell])
        {
            if (_out.cellToObject.test(id))
                continue;
            if (!haveFunnel)
            {
                _funnel = portalFunnel(_sequence.data(), _sequence.size());
                haveFunnel = true;
            }
            const Aabb part = clippedToCell(_objectBounds[id], _graph.cells[cell], _tolerance);
            if (boxMeetsFunnel(part, _funnel, _tolerance))
                _out.cellToObject.set(id);
        }
    }

    // Past the budget: everything reachable through the adjacency graph is visible.
    void markEverythingReachable(std::uint32_t source)
    {
        std::vector<char> seen(_graph.cells.size(), 0);
        std::deque<std::uint32_t> queue{source};
        seen[source] = 1;
        while (!queue.empty())
        {
            const std::uint32_t cell = queue.front();
            queue.pop_front();
            reachCell(cell);
            addAllObjects(cell);
            for (std::uint32_t portalIndex : _graph.cellPortals[cell])
            {
                const std::uint32_t next = _graph.portals[portalIndex].otherCell(cell);
                if (next != NoCell && !seen[next])
                {
                    seen[next] = 1;
                    queue.push_back(next);
                }
            }
        }
    }

    const CellGraph& _graph;
    const CellObjects& _objects;
    const std::vector<Aabb>& _objectBounds;
    double _tolerance;
    std::uint32_t _budget;
    SourceCellVisibility& _out;
    std::vector<char> _onPath;
    std::vector<OrientedPortal> _sequence;
    PortalFunnel _funnel;
};
} // namespace

CellPortalData bakeCellPortal(const Scene& scene, const BakeOptions& options, const BakeProgress& progress)
{
    CellPortalData data;
    data.fingerprint = sceneFingerprint(scene);
    data.objectCount = static_cast<std::uint32_t>(scene.objects.size());
    data.graph = subdivideCells(scene, options.subdivision);
    const CellGraph& graph = data.graph;
    const double tolerance = cellPortalTolerance(graph);
    const CellObjects objects = assignObjectsToCells(scene, graph, tolerance);
    std::vector<Aabb> bounds(scene.objects.size());
    for (const SceneObject& object : scene.objects)
        bounds[object.id] = object.bounds;

    const BakeContext context{graph, objects, bounds, tolerance, options.stabBudget};
    const std::size_t cellCount = graph.cells.size();
    data.sources.resize(cellCount);
    std::atomic<std::size_t> done{0};
    std::mutex progressMutex;
    const auto searchCells = [&](const tbb::blocked_range<std::size_t>& range)
    {
        for (std::size_t cell = range.begin(); cell != range.end(); ++cell)
        {
            SourceCellSearch search(context, data.sources[cell]);
            search.run(static_cast<std::uint32_t>(cell));
            const std::size_t finished = ++done;
            if (progress)
            {
                const std::lock_guard<std::mutex> lock(progressMutex);
                progress(finished, cellCount);
            }
        }
    };
    const int threads = options.threads == 0 ? tbb::this_task_arena::max_concurrency() : int(options.threads);
    tbb::task_arena arena(threads);
    arena.execute([&] { tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cellCount, 1), searchCells); });

    BakeStatistics& stats = data.statistics;
    stats.cells = static_cast<std::uint32_t>(cellCount);
    stats.portals = static_cast<std::uint32_t>(graph.portals.size());
    for (const SourceCellVisibility& source : data.sources)
    {
        stats.stabNodes += source.stabTree.size();
        stats.budgetExceededCells += source.budgetExceeded ? 1u : 0u;
        stats.averageVisibleCells += double(source.cellToCell.count());
        stats.averagePvsObjects += double(source.cellToObject.count());
    }
    if (cellCount != 0)
    {
        stats.averageVisibleCells /= double(cellCount);
        stats.averagePvsObjects /= double(cellCount);
    }
    return data;
}

std::string canonicalBakeOptions(const BakeOptions& options)
{
    // note: to_chars gives the shortest text that reads back exactly, whatever the locale.
    const auto number = [](double value)
    {
        char text[32];
        return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
    };
    const SubdivisionOptions& s = options.subdivision;
    return "min-coverage=" + number(s.minCoverage) + " min-face-area=" + number(s.minFaceArea) +
           " min-cell-size=" + number(s.minCellSize) + " max-depth=" + std::to_string(s.maxDepth) +
           " max-cells=" + std::to_string(s.maxCells) + " stab-budget=" + std::to_string(options.stabBudget);
}
} // namespace osgVis::core
