// SPDX-License-Identifier: MIT
#include "BakedCellCheck.h"

#include "BenchRun.h"
#include "ReportJson.h"
#include "TextFile.h"


#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/oracle/VolumeOracle.h>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace osgVis::bench
{
namespace
{
struct CellCheck
{
    std::uint32_t cell = 0; ///< absolute index in the bake
    std::size_t pvsObjects = 0, seenObjects = 0, missing = 0;
    double pvsTriangles = 0.0, seenTriangles = 0.0;
    double ratio() const { return seenTriangles > 0.0 ? pvsTriangles / seenTriangles : 1.0; }
};
} // namespace

int runBakedCellCheck(const BenchOptions& options, std::ostream& out)
{
    const core::PvsFile file = core::readPvsFile(options.sceneFile);
    if (!file.hasViewCells || file.viewCells.cells.empty())
        throw std::runtime_error("'" + options.sceneFile + "' holds no view cells (bake it with osgvispvs --method multifocal)");
    // The walk is loaded as for a walk run and not used.
    const apps::LoadedScene loaded = loadBenchScene(options);
    const core::Scene& scene = loaded.objects->scene;
    if (scene.objects.size() != file.data.objectCount)
        throw std::runtime_error("'" + options.sceneFile + "' was baked for " + std::to_string(file.data.objectCount) +
                                 " objects, the model has " + std::to_string(scene.objects.size()));

    oracle::VolumeOracleSettings settings;
    settings.faceSize = options.volumeFaceSize;
    settings.interiorEyes = options.volumeEyes;
    settings.supersample = 1;
    settings.triangles = false;
    // Eyes see what a view of the bake's near distance would: a 90° face reaches √3 × its near plane.
    settings.zNear = file.nearDistance > 0.0 ? file.nearDistance / 1.7320508075688772 : 0.0;
    oracle::VolumeOracle volumeOracle(loaded.model.get(), settings);

    const std::size_t held = file.viewCells.cells.size();
    const std::size_t count = std::min<std::size_t>(options.volumeCells, held);
    std::vector<CellCheck> checks;
    char line[256];
    out << "view cells of " << options.sceneFile << " (" << held << " held, " << file.viewCells.totalCells
        << " in the bake) against the volume oracle, " << count << " cells, " << settings.interiorEyes + 14
        << " eyes each\n";
    for (std::size_t k = 0; k < count; ++k)
    {
        const std::size_t i = count == 1 ? held / 2 : k * (held - 1) / (count - 1);
        const core::Aabb& box = file.viewCells.cells[i];
        const core::VisibleSet& pvs = file.viewCells.pvs[i];
        const oracle::VolumeVisibility seen = volumeOracle.visibleFrom(
            osg::BoundingBoxd(box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z));
        CellCheck check;
        check.cell = file.viewCells.cellIndices[i];
        check.pvsObjects = pvs.count();
        check.seenObjects = seen.objects.size();
        for (std::uint32_t id : seen.objects)
        {
            check.missing += pvs.test(id) ? 0 : 1;
            check.seenTriangles += scene.objects[id].triangleCount;
        }
        for (core::ObjectId id : pvs.ids())
            check.pvsTriangles += scene.objects[id].triangleCount;
        std::snprintf(line, sizeof line,
                      "  cell %6u (%g,%g,%g,%g,%g,%g): PVS %5zu objects, seen %5zu, missing %zu, triangles PVS/seen %.3f\n",
                      check.cell, box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z, check.pvsObjects,
                      check.seenObjects, check.missing, check.ratio());
        out << line;
        checks.push_back(check);
    }
    double meanRatio = 0.0, maxRatio = 0.0;
    std::size_t missing = 0;
    for (const CellCheck& c : checks)
    {
        meanRatio += c.ratio() / double(checks.size());
        maxRatio = std::max(maxRatio, c.ratio());
        missing += c.missing;
    }
    std::snprintf(line, sizeof line, "  mean PVS/seen triangles %.3f, largest %.3f, missing %zu\n", meanRatio, maxRatio,
                  missing);
    out << line;
    if (!options.jsonFile.empty())
        writeTextFile(options.jsonFile, "JSON report",
                      [&](std::ostream& json)
                      {
                          json.precision(17);
                          json << "{\n  \"command\": " << jsonString(options.commandLine) << ",\n  \"cells_checked\": "
                               << checks.size() << ",\n  \"mean_triangle_ratio\": " << meanRatio
                               << ",\n  \"largest_triangle_ratio\": " << maxRatio << ",\n  \"missing_objects\": "
                               << missing << ",\n  \"cells\": [";
                          for (const CellCheck& c : checks)
                              json << (&c == &checks.front() ? "\n" : ",\n") << "    {\"cell\": " << c.cell
                                   << ", \"pvs_objects\": " << c.pvsObjects << ", \"seen_objects\": " << c.seenObjects
                                   << ", \"missing\": " << c.missing << ", \"triangle_ratio\": " << c.ratio() << "}";
                          json << "\n  ]\n}\n";
                      });
    if (missing)
        out << "osgvisbench: FAIL: baked cells lack " << missing << " objects the oracle saw\n";
    return missing ? 1 : 0;
}
} // namespace osgVis::bench
