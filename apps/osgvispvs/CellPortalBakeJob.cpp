// SPDX-License-Identifier: MIT
// The cell-portal bake as units: every process subdivides alike, a unit is a range of source cells,
// and the output is the merge of the units' range files (mergeCellPortalPvs), byte for byte what
// bakeCellPortal writes in one go.
#include "BakeJob.h"
#include "BakeSummary.h"
#include "ToolFiles.h"

#include <osgVis/core/cellportal/CellPortalBake.h>
#include <osgVis/core/pvs/CellPortalMerge.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace osgVis::pvstool
{
namespace
{
class CellPortalBakeJob final : public BakeJob
{
public:
    CellPortalBakeJob(const PvsToolOptions& o, const core::Scene& scene)
        : _o(o), _plan(scene, singleThreaded(o.bake))
    {
        for (const core::SceneObject& object : scene.objects)
            _triangles += object.triangleCount;
        _identity.method = "cellportal";
        _identity.options = core::canonicalBakeOptions(o.bake);
        _identity.geometryFingerprint = core::sceneGeometryFingerprint(scene);
        _identity.data.fingerprint = _plan.skeleton().fingerprint;
        _identity.data.objectCount = _plan.skeleton().objectCount;
        _range = requestedCells(o, cellCount(), "cells of this subdivision");
    }

    std::uint32_t cellCount() const override { return std::uint32_t(_plan.cellCount()); }
    std::pair<std::uint32_t, std::uint32_t> cellsToBake() const override { return _range; }
    std::uint32_t defaultUnitCount() const override { return 64; }
    std::vector<double> cellCosts() const override { return _plan.sourceCostEstimates(); }

    core::PvsFile bakeUnit(std::uint32_t first, std::uint32_t end) const override
    {
        core::PvsFile file = _identity;
        file.data = _plan.skeleton();
        std::vector<core::SourceCellVisibility> sources = _plan.bakeSources(first, end);
        for (std::uint32_t c = first; c < end; ++c)
            file.data.sources[c] = std::move(sources[c - first]);
        file.sourceRange = std::make_pair(first, end);
        return file;
    }

    std::string mismatch(const core::PvsFile& file, const BakeUnit& unit) const override
    {
        if (std::string identity = bakeIdentityMismatch(file, _identity); !identity.empty())
            return identity;
        if (!file.hasCellPortal || file.hasViewCells || !file.sourceRange ||
            *file.sourceRange != std::make_pair(unit.first, unit.end))
            return "not the source cells " + std::to_string(unit.first) + ":" + std::to_string(unit.end);
        if (file.data.graph.cells.size() != _plan.cellCount())
            return "baked for a subdivision of " + std::to_string(file.data.graph.cells.size()) + " cells";
        return "";
    }

    core::PvsFile join(std::vector<core::PvsFile>&& units, const std::string& pvsFile) const override
    {
        return joinUnitFiles(core::mergeCellPortalPvs, units, _range == std::make_pair(0u, cellCount()), _o.modelFile, pvsFile);
    }

    void report(const core::PvsFile& output, const BakeRunFigures& run) const override
    {
        std::error_code error;
        BakeSummary summary = summarizeBake(output.data, _triangles);
        summary.modelFile = _o.modelFile;
        summary.pvsFile = _o.pvsFile;
        summary.modelPathInPvs = output.modelPath;
        summary.bakeSeconds = run.seconds;
        summary.fileBytes = fs::file_size(_o.pvsFile, error);
        summary.options = _o.bake;
        if (output.sourceRange)
            std::cout << "source cells " << output.sourceRange->first << "-" << output.sourceRange->second - 1
                      << " of " << cellCount() << " (a range file: join the ranges with osgvispvs merge)\n";
        printBakeSummary(std::cout, summary);
        if (!_o.jsonFile.empty())
        {
            std::ofstream json(_o.jsonFile);
            writeBakeSummaryJson(json, summary);
            if (!json.flush())
                throw ToolError("cannot write the JSON file '" + _o.jsonFile + "'");
        }
    }

private:
    // Units run one per worker thread (the runner sets how many), each search single-threaded.
    static core::BakeOptions singleThreaded(core::BakeOptions options)
    {
        options.threads = 1;
        return options;
    }

    const PvsToolOptions& _o;
    core::CellPortalBakePlan _plan;
    core::PvsFile _identity;
    std::pair<std::uint32_t, std::uint32_t> _range;
    std::uint64_t _triangles = 0;
};
} // namespace

std::unique_ptr<BakeJob> makeCellPortalJob(const PvsToolOptions& o, const core::Scene& scene)
{
    return std::make_unique<CellPortalBakeJob>(o, scene);
}
} // namespace osgVis::pvstool
