// SPDX-License-Identifier: MIT
#include <osgVis/core/pvs/ViewCellMerge.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <tuple>

namespace osgVis::core
{
namespace
{
std::string hex(std::uint64_t value)
{
    char text[19];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
    return text;
}

// The shortest text that reads back as `value`.
std::string number(double value)
{
    char text[32];
    const std::to_chars_result end = std::to_chars(text, text + sizeof text, value);
    return std::string(text, end.ptr);
}

// "0, 3-5, 9": the ascending indices as runs, at most `most` runs and then "...".
std::string indexRuns(const std::vector<std::uint32_t>& indices, std::size_t most)
{
    std::string text;
    std::size_t runs = 0;
    for (std::size_t i = 0; i < indices.size();)
    {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1)
            ++j;
        if (runs == most)
            return text + ", ...";
        text += (runs ? ", " : "") + std::to_string(indices[i]);
        if (j > i)
            text += "-" + std::to_string(indices[j]);
        ++runs;
        i = j + 1;
    }
    return text;
}

class InputNames
{
public:
    explicit InputNames(const std::vector<std::string>& names) : _names(names) {}
    std::string operator()(std::size_t input) const
    {
        return input < _names.size() ? _names[input] : "input " + std::to_string(input + 1);
    }

private:
    const std::vector<std::string>& _names;
};

// Throws unless `input` agrees with the first input on the model and the bake.
void checkSameBake(const PvsFile& first, const PvsFile& input, const std::string& firstName,
                   const std::string& inputName)
{
    const std::string models = inputName + " and " + firstName + " were baked for different models (";
    if (input.geometryFingerprint != first.geometryFingerprint)
        throw PvsFormatError(models + "geometry fingerprint " + hex(input.geometryFingerprint) + " and " +
                             hex(first.geometryFingerprint) + ")");
    if (input.data.fingerprint != first.data.fingerprint)
        throw PvsFormatError(models + "fingerprint " + hex(input.data.fingerprint) + " and " +
                             hex(first.data.fingerprint) + ")");
    if (input.data.objectCount != first.data.objectCount)
        throw PvsFormatError(models + std::to_string(input.data.objectCount) + " and " +
                             std::to_string(first.data.objectCount) + " objects)");
    const std::string bakes = inputName + " and " + firstName + " are not ranges of one bake (";
    if (input.method != first.method)
        throw PvsFormatError(bakes + "method '" + input.method + "' and '" + first.method + "')");
    if (input.options != first.options)
        throw PvsFormatError(bakes + "options '" + input.options + "' and '" + first.options + "')");
    if (input.nearDistance != first.nearDistance)
        throw PvsFormatError(bakes + "near distance " + number(input.nearDistance) + " and " +
                             number(first.nearDistance) + ")");
    if (input.viewCells.totalCells != first.viewCells.totalCells)
        throw PvsFormatError(bakes + std::to_string(input.viewCells.totalCells) + " and " +
                             std::to_string(first.viewCells.totalCells) + " cells in all)");
}
} // namespace

PvsFile mergeViewCellPvs(const std::vector<PvsFile>& ranges, const ViewCellMergeOptions& options)
{
    const InputNames name(options.inputNames);
    if (ranges.empty())
        throw PvsFormatError("nothing to merge: no input files");
    for (std::size_t i = 0; i < ranges.size(); ++i)
    {
        const PvsFile& input = ranges[i];
        if (!input.hasViewCells)
            throw PvsFormatError("cannot merge " + name(i) + ": it holds no view cells");
        if (input.hasCellPortal)
            throw PvsFormatError("cannot merge " + name(i) +
                                 ": it holds cell-portal data (only view-cell files merge)");
        const ViewCellPvs& v = input.viewCells;
        if (v.cells.size() != v.cellIndices.size() || v.pvs.size() != v.cellIndices.size())
            throw PvsFormatError("cannot merge " + name(i) + ": its view cells have " +
                                 std::to_string(v.cellIndices.size()) + " indices, " + std::to_string(v.cells.size()) +
                                 " boxes and " + std::to_string(v.pvs.size()) + " sets");
        if (i > 0)
            checkSameBake(ranges[0], input, name(0), name(i));
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
        std::vector<std::uint32_t> missing;
        std::size_t k = 0;
        for (std::uint32_t index = 0; index < total; ++index)
        {
            while (k < cells.size() && std::get<0>(cells[k]) < index)
                ++k;
            if (k == cells.size() || std::get<0>(cells[k]) != index)
                missing.push_back(index);
        }
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
