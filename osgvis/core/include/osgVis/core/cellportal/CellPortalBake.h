// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The cell-portal bake: subdivision, then per source cell a depth-first search over portal
/// sequences that keeps a sequence while a sightline can stab it (the stab tree), cell-to-cell
/// visibility, and cell-to-object visibility from the funnel beyond each sequence.
#include <osgVis/core/pvs/CellPortalData.h>
#include <osgVis/core/cellportal/CellSubdivision.h>

#include <functional>
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

/// The options as a `.pvs` file records them (PvsFile::options), one spelling for equal options:
/// "min-coverage=0.3 min-face-area=0 min-cell-size=1e-04 max-depth=40 max-cells=200000
/// stab-budget=50000", numbers as std::to_chars writes them (the shortest text that reads back
/// exactly). `threads` is left out: the results do not depend on it.
std::string canonicalBakeOptions(const BakeOptions& options);
} // namespace osgVis::core
