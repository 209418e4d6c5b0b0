// SPDX-License-Identifier: MIT
// The multifocal view-cell bake as units: the cells (a grid, the walk's cells, markers), a unit is a
// range of them, and the output is the merge of the units' range files (mergeViewCellPvs).
#include "BakeJob.h"
#include "ToolFiles.h"

#include <osgVis/core/multifocal/MultifocalBake.h>
#include <osgVis/core/pvs/ViewCellMerge.h>
#include <osgVis/core/scene/SceneFingerprint.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/scene/Walk.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace osgVis::pvstool
{
namespace
{
struct CellLayout
{
    std::vector<core::Aabb> cells;
    std::string description; ///< recorded in the file's options: ranges of other layouts do not merge
    std::optional<core::Walk> walk;
};

std::string triple(const core::Vec3& v)
{
    std::ostringstream s;
    s.precision(17);
    s << v.x << ',' << v.y << ',' << v.z;
    return s.str();
}

CellLayout cellLayout(const PvsToolOptions& o, const core::Scene& scene)
{
    const core::Aabb bounds = scene.bounds();
    const double diagonal = bounds.empty() ? 1.0 : glm::length(bounds.extent());
    const core::Vec3 size = o.cellSize.x > 0.0 ? o.cellSize : core::Vec3(diagonal / 50.0);
    CellLayout layout;
    std::string walkFile = o.walkFile;
    if (!o.grid && walkFile.empty() && scene.cells.empty())
    {
        const fs::path beside = fs::path(o.modelFile).replace_extension(".walk");
        std::error_code error;
        if (fs::exists(beside, error))
            walkFile = beside.string();
    }
    try
    {
        if (o.grid)
        {
            layout.cells = core::gridViewCells(*o.grid, size);
            layout.description = "grid=" + triple(o.grid->min) + "," + triple(o.grid->max) + " size=" + triple(size);
        }
        else if (!walkFile.empty())
        {
            try
            {
                layout.walk = core::Walk::load(walkFile);
            }
            catch (const std::exception& e)
            {
                throw ToolError("cannot read the walk '" + walkFile + "': " + e.what());
            }
            std::vector<core::Vec3> eyes;
            for (const core::WalkKey& key : layout.walk->keys)
                eyes.push_back(key.eye);
            layout.cells = core::viewCellsAlong(eyes, size, o.cellOrigin);
            layout.description = "walk=" + fs::path(walkFile).filename().string() + " origin=" + triple(o.cellOrigin) +
                                 " size=" + triple(size);
        }
        else if (!scene.cells.empty())
        {
            for (const core::Cell& cell : scene.cells)
                layout.cells.push_back(cell.bounds);
            layout.description = "markers=" + std::to_string(scene.cells.size());
        }
        else
        {
            layout.cells = core::gridViewCells(bounds, size);
            layout.description = "grid=model size=" + triple(size);
        }
    }
    catch (const std::invalid_argument& e)
    {
        throw ToolError(std::string("bad view cells: ") + e.what());
    }
    for (const core::Aabb& cell : layout.cells)
    {
        const core::Vec3 e = cell.extent();
        if (cell.empty() || !std::isfinite(e.x + e.y + e.z + cell.min.x + cell.min.y + cell.min.z) ||
            !(e.x > 0.0 && e.y > 0.0 && e.z > 0.0))
            throw ToolError("bad view cells: a cell of zero or negative size, or not finite");
    }
    if (layout.cells.empty())
        throw ToolError("no view cells: the walk holds no eye");
    return layout;
}

// What views of the walk reach, twice over (cameras whose near plane the renderer recomputes);
// without a walk a thousandth of the model's diagonal.
double assumedNear(const PvsToolOptions& o, const CellLayout& layout, const core::Scene& scene)
{
    if (o.nearDistance)
        return *o.nearDistance;
    if (layout.walk && !layout.walk->keys.empty())
    {
        const core::WalkKey& key = layout.walk->keys.front();
        const core::View view =
            core::makeView(key.viewMatrix(), layout.walk->projection.matrix(layout.walk->aspect()));
        return 2.0 * core::nearPlaneReach(view);
    }
    const core::Aabb bounds = scene.bounds();
    return 1e-3 * (bounds.empty() ? 1.0 : glm::length(bounds.extent()));
}

class ViewCellBakeJob final : public BakeJob
{
public:
    ViewCellBakeJob(const PvsToolOptions& o, const core::Scene& scene)
        : _o(o), _scene(scene), _layout(cellLayout(o, scene)), _occluders(core::volumeOccluders(scene))
    {
        _options = o.multifocal;
        _options.nearDistance = assumedNear(o, _layout, scene);
        _identity.method = "multifocal";
        _identity.options = _options.canonical() + " " + _layout.description;
        _identity.nearDistance = _options.nearDistance;
        _identity.geometryFingerprint = core::sceneGeometryFingerprint(scene);
        _identity.data.fingerprint = core::sceneFingerprint(scene);
        _identity.data.objectCount = std::uint32_t(scene.objects.size());
        _identity.hasCellPortal = false;
        _identity.hasViewCells = true;
        _identity.viewCells.totalCells = cellCount();
        _range = requestedCells(o, cellCount(), "view cells of this layout");
    }

    std::uint32_t cellCount() const override { return std::uint32_t(_layout.cells.size()); }
    std::pair<std::uint32_t, std::uint32_t> cellsToBake() const override { return _range; }
    std::uint32_t defaultUnitCount() const override { return 1024; }
    std::vector<double> cellCosts() const override { return core::viewCellCostEstimates(_scene, _layout.cells); }

    core::PvsFile bakeUnit(std::uint32_t first, std::uint32_t end) const override
    {
        core::ViewCellBake bake = core::bakeViewCells(_scene, _occluders, _layout.cells, first, end, _options);
        core::PvsFile file = _identity;
        for (std::uint32_t i = first; i < end; ++i)
        {
            file.viewCells.cellIndices.push_back(i);
            file.viewCells.cells.push_back(_layout.cells[i]);
            file.viewCells.pvs.push_back(std::move(bake.pvs[i - first]));
            _trianglesCulled[i] = double(bake.statistics[i - first].trianglesCulled);
        }
        return file;
    }

    std::string mismatch(const core::PvsFile& file, const BakeUnit& unit) const override
    {
        if (std::string identity = bakeIdentityMismatch(file, _identity); !identity.empty())
            return identity;
        const core::ViewCellPvs& v = file.viewCells;
        if (file.hasCellPortal || !file.hasViewCells || v.totalCells != cellCount() || v.cellIndices.size() != unit.cells())
            return "not the view cells " + std::to_string(unit.first) + ":" + std::to_string(unit.end);
        for (std::uint32_t k = 0; k < unit.cells(); ++k)
            if (v.cellIndices[k] != unit.first + k || v.cells[k].min != _layout.cells[unit.first + k].min ||
                v.cells[k].max != _layout.cells[unit.first + k].max)
                return "not the view cells " + std::to_string(unit.first) + ":" + std::to_string(unit.end);
        return "";
    }

    core::PvsFile join(std::vector<core::PvsFile>&& units, const std::string& pvsFile) const override
    {
        return joinUnitFiles(core::mergeViewCellPvs, units, _range == std::make_pair(0u, cellCount()), _o.modelFile, pvsFile);
    }

    void report(const core::PvsFile& output, const BakeRunFigures& run) const override;

private:
    const PvsToolOptions& _o;
    const core::Scene& _scene;
    CellLayout _layout;
    std::vector<core::OccluderPolygon> _occluders;
    core::MultifocalOptions _options;
    core::PvsFile _identity;
    std::pair<std::uint32_t, std::uint32_t> _range;
    // Per cell, filled by the cells this process bakes (-1: baked elsewhere or in an earlier run).
    mutable std::vector<double> _trianglesCulled = std::vector<double>(_layout.cells.size(), -1.0);
};

void ViewCellBakeJob::report(const core::PvsFile& output, const BakeRunFigures& run) const
{
    std::error_code error;
    const std::uint64_t bytes = fs::file_size(_o.pvsFile, error);
    const auto [first, end] = _range;
    const double cells = double(end - first);
    double pvsObjects = 0.0;
    for (const core::VisibleSet& pvs : output.viewCells.pvs)
        pvsObjects += double(pvs.count());
    // The triangles culled are no part of the file: known only when this process baked every cell.
    double trianglesCulled = 0.0;
    bool trianglesKnown = true;
    for (std::uint32_t i = first; i < end; ++i)
    {
        trianglesKnown = trianglesKnown && _trianglesCulled[i] >= 0.0;
        trianglesCulled += std::max(_trianglesCulled[i], 0.0);
    }
    const double objects = double(_scene.objects.size()), triangles = double(_scene.triangles.size());
    const double culledFraction = trianglesCulled / cells / std::max(triangles, 1.0);
    char culledText[96] = "triangles culled a cell not known (cells baked by other processes or runs)";
    if (trianglesKnown)
        std::snprintf(culledText, sizeof culledText, "%.1f %% of the triangles culled a cell", 100.0 * culledFraction);
    char line[600];
    std::snprintf(line, sizeof line,
                  "multifocal bake of %s: cells %u-%u of %u (%s), %zu objects, %.0f triangles\n"
                  "  PVS: %.1f objects a cell (%.1f %%), %s\n"
                  "  %.2f s (%.3f s a cell), %llu bytes (%.0f a cell), near %.4g -> %s\n",
                  _o.modelFile.c_str(), first, end - 1, cellCount(), _layout.description.c_str(), _scene.objects.size(),
                  triangles, pvsObjects / cells, 100.0 * pvsObjects / cells / std::max(objects, 1.0), culledText,
                  run.seconds, run.seconds / cells, (unsigned long long)bytes, double(bytes) / cells,
                  _options.nearDistance, _o.pvsFile.c_str());
    std::cout << line;
    if (_o.jsonFile.empty())
        return;
    std::ofstream json(_o.jsonFile);
    json.precision(17);
    json << "{\n  \"method\": \"multifocal\",\n  \"model\": \"" << _o.modelFile << "\",\n  \"pvs\": \"" << _o.pvsFile
         << "\",\n  \"objects\": " << _scene.objects.size() << ",\n  \"triangles\": " << _scene.triangles.size()
         << ",\n  \"total_cells\": " << cellCount() << ",\n  \"first_cell\": " << first << ",\n  \"end_cell\": " << end
         << ",\n  \"average_pvs_objects\": " << pvsObjects / cells << ",\n  \"average_pvs_fraction\": "
         << pvsObjects / cells / std::max(objects, 1.0) << ",\n  \"average_triangles_culled_fraction\": ";
    if (trianglesKnown)
        json << culledFraction;
    else
        json << "null";
    json << ",\n  \"bake_seconds\": " << run.seconds << ",\n  \"seconds_per_cell\": " << run.seconds / cells
         << ",\n  \"ranks\": " << run.ranks << ",\n  \"units_baked\": " << run.unitsBaked
         << ",\n  \"units_resumed\": " << run.unitsResumed << ",\n  \"join_seconds\": " << run.joinSeconds
         << ",\n  \"file_bytes\": " << bytes
         << ",\n  \"bytes_per_cell\": " << double(bytes) / cells << ",\n  \"near\": " << _options.nearDistance
         << ",\n  \"options\": \"" << output.options << "\"\n}\n";
    if (!json.flush())
        throw ToolError("cannot write the JSON file '" + _o.jsonFile + "'");
}
} // namespace

std::unique_ptr<BakeJob> makeViewCellJob(const PvsToolOptions& o, const core::Scene& scene)
{
    return std::make_unique<ViewCellBakeJob>(o, scene);
}
} // namespace osgVis::pvstool
