// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The cell-portal bake: subdivision, then per source cell a depth-first search over portal
/// sequences that keeps a sequence while a sightline can stab it (the stab tree), cell-to-cell
/// visibility, and cell-to-object visibility from the funnel beyond each sequence.
#include <osgVis/core/pvs/CellPortalData.h>
#include <osgVis/core/cellportal/CellSubdivision.h>

#include <functional>
#include <memory>
#include <string>

namespace osgVis::core
{
struct BakeOptions
{
    SubdivisionOptions subdivision;
    /// Stab-tree nodes one source cell may grow; past it every cell still reachable counts as
    /// visible (conservative) and the cell is reported in BakeStatistics::budgetExceededCells.
    std::uint32_t stabBudget = 50000;
    /// Worker threads for the per-cell searches (0: all cores). Results do not depend on it.
    unsigned threads = 0;
};

/// Called with the number of source cells done so far and the total, from worker threads but never
/// two calls at once.
using BakeProgress = std::function<void(std::size_t done, std::size_t total)>;

CellPortalData bakeCellPortal(const Scene& scene, const BakeOptions& options = {}, const BakeProgress& progress = {});

/// The bake in pieces, for bakes split over processes (osgvispvs --cells, MPI): the subdivision
/// and the objects of each cell, computed alike by every process (deterministic), then the stab
/// trees of any range of source cells. A source cell's result depends only on the scene, the
/// options and the cell, so ranges baked apart equal the whole bake's.
class CellPortalBakePlan
{
public:
    CellPortalBakePlan(const Scene& scene, const BakeOptions& options);
    ~CellPortalBakePlan();
    CellPortalBakePlan(const CellPortalBakePlan&) = delete;
    CellPortalBakePlan& operator=(const CellPortalBakePlan&) = delete;

    /// The subdivision, fingerprint and object count, with every source cell an empty placeholder.
    const CellPortalData& skeleton() const { return _skeleton; }
    std::size_t cellCount() const { return _skeleton.graph.cells.size(); }
    /// The visibility from source cells [first, end), in parallel on options.threads.
    std::vector<SourceCellVisibility> bakeSources(std::size_t first, std::size_t end,
                                                  const BakeProgress& progress = {}) const;
    /// A guess of each source cell's search cost, to hand out the dearest first: the objects and
    /// portals of the cells within two portals of it (the search grows with both).
    std::vector<double> sourceCostEstimates() const;

private:
    struct Context;
    CellPortalData _skeleton;
    BakeOptions _options;
    std::unique_ptr<Context> _context;
};

/// The options as a `.pvs` file records them (PvsFile::options), one spelling for equal options:
/// "min-coverage=0.3 min-face-area=0 min-cell-size=1e-04 max-depth=40 max-cells=200000
/// stab-budget=50000", numbers as std::to_chars writes them (the shortest text that reads back
/// exactly). `threads` is left out: the results do not depend on it.
std::string canonicalBakeOptions(const BakeOptions& options);
} // namespace osgVis::core
