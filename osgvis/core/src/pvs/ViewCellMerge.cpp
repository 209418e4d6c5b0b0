// SPDX-License-Identifier: MIT
#include <osgVis/core/pvs/ViewCellMerge.h>

#include "RangeMergeChecks.h"

#include <algorithm>
#include <tuple>

namespace osgVis::core
{
PvsFile mergeViewCellPvs(const std::vector<PvsFile>& ranges, const ViewCellMergeOptions& options)
{
    const InputNames name(options.inputNames);
    if (ranges.empty())
        throw PvsFormatError("nothing to merge: no input files");
    for (std::size_t i = 0; i < ranges.size(); ++i)
    {
        const PvsFile& input = ranges[i];
        checkMergedData(input, name(i), MergedData::ViewCells);
        const ViewCellPvs& v = input.viewCells;
        if (v.cells.size() != v.cellIndices.size() || v.pvs.size() != v.cellIndices.size())
            throw PvsFormatError("cannot merge " + name(i) + ": its view cells have " +
                                 std::to_string(v.cellIndices.size()) + " indices, " + std::to_string(v.cells.size()) +
                                 " boxes and " + std::to_string(v.pvs.size()) + " sets");
        if (i > 0)
        {
            checkSameBake(ranges[0], input, name(0), name(i));
            if (v.totalCells != ranges[0].viewCells.totalCells)
                throw notOneBake(name(0), name(i), std::to_string(v.totalCells) + " and " +
                                                       std::to_string(ranges[0].viewCells.totalCells) + " cells in all");
        }
    }

    // (absolute index, input, position in that input), in ascending index.
    std::vector<std::tuple<std::uint32_t, std::size_t, std::size_t>> cells;
    for (std::size_t i = 0; i < ranges.size(); ++i)
        for (std::size_t c = 0; c < ranges[i].viewCells.cellIndices.size(); ++c)
            cells.emplace_back(ranges[i].viewCells.cellIndices[c], i, c);
    std::sort(cells.begin(), cells.end());
    for (std::size_t k = 1; k < cells.size(); ++k)
        if (std::get<0>(cells[k]) == std::get<0>(cells[k - 1]))
            throw PvsFormatError("cell " + std::to_string(std::get<0>(cells[k])) + " is in both " +
                                 name(std::get<1>(cells[k - 1])) + " and " + name(std::get<1>(cells[k])));

    const PvsFile& first = ranges[0];
    const std::uint32_t total = first.viewCells.totalCells;
    if (options.requireAllCells && cells.size() != total)
    {
        std::vector<std::uint32_t> present;
        for (const auto& cell : cells)
            present.push_back(std::get<0>(cell));
        const std::vector<std::uint32_t> missing = missingIndices(present, total);
        throw PvsFormatError("the inputs miss " + std::to_string(missing.size()) + " of the " + std::to_string(total) +
                             " cells: " + indexRuns(missing, 8));
    }

    PvsFile merged;
    merged.modelPath = first.modelPath;
    merged.method = first.method;
    merged.options = first.options;
    merged.nearDistance = first.nearDistance;
    merged.geometryFingerprint = first.geometryFingerprint;
    merged.hasCellPortal = false;
    merged.data.fingerprint = first.data.fingerprint;
    merged.data.objectCount = first.data.objectCount;
    merged.hasViewCells = true;
    ViewCellPvs& out = merged.viewCells;
    out.totalCells = total;
    out.cellIndices.reserve(cells.size());
    out.cells.reserve(cells.size());
    out.pvs.reserve(cells.size());
    for (const auto& [index, input, position] : cells)
    {
        const ViewCellPvs& from = ranges[input].viewCells;
        out.cellIndices.push_back(index);
        out.cells.push_back(from.cells[position]);
        out.pvs.push_back(from.pvs[position]);
    }
    return merged;
}
} // namespace osgVis::core
