// SPDX-License-Identifier: MIT
// osgvispvs: bakes cell-and-portal visibility for a model into a .pvs file (docs/pvs-format.md) and
// reports the bake's statistics; `osgvispvs merge` joins range files of a view-cell bake (PvsMerge.h).
// Exit status 1 for files that cannot be read or written or an empty scene, 2 for a bad command line
// (as osgvisbench).
#include "BakeProgressBar.h"
#include "BakeSummary.h"
#include "PvsMerge.h"
#include "PvsToolOptions.h"

#include <osgVis/ModelRepair>
#include <osgVis/SceneExtractor>
#include <osgVis/Version>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <osgDB/ReadFile>

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
// A file the tool cannot produce; main prints it and exits with 1.
struct ToolError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// Fails before a long bake, not after it: the output's folder must exist and take a new file.
void checkWritable(const std::string& path, const char* what)
{
    const fs::path target(path);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code error;
    if (!fs::is_directory(folder, error))
        throw ToolError(std::string("cannot write ") + what + " '" + path + "': folder '" + folder.string() +
                        "' does not exist");
    if (fs::is_directory(target, error))
        throw ToolError(std::string("cannot write ") + what + " '" + path + "': it is a folder");
    const fs::path probe = target.string() + ".osgvispvs-probe";
    if (!std::ofstream(probe))
        throw ToolError(std::string("cannot write ") + what + " '" + path + "': no permission in folder '" +
                        folder.string() + "'");
    fs::remove(probe, error);
}

// The model as the .pvs names it: relative to the .pvs's folder, so both can move together.
std::string modelPathFromPvs(const std::string& modelFile, const std::string& pvsFile)
{
    const fs::path model = fs::absolute(modelFile);
    const fs::path relative = fs::relative(model, fs::absolute(pvsFile).parent_path());
    return relative.empty() ? model.generic_string() : relative.generic_string();
}

int bake(const PvsToolOptions& o)
{
    std::error_code error;
    if (!fs::exists(o.modelFile, error))
        throw ToolError("model file '" + o.modelFile + "' does not exist");
    checkWritable(o.pvsFile, "the .pvs file");
    if (!o.jsonFile.empty())
        checkWritable(o.jsonFile, "the JSON file");

    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(o.modelFile);
    if (!model)
        throw ToolError("cannot read model '" + o.modelFile +
                        "' (not a model osgDB can read, or no plugin for its extension)");
    // The same repairs as the .pvs plugin and the apps make, so the bake sees the drawn scene.
    if (const std::string repaired = osgVis::repairLoadedModel(*model, o.modelFile); !repaired.empty())
        std::cerr << "model '" << o.modelFile << "': " << repaired << "\n";
    osgVis::ExtractionOptions extraction;
    extraction.keepTriangles = true; // the subdivision splits along the model's opaque faces
    const osg::ref_ptr<osgVis::ExtractedScene> extracted = osgVis::extractScene(*model, extraction);
    const osgVis::core::Scene& scene = extracted->scene;
    if (scene.objects.empty())
        throw ToolError("model '" + o.modelFile + "' holds no drawable objects: nothing to bake");
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
        return bake(options);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvispvs: " << e.what() << '\n';
        return 1;
    }
}
