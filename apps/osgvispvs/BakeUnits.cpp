// SPDX-License-Identifier: MIT
#include "BakeUnits.h"

#include <algorithm>
#include <cstdio>

namespace osgVis::pvstool
{
std::uint32_t cellsPerUnitFor(std::uint32_t totalCells, std::uint32_t units)
{
    units = std::max<std::uint32_t>(units, 1);
    return std::max<std::uint32_t>(1, std::uint32_t((std::uint64_t(totalCells) + units - 1) / units));
}

std::vector<BakeUnit> splitIntoUnits(std::uint32_t first, std::uint32_t end, std::uint32_t cellsPerUnit)
{
    cellsPerUnit = std::max<std::uint32_t>(cellsPerUnit, 1);
    std::vector<BakeUnit> units;
    for (std::uint64_t at = first; at < end;)
    {
        const std::uint64_t gridEnd = (at / cellsPerUnit + 1) * cellsPerUnit;
        const auto to = std::uint32_t(std::min<std::uint64_t>(gridEnd, end));
        units.push_back({std::uint32_t(at), to, 0.0});
        at = to;
    }
    return units;
}

void orderByCost(std::vector<BakeUnit>& units, const std::vector<double>& cellCosts)
{
    for (BakeUnit& unit : units)
    {
        unit.cost = 0.0;
        for (std::uint32_t c = unit.first; c < unit.end && c < cellCosts.size(); ++c)
            unit.cost += cellCosts[c];
    }
    std::stable_sort(units.begin(), units.end(), [](const BakeUnit& a, const BakeUnit& b)
                     { return a.cost != b.cost ? a.cost > b.cost : a.first < b.first; });
}

std::pair<std::uint32_t, std::uint32_t> shardCells(std::uint32_t k, std::uint32_t n, std::uint32_t totalCells)
{
    const auto at = [&](std::uint32_t i) { return std::uint32_t(std::uint64_t(i) * totalCells / n); };
    return {at(k - 1), at(k)};
}

std::string unitFileName(const BakeUnit& unit)
{
    char name[48];
    std::snprintf(name, sizeof name, "cells-%08u-%08u.pvs", unit.first, unit.end);
    return name;
}
} // namespace osgVis::pvstool
