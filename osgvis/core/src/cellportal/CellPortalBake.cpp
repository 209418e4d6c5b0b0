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
#include <stdexcept>

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

struct CellPortalBakePlan::Context
{
    CellObjects objects;
    std::vector<Aabb> bounds;
    double tolerance = 0.0;
};

CellPortalBakePlan::CellPortalBakePlan(const Scene& scene, const BakeOptions& options)
    : _options(options), _context(std::make_unique<Context>())
{
    _skeleton.fingerprint = sceneFingerprint(scene);
    _skeleton.objectCount = static_cast<std::uint32_t>(scene.objects.size());
    _skeleton.graph = subdivideCells(scene, options.subdivision);
    _context->tolerance = cellPortalTolerance(_skeleton.graph);
    _context->objects = assignObjectsToCells(scene, _skeleton.graph, _context->tolerance);
    _context->bounds.resize(scene.objects.size());
    for (const SceneObject& object : scene.objects)
        _context->bounds[object.id] = object.bounds;
    _skeleton.sources.assign(cellCount(), placeholderSource(cellCount(), _skeleton.objectCount));
    // Only the whole database can stand for every load state (docs/paging.md); a bake of some tiles
    // is tied to exactly those by its fingerprint, as for any scene.
    if (scene.tiles && scene.tiles->complete)
        _skeleton.tiles = scene.tiles;
}

CellPortalBakePlan::~CellPortalBakePlan() = default;

std::vector<SourceCellVisibility> CellPortalBakePlan::bakeSources(std::size_t first, std::size_t end,
                                                                  const BakeProgress& progress) const
{
    if (first > end || end > cellCount())
        throw std::out_of_range("bakeSources: cells " + std::to_string(first) + ".." + std::to_string(end) +
                                " outside the " + std::to_string(cellCount()) + " cells");
    const BakeContext context{_skeleton.graph, _context->objects, _context->bounds, _context->tolerance,
                              _options.stabBudget};
    const std::size_t count = end - first;
    std::vector<SourceCellVisibility> sources(count);
    std::atomic<std::size_t> done{0};
    std::mutex progressMutex;
    const auto searchCells = [&](const tbb::blocked_range<std::size_t>& range)
    {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
        {
            SourceCellSearch search(context, sources[i]);
            search.run(static_cast<std::uint32_t>(first + i));
            const std::size_t finished = ++done;
            if (progress)
            {
                const std::lock_guard<std::mutex> lock(progressMutex);
                progress(finished, count);
            }
        }
    };
    const int threads = _options.threads == 0 ? tbb::this_task_arena::max_concurrency() : int(_options.threads);
    tbb::task_arena arena(threads);
    arena.execute([&] { tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1), searchCells); });
    if (_skeleton.tiles)
        for (SourceCellVisibility& source : sources)
            propagateToPlaceholders(*_skeleton.tiles, source.cellToObject);
    return sources;
}

std::vector<double> CellPortalBakePlan::sourceCostEstimates() const
{
    const CellGraph& graph = _skeleton.graph;
    std::vector<double> local(cellCount());
    for (std::size_t c = 0; c < cellCount(); ++c)
        local[c] = 1.0 + double(_context->objects.perCell[c].size()) + double(graph.cellPortals[c].size());
    std::vector<double> costs(cellCount(), 0.0);
    std::vector<std::uint32_t> seen(cellCount(), NoCell);
    for (std::size_t c = 0; c < cellCount(); ++c)
    {
        // The cells within two portals of c, each once.
        std::vector<std::uint32_t> ring{std::uint32_t(c)};
        seen[c] = std::uint32_t(c);
        for (int step = 0; step < 2; ++step)
        {
            const std::size_t end = ring.size();
            for (std::size_t k = 0; k < end; ++k)
                for (std::uint32_t p : graph.cellPortals[ring[k]])
                {
                    const std::uint32_t next = graph.portals[p].otherCell(ring[k]);
                    if (next != NoCell && seen[next] != c)
                    {
                        seen[next] = std::uint32_t(c);
                        ring.push_back(next);
                    }
                }
        }
        for (std::uint32_t cell : ring)
            costs[c] += local[cell];
    }
    return costs;
}

CellPortalData bakeCellPortal(const Scene& scene, const BakeOptions& options, const BakeProgress& progress)
{
    const CellPortalBakePlan plan(scene, options);
    CellPortalData data = plan.skeleton();
    data.sources = plan.bakeSources(0, plan.cellCount(), progress);
    data.statistics = bakeStatisticsOf(data);
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
           " max-cells=" + std::to_string(s.maxCells) + " stab-budget=" + std::to_string(options.stabBudget) +
           // Only when set, so that the files baked before the option read back equal.
           (s.fromSolids ? " from-solids=1" : "");
}
} // namespace osgVis::core
