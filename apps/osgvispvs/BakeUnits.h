// SPDX-License-Identifier: MIT
#pragma once
// How a bake is cut into work units: consecutive cell ranges on a grid fixed by the cell count and
// the unit size alone (so a resumed or re-split bake finds the same units), handed out dearest
// first by an estimate (the long ones then do not come last and stall the end of the bake).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::pvstool
{
struct BakeUnit
{
    std::uint32_t first = 0, end = 0; ///< cells [first, end)
    double cost = 0.0;                ///< the estimate: the sum over its cells
    std::uint32_t cells() const { return end - first; }
};

/// Cells per unit for `units` units over `totalCells` (at least 1).
std::uint32_t cellsPerUnitFor(std::uint32_t totalCells, std::uint32_t units);

/// The units of the grid [k·cellsPerUnit, (k+1)·cellsPerUnit) cut to [first, end), in order of
/// their cells.
std::vector<BakeUnit> splitIntoUnits(std::uint32_t first, std::uint32_t end, std::uint32_t cellsPerUnit);

/// Sets each unit's cost from `cellCosts` (one per cell of the layout) and sorts the units by
/// descending cost, ties by their first cell: the same order on every run.
void orderByCost(std::vector<BakeUnit>& units, const std::vector<double>& cellCosts);

/// Shard `k` of `n` (1-based, as `--shard K/N` says): cells [⌊(k-1)·total/n⌋, ⌊k·total/n⌋).
std::pair<std::uint32_t, std::uint32_t> shardCells(std::uint32_t k, std::uint32_t n, std::uint32_t totalCells);

/// The file name of a unit's result in the state folder: "cells-00000012-00000016.pvs".
std::string unitFileName(const BakeUnit& unit);
} // namespace osgVis::pvstool
