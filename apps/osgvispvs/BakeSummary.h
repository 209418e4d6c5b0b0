// SPDX-License-Identifier: MIT
#pragma once
// What osgvispvs reports about a bake: the figures of the baked data (counted from the data
// themselves), printed as text and optionally written as JSON.
#include <osgVis/core/cellportal/CellPortalBake.h>

#include <cstdint>
#include <ostream>
#include <string>

namespace osgVis::pvstool
{
struct BakeSummary
{
    std::string modelFile, pvsFile;
    std::string modelPathInPvs; // as the .pvs names the model: relative to its folder
    std::uint32_t objects = 0;
    std::uint64_t triangles = 0;
    std::uint32_t cells = 0, portals = 0;
    std::uint64_t stabNodes = 0;
    double averageVisibleCells = 0.0;
    double averagePvsObjects = 0.0;
    std::uint32_t budgetExceededCells = 0;
    double bakeSeconds = 0.0;
    std::uint64_t fileBytes = 0;
    core::BakeOptions options;

    double averagePvsFraction() const { return objects ? averagePvsObjects / objects : 0.0; }
    double budgetExceededFraction() const { return cells ? double(budgetExceededCells) / cells : 0.0; }
};

// Counts cells, portals, stab-tree nodes, visible cells, PVS sizes and budget hits in `data`.
BakeSummary summarizeBake(const core::CellPortalData& data, std::uint64_t triangles);

void printBakeSummary(std::ostream& out, const BakeSummary& summary);
// One JSON object with the same figures (snake_case keys) and the options used.
void writeBakeSummaryJson(std::ostream& out, const BakeSummary& summary);
} // namespace osgVis::pvstool
