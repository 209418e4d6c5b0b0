// SPDX-License-Identifier: MIT
#include "ToolFiles.h"

#include <osgVis/ModelRepair>
#include <osgVis/PagedDatabase>
#include <osgVis/Q3Solids>

#include <osgDB/ReadFile>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace osgVis::pvstool
{
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

std::string modelPathFromPvs(const std::string& modelFile, const std::string& pvsFile)
{
    const fs::path model = fs::absolute(modelFile);
    const fs::path relative = fs::relative(model, fs::absolute(pvsFile).parent_path());
    return relative.empty() ? model.generic_string() : relative.generic_string();
}

core::SolidSpace statedSolids(const std::string& modelFile)
{
    std::string extension = fs::path(modelFile).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".bsp")
        return {}; // nothing else states solids yet: --explain says so
    try
    {
        return readQ3Solids(modelFile);
    }
    catch (const std::exception& e)
    {
        throw ToolError(std::string("--cells-from solids: ") + e.what());
    }
}

LoadedModel loadModelToBake(const PvsToolOptions& o, bool workerRank)
{
    std::error_code error;
    if (!fs::exists(o.modelFile, error))
        throw ToolError("model file '" + o.modelFile + "' does not exist");
    if (!workerRank)
        checkWritable(o.pvsFile, "the .pvs file");
    if (!o.jsonFile.empty() && !workerRank)
        checkWritable(o.jsonFile, "the JSON file");
    LoadedModel loaded;
    loaded.model = osgDB::readRefNodeFile(o.modelFile);
    if (!loaded.model)
        throw ToolError("cannot read model '" + o.modelFile +
                        "' (not a model osgDB can read, or no plugin for its extension)");
    // A paged database is baked whole, so that its data serve every load state (docs/paging.md).
    const WholeDatabase whole = loadWholeDatabase(*loaded.model);
    if (!whole.unreadable.empty())
        throw ToolError("model '" + o.modelFile + "' is a paged database whose tile " + whole.unreadable.front() +
                        (whole.unreadable.size() > 1 ? " (and " + std::to_string(whole.unreadable.size() - 1) + " more)"
                                                     : std::string()) +
                        " cannot be read: a bake needs every tile");
    if (whole.tilesRead != 0 && !workerRank)
        std::cerr << "model '" << o.modelFile << "': read " << whole.tilesRead << " paged tiles to bake the whole database\n";
    if (const std::string repaired = repairLoadedModel(*loaded.model, o.modelFile); !repaired.empty() && !workerRank)
        std::cerr << "model '" << o.modelFile << "': " << repaired << "\n";
    ExtractionOptions extraction;
    extraction.keepTriangles = true; // both bakes work on the model's faces
    loaded.extracted = extractScene(*loaded.model, extraction);
    if (loaded.extracted->scene.objects.empty())
        throw ToolError("model '" + o.modelFile + "' holds no drawable objects: nothing to bake");
    if (o.bake.subdivision.fromSolids)
        loaded.extracted->scene.solids = statedSolids(o.modelFile);
    return loaded;
}
} // namespace osgVis::pvstool
