// SPDX-License-Identifier: MIT
// osgvispvs: bakes cell-and-portal visibility for a model into a .pvs file (docs/pvs-format.md) and
// reports the bake's statistics; `osgvispvs merge` joins range files of a view-cell bake (PvsMerge.h).
// Exit status 1 for files that cannot be read or written or an empty scene, 2 for a bad command line
// (as osgvisbench).
#include "BakeProgressBar.h"
#include "BakeSummary.h"
#include "PvsMerge.h"
#include "PvsToolOptions.h"
#include "ToolFiles.h"
#include "ViewCellBakeCommand.h"

#include <osgVis/Version>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;
using namespace osgVis::pvstool;

namespace
{
int bake(const PvsToolOptions& o)
{
    std::error_code error;
    const LoadedModel loaded = loadModelToBake(o);
    const osgVis::core::Scene& scene = loaded.extracted->scene;
    std::uint64_t triangles = 0;
    for (const osgVis::core::SceneObject& object : scene.objects)
        triangles += object.triangleCount;

    BakeProgressBar bar(stderr, o.forceProgress || isatty(fileno(stderr)));
    const auto start = std::chrono::steady_clock::now();
    osgVis::core::PvsFile file;
    file.data = osgVis::core::bakeCellPortal(scene, o.bake,
                                             [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bar.finish(file.data.graph.cells.size(), seconds);

    file.method = "cellportal";
    file.options = osgVis::core::canonicalBakeOptions(o.bake);
    file.geometryFingerprint = osgVis::core::sceneGeometryFingerprint(scene);
    file.modelPath = modelPathFromPvs(o.modelFile, o.pvsFile);
    try
    {
        osgVis::core::writePvsFile(o.pvsFile, file);
    }
    catch (const std::exception& e)
    {
        throw ToolError("cannot write the .pvs file '" + o.pvsFile + "': " + e.what());
    }

    BakeSummary summary = summarizeBake(file.data, triangles);
    summary.modelFile = o.modelFile;
    summary.pvsFile = o.pvsFile;
    summary.modelPathInPvs = file.modelPath;
    summary.bakeSeconds = seconds;
    summary.fileBytes = fs::file_size(o.pvsFile, error);
    summary.options = o.bake;
    printBakeSummary(std::cout, summary);
    if (!o.jsonFile.empty())
    {
        std::ofstream json(o.jsonFile);
        writeBakeSummaryJson(json, summary);
        if (!json.flush())
            throw ToolError("cannot write the JSON file '" + o.jsonFile + "'");
    }
    return 0;
}
} // namespace

int main(int argc, char** argv)
{
    if (argc > 1 && std::string(argv[1]) == "merge")
        return runPvsMerge(std::vector<std::string>(argv + 2, argv + argc));
    PvsToolOptions options;
    try
    {
        options = parsePvsToolOptions(argc, argv);
    }
    catch (const UsageError& e)
    {
        std::cerr << "osgvispvs: " << e.what() << "\n(osgvispvs --help for usage)\n";
        return 2;
    }
    if (options.help)
    {
        std::cout << pvsToolUsage();
        return 0;
    }
    if (options.version)
    {
        std::cout << "osgvispvs (osgVis " << osgVisGetVersion() << ")\n";
        return 0;
    }
    try
    {
        return options.method == "multifocal" ? bakeViewCells(options) : bake(options);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvispvs: " << e.what() << '\n';
        return 1;
    }
}
