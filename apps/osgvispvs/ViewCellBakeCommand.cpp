// SPDX-License-Identifier: MIT
#include "ViewCellBakeCommand.h"

#include "BakeProgressBar.h"
#include "ToolFiles.h"

#include <osgVis/core/multifocal/MultifocalBake.h>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/scene/SceneFingerprint.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/scene/Walk.h>

#include <tbb/global_control.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
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
} // namespace

int bakeViewCells(const PvsToolOptions& o)
{
    const LoadedModel loaded = loadModelToBake(o);
    const core::Scene& scene = loaded.extracted->scene;
    const CellLayout layout = cellLayout(o, scene);
    const std::uint32_t total = std::uint32_t(layout.cells.size());
    std::uint32_t first = 0, end = total;
    if (o.cellRange)
    {
        first = o.cellRange->first;
        end = o.cellRange->second;
        if (end > total)
            throw ToolError("--cells " + std::to_string(first) + ":" + std::to_string(end) + " reaches past the " +
                            std::to_string(total) + " view cells of this layout");
    }
    core::MultifocalOptions options = o.multifocal;
    options.nearDistance = assumedNear(o, layout, scene);

    std::unique_ptr<tbb::global_control> threads;
    if (o.bake.threads > 0)
        threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o.bake.threads);
    BakeProgressBar bar(stderr, o.forceProgress || isatty(fileno(stderr)));
    const auto start = std::chrono::steady_clock::now();
    core::ViewCellBake bake = core::bakeViewCells(scene, layout.cells, first, end, options,
                                                  [&](std::size_t done, std::size_t count) { bar.update(done, count); });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bar.finish(end - first, seconds);

    core::PvsFile file;
    file.modelPath = modelPathFromPvs(o.modelFile, o.pvsFile);
    file.method = "multifocal";
    file.options = options.canonical() + " " + layout.description;
    file.nearDistance = options.nearDistance;
    file.geometryFingerprint = core::sceneGeometryFingerprint(scene);
    file.data.fingerprint = core::sceneFingerprint(scene);
    file.data.objectCount = std::uint32_t(scene.objects.size());
    file.hasCellPortal = false;
    file.hasViewCells = true;
    file.viewCells.totalCells = total;
    double pvsObjects = 0.0, trianglesCulled = 0.0;
    for (std::uint32_t i = first; i < end; ++i)
    {
        file.viewCells.cellIndices.push_back(i);
        file.viewCells.cells.push_back(layout.cells[i]);
        pvsObjects += double(bake.pvs[i - first].count());
        trianglesCulled += double(bake.statistics[i - first].trianglesCulled);
        file.viewCells.pvs.push_back(std::move(bake.pvs[i - first]));
    }
    try
    {
        core::writePvsFile(o.pvsFile, file);
    }
    catch (const std::exception& e)
    {
        throw ToolError("cannot write the .pvs file '" + o.pvsFile + "': " + e.what());
    }
    std::error_code error;
    const std::uint64_t bytes = fs::file_size(o.pvsFile, error);
    const double cells = double(end - first);
    const double objects = double(scene.objects.size()), triangles = double(scene.triangles.size());
    char line[400];
    std::snprintf(line, sizeof line,
                  "multifocal bake of %s: cells %u-%u of %u (%s), %zu objects, %.0f triangles\n"
                  "  PVS: %.1f objects a cell (%.1f %%), %.1f %% of the triangles culled a cell\n"
                  "  %.2f s (%.3f s a cell), %llu bytes (%.0f a cell), near %.4g -> %s\n",
                  o.modelFile.c_str(), first, end - 1, total, layout.description.c_str(), scene.objects.size(),
                  triangles, pvsObjects / cells, 100.0 * pvsObjects / cells / std::max(objects, 1.0),
                  100.0 * trianglesCulled / cells / std::max(triangles, 1.0), seconds, seconds / cells,
                  (unsigned long long)bytes, double(bytes) / cells, options.nearDistance, o.pvsFile.c_str());
    std::cout << line;
    if (!o.jsonFile.empty())
    {
        std::ofstream json(o.jsonFile);
        json.precision(17);
        json << "{\n  \"method\": \"multifocal\",\n  \"model\": \"" << o.modelFile << "\",\n  \"pvs\": \"" << o.pvsFile
             << "\",\n  \"objects\": " << scene.objects.size() << ",\n  \"triangles\": " << scene.triangles.size()
             << ",\n  \"total_cells\": " << total << ",\n  \"first_cell\": " << first << ",\n  \"end_cell\": " << end
             << ",\n  \"average_pvs_objects\": " << pvsObjects / cells << ",\n  \"average_pvs_fraction\": "
             << pvsObjects / cells / std::max(objects, 1.0) << ",\n  \"average_triangles_culled_fraction\": "
             << trianglesCulled / cells / std::max(triangles, 1.0) << ",\n  \"bake_seconds\": " << seconds
             << ",\n  \"seconds_per_cell\": " << seconds / cells << ",\n  \"file_bytes\": " << bytes
             << ",\n  \"bytes_per_cell\": " << double(bytes) / cells << ",\n  \"near\": " << options.nearDistance
             << ",\n  \"options\": \"" << file.options << "\"\n}\n";
        if (!json.flush())
            throw ToolError("cannot write the JSON file '" + o.jsonFile + "'");
    }
    return 0;
}
} // namespace osgVis::pvstool
