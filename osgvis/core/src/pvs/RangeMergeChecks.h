// SPDX-License-Identifier: MIT
#pragma once
// What the merges of split bakes (view cells, cell-portal sources) check alike: the inputs' names in
// messages, that two inputs come from one model and one bake, and index lists in messages.
#include <osgVis/core/pvs/PvsFormat.h>

#include <string>
#include <vector>

namespace osgVis::core
{
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

// What a merge joins: view-cell and cell-portal files do not merge together.
enum class MergedData
{
    CellPortal,
    ViewCells,
};
// Throws unless `input` holds the `kind` of data the merge joins, and not the other kind.
void checkMergedData(const PvsFile& input, const std::string& inputName, MergedData kind);

// Throws unless `input` agrees with the first input on the model (fingerprints, object count) and
// the bake (method, options, near distance).
void checkSameBake(const PvsFile& first, const PvsFile& input, const std::string& firstName,
                   const std::string& inputName);
// The error for an input that disagrees with the first on something else of the bake.
PvsFormatError notOneBake(const std::string& firstName, const std::string& inputName, const std::string& what);

// "0, 3-5, 9": the ascending indices as runs, at most `most` runs and then "...".
std::string indexRuns(const std::vector<std::uint32_t>& indices, std::size_t most);
// The indices 0..total-1 missing from the ascending `present`.
std::vector<std::uint32_t> missingIndices(const std::vector<std::uint32_t>& present, std::uint32_t total);
} // namespace osgVis::core
