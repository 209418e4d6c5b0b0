// SPDX-License-Identifier: MIT
// What both bake jobs check alike: the identity of a unit's file, and the range a command asks for.
#include "BakeJob.h"
#include "ToolFiles.h"

#include <cstdio>

namespace osgVis::pvstool
{
std::string bakeIdentityMismatch(const core::PvsFile& file, const core::PvsFile& identity)
{
    const auto hex = [](std::uint64_t value)
    {
        char text[19];
        std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
        return std::string(text);
    };
    if (file.geometryFingerprint != identity.geometryFingerprint || file.data.fingerprint != identity.data.fingerprint ||
        file.data.objectCount != identity.data.objectCount)
        return "baked for another model (geometry fingerprint " + hex(file.geometryFingerprint) + ", this model's " +
               hex(identity.geometryFingerprint) + ")";
    if (file.method != identity.method)
        return "baked by method '" + file.method + "', not '" + identity.method + "'";
    if (file.options != identity.options)
        return "baked with options '" + file.options + "', not '" + identity.options + "'";
    if (file.nearDistance != identity.nearDistance)
        return "baked for another near distance";
    return "";
}

core::PvsFile joinUnitFiles(core::PvsFile (*merge)(const std::vector<core::PvsFile>&, const core::ViewCellMergeOptions&),
                            const std::vector<core::PvsFile>& units, bool allCells, const std::string& modelFile,
                            const std::string& pvsFile)
{
    core::ViewCellMergeOptions options;
    options.requireAllCells = allCells;
    core::PvsFile file = merge(units, options);
    file.modelPath = modelPathFromPvs(modelFile, pvsFile);
    return file;
}

std::pair<std::uint32_t, std::uint32_t> requestedCells(const PvsToolOptions& o, std::uint32_t total, const char* what)
{
    if (o.shard)
        return shardCells(o.shard->first, o.shard->second, total);
    if (!o.cellRange)
        return {0, total};
    const auto [first, end] = *o.cellRange;
    if (end > total)
        throw ToolError("--cells " + std::to_string(first) + ":" + std::to_string(end) + " reaches past the " +
                        std::to_string(total) + " " + what);
    return {first, end};
}
} // namespace osgVis::pvstool
