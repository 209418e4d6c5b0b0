// SPDX-License-Identifier: MIT
#include "RangeMergeChecks.h"

#include <charconv>
#include <cstdio>

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
} // namespace

void checkMergedData(const PvsFile& input, const std::string& inputName, MergedData kind)
{
    const bool viewCells = kind == MergedData::ViewCells;
    if (!(viewCells ? input.hasViewCells : input.hasCellPortal))
        throw PvsFormatError("cannot merge " + inputName + ": it holds no " +
                             (viewCells ? "view cells" : "cell-portal data"));
    if (viewCells ? input.hasCellPortal : input.hasViewCells)
        throw PvsFormatError("cannot merge " + inputName + ": it holds " +
                             (viewCells ? "cell-portal data" : "view cells") +
                             " (view-cell and cell-portal files do not merge together)");
}

PvsFormatError notOneBake(const std::string& firstName, const std::string& inputName, const std::string& what)
{
    return PvsFormatError(inputName + " and " + firstName + " are not ranges of one bake (" + what + ")");
}

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
    if (input.method != first.method)
        throw notOneBake(firstName, inputName, "method '" + input.method + "' and '" + first.method + "'");
    if (input.options != first.options)
        throw notOneBake(firstName, inputName, "options '" + input.options + "' and '" + first.options + "'");
    if (input.nearDistance != first.nearDistance)
        throw notOneBake(firstName, inputName,
                         "near distance " + number(input.nearDistance) + " and " + number(first.nearDistance));
}

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

std::vector<std::uint32_t> missingIndices(const std::vector<std::uint32_t>& present, std::uint32_t total)
{
    std::vector<std::uint32_t> missing;
    std::size_t k = 0;
    for (std::uint32_t index = 0; index < total; ++index)
    {
        while (k < present.size() && present[k] < index)
            ++k;
        if (k == present.size() || present[k] != index)
            missing.push_back(index);
    }
    return missing;
}
} // namespace osgVis::core
