// SPDX-License-Identifier: MIT
#include <osgVis/core/pvs/CellPortalMerge.h>

#include "PvsCellPortalCodec.h"
#include "PvsTileCodec.h"
#include "RangeMergeChecks.h"

#include <algorithm>
#include <tuple>

namespace osgVis::core
{
namespace
{
// The subdivision's bytes as the file stores them (sources and statistics left out), and its tile
// keys where it has them: two bakes share a subdivision exactly when these agree.
std::vector<std::uint8_t> graphBytes(const PvsFile& file)
{
    CellPortalData graphOnly;
    graphOnly.graph = file.data.graph;
    PvsByteWriter out;
    writeCellPortalParts(out, graphOnly);
    out.u8(file.data.tiles ? 1 : 0);
    if (file.data.tiles)
        writeTiles(out, *file.data.tiles);
    return std::move(out.bytes());
}

std::pair<std::uint32_t, std::uint32_t> sourcesOf(const PvsFile& file)
{
    return file.sourceRange ? *file.sourceRange
                            : std::make_pair(std::uint32_t(0), std::uint32_t(file.data.sources.size()));
}
} // namespace

PvsFile mergeCellPortalPvs(const std::vector<PvsFile>& ranges, const ViewCellMergeOptions& options)
{
    const InputNames name(options.inputNames);
    if (ranges.empty())
        throw PvsFormatError("nothing to merge: no input files");
    std::vector<std::uint8_t> firstGraph;
    for (std::size_t i = 0; i < ranges.size(); ++i)
    {
        const PvsFile& input = ranges[i];
        checkMergedData(input, name(i), MergedData::CellPortal);
        if (i == 0)
        {
            firstGraph = graphBytes(input);
            continue;
        }
        checkSameBake(ranges[0], input, name(0), name(i));
        if (graphBytes(input) != firstGraph)
            throw notOneBake(name(0), name(i),
                             "different subdivisions: " + std::to_string(input.data.graph.cells.size()) + " and " +
                                 std::to_string(ranges[0].data.graph.cells.size()) + " cells");
    }

    // (first, end, input) in ascending first.
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::size_t>> pieces;
    for (std::size_t i = 0; i < ranges.size(); ++i)
        pieces.emplace_back(sourcesOf(ranges[i]).first, sourcesOf(ranges[i]).second, i);
    std::sort(pieces.begin(), pieces.end());
    for (std::size_t k = 1; k < pieces.size(); ++k)
        if (std::get<0>(pieces[k]) < std::get<1>(pieces[k - 1]))
            throw PvsFormatError("source cell " + std::to_string(std::get<0>(pieces[k])) + " is in both " +
                                 name(std::get<2>(pieces[k - 1])) + " and " + name(std::get<2>(pieces[k])));

    const PvsFile& first = ranges[0];
    const auto total = std::uint32_t(first.data.sources.size());
    std::vector<std::uint32_t> present;
    for (const auto& [from, to, input] : pieces)
        for (std::uint32_t c = from; c < to; ++c)
            present.push_back(c);
    if (present.size() != total)
    {
        const std::vector<std::uint32_t> missing = missingIndices(present, total);
        const bool contiguous = present.back() - present.front() + 1 == present.size();
        if (options.requireAllCells || !contiguous)
            throw PvsFormatError("the inputs miss " + std::to_string(missing.size()) + " of the " +
                                 std::to_string(total) + " source cells: " + indexRuns(missing, 8) +
                                 (options.requireAllCells ? "" : " (a partial merge must hold one contiguous range)"));
    }

    PvsFile merged = first;
    for (const auto& [from, to, input] : pieces)
        for (std::uint32_t c = from; c < to; ++c)
            merged.data.sources[c] = ranges[input].data.sources[c];
    if (present.size() == total)
    {
        merged.sourceRange.reset();
        merged.data.statistics = bakeStatisticsOf(merged.data);
    }
    else
    {
        merged.sourceRange = std::make_pair(present.front(), present.back() + 1);
        merged.data.statistics = {};
    }
    return merged;
}
} // namespace osgVis::core
