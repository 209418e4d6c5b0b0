// SPDX-License-Identifier: MIT
#include "SceneSource.h"

#include "OrbitWalk.h"
#include "Q3PvsMode.h"
#include "FreeSpaceWalk.h"

#include <osgVis/ModelRepair>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/gen/Generator.h>

#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace osgVis::apps
{
namespace
{
bool hasExtension(const std::string& path, const std::string& wanted)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == wanted;
}

osg::ref_ptr<osg::Node> readModel(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw SceneError("cannot read scene '" + path + "': no such file");
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(path);
    if (!model)
        throw SceneError("cannot read scene '" + path + "': no OpenSceneGraph plugin could load it");
    if (const std::string repaired = repairLoadedModel(*model, path); !repaired.empty())
        std::cerr << "scene '" << path << "': " << repaired << "\n";
    return model;
}

core::Walk readWalk(const std::string& path)
{
    try
    {
        return core::Walk::load(path);
    }
    catch (const core::WalkError& e)
    {
        throw SceneError(std::string("bad walk: ") + e.what());
    }
}

// The walk stored beside a model: same folder and stem, extension .walk.
std::string walkBeside(const std::string& scenePath)
{
    std::filesystem::path candidate(scenePath);
    candidate.replace_extension(".walk");
    std::error_code error;
    return std::filesystem::is_regular_file(candidate, error) ? candidate.string() : std::string();
}

bool isPvsPath(const std::string& path)
{
    return hasExtension(path, ".pvs");
}

// The plugin's verdict on the baked data, from the group's descriptions.
std::string trustLine(const osg::Node& group)
{
    const std::string trusted = "osgVis:pvs-trusted", untrusted = "osgVis:pvs-untrusted";
    for (const std::string& description : group.getDescriptions())
    {
        if (description.compare(0, untrusted.size(), untrusted) == 0)
        {
            std::string reason = description.substr(untrusted.size());
            reason.erase(0, reason.find_first_not_of(": "));
            return "untrusted: " + reason;
        }
        if (description.compare(0, trusted.size(), trusted) == 0)
            return "trusted";
    }
    return "untrusted: the .pvs plugin gave no verdict";
}

// The walk of a .pvs scene: beside the .pvs (its stem), else beside the model it names.
std::string walkForPvs(const std::string& pvsPath)
{
    const std::string besidePvs = walkBeside(pvsPath);
    if (!besidePvs.empty())
        return besidePvs;
    try
    {
        const std::filesystem::path modelPath(core::readPvsFile(pvsPath).modelPath);
        const std::filesystem::path model =
            modelPath.is_absolute() ? modelPath : std::filesystem::path(pvsPath).parent_path() / modelPath;
        return walkBeside(model.lexically_normal().string());
    }
    catch (const core::PvsFormatError&)
    {
        return ""; // the plugin already said why the file is not trusted
    }
}

// A .pvs file read through the osgdb_pvs plugin: the model it names, unwrapped from the plugin's
// cellportal VisibilityGroup so that the caller's own modes wrap it. The group holds the baked
// data; the apps build many chains of their own (a group per mode, cull-only sweeps, dumps), so
// they find the data in the process-wide store, where they are put here.
osg::ref_ptr<osg::Node> readPvsScene(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw SceneError("cannot read scene '" + path + "': no such file");
    osgDB::Registry* registry = osgDB::Registry::instance();
    osgDB::ReaderWriter::ReadResult result = registry->readNode(path, registry->getOptions());
    osg::ref_ptr<osg::Node> node = result.getNode();
    if (!node)
    {
        const std::string why = result.message().empty() ? "the osgdb_pvs plugin was not found or could not load it"
                                                         : result.message();
        throw SceneError("cannot read scene '" + path + "': " + why);
    }
    auto* group = dynamic_cast<VisibilityGroup*>(node.get());
    if (!group || group->getNumChildren() != 1)
        throw SceneError("cannot read scene '" + path +
                         "': it did not load as a VisibilityGroup holding one model");
    if (const std::shared_ptr<const core::BakedData> baked = group->getBakedData())
    {
        if (auto data = baked->get<core::CellPortalData>())
            core::registerBakedCellPortalData(std::move(data));
        core::registerBakedViewCells(baked->get<core::BakedViewCells>());
    }
    const char* what = group->getModes() == "multifocal" ? "view cells" : "cell-portal data";
    std::cerr << "scene '" << path << "': baked " << what << " " << trustLine(*group) << std::endl;
    return group->getChild(0);
}

core::Walk orbitWalk(LoadedScene& scene)
{
    try
    {
        scene.walkSource = "automatic orbit";
        return makeOrbitWalk(scene.objects->scene.bounds());
    }
    catch (const std::invalid_argument& e)
    {
        throw SceneError("scene '" + scene.name + "' has no walk and no usable bounds for one: " + e.what());
    }
}

// The walk through the model's free space; with `orbitIfNone`, an orbit when it finds no eye.
core::Walk freeSpaceWalk(LoadedScene& scene, bool orbitIfNone, bool randomGaze, std::uint32_t seed)
{
    // note: the walk needs the triangles, which the scene's own extraction leaves out.
    const osg::ref_ptr<ExtractedScene> withTriangles = extractScene(*scene.model, ExtractionOptions{true});
    try
    {
        const RayScene rays(withTriangles->scene);
        FreeSpaceWalkReport report;
        FreeSpaceWalkOptions walkOptions;
        if (randomGaze)
        {
            walkOptions.randomGaze = true;
            walkOptions.seed = seed;
            walkOptions.stations = 100;
        }
        core::Walk walk = makeFreeSpaceWalk(rays, walkOptions, &report);
        std::ostringstream source;
        source << (randomGaze ? "random gazes (seed " + std::to_string(seed) + ") from the automatic walk's eyes ("
                              : std::string("automatic walk ("))
               << report.stations << " eyes of " << report.eyes << " found from "
               << report.candidates << " floor points; eye height " << report.eyeHeight << ": " << report.eyeHeightRule
               << "; rejected " << report.openSky << " under open sky, " << report.lowCeiling << " under low ceilings, "
               << report.nearWall << " next to a wall, " << report.insideSolid << " inside solid geometry, "
               << report.doubtful << " near it)";
        scene.walkSource = source.str();
        return walk;
    }
    catch (const std::runtime_error& e)
    {
        if (!orbitIfNone)
            throw SceneError("scene '" + scene.name + "': no automatic walk: " + e.what());
        std::cerr << "scene '" << scene.name << "': no automatic walk (" << e.what() << "); orbiting it instead\n";
        return orbitWalk(scene);
    }
}
} // namespace

LoadedScene loadScene(const SceneRequest& options)
{
    LoadedScene result;
    if (!options.generateKind.empty())
    {
        gen::GeneratedScene generated;
        try
        {
            gen::GenerateOptions generateOptions;
            generateOptions.kind = gen::parseSceneKind(options.generateKind);
            if (!options.forestLayout.empty())
            {
                if (generateOptions.kind != gen::SceneKind::Forest)
                    throw SceneError("--layout goes with --generate forest only");
                generateOptions.forestLayout = gen::parseForestLayout(options.forestLayout);
            }
            generateOptions.triangles = options.triangles;
            generateOptions.seed = options.seed;
            generated = gen::generate(generateOptions);
        }
        catch (const std::invalid_argument& e)
        {
            throw SceneError(std::string("--generate: ") + e.what());
        }
        result.model = generated.root;
        result.walk = std::move(generated.walk);
        result.walkSource = "generated";
        const std::string layout = options.forestLayout.empty() ? "" : " " + options.forestLayout;
        result.name = "generated " + options.generateKind + layout + " (" + std::to_string(options.triangles) +
                      " triangles, seed " + std::to_string(options.seed) + ")";
    }
    else
    {
        result.model = isPvsPath(options.scenePath) ? readPvsScene(options.scenePath) : readModel(options.scenePath);
        result.name = options.scenePath;
    }

    result.objects = extractScene(*result.model, ExtractionOptions{false});
    if (result.objects->scene.objects.empty())
        throw SceneError("scene '" + result.name + "' has no drawables: nothing to walk through");
    // A Quake 3 level carries its own cells: the mode q3-pvs-approx culls by them.
    if (options.generateKind.empty() && hasExtension(options.scenePath, ".bsp"))
        std::cerr << "scene '" << result.name << "': " << attachQ3Pvs(options.scenePath, *result.model, *result.objects)
                  << std::endl;

    std::string walkPath = options.walkPath;
    bool walkChosenForUser = false; // the automatic walk may then fall back to an orbit
    if (walkPath.empty() && options.generateKind.empty())
    {
        walkPath = isPvsPath(options.scenePath) ? walkForPvs(options.scenePath) : walkBeside(options.scenePath);
        if (walkPath.empty())
            walkPath = "auto", walkChosenForUser = true;
    }
    if (walkPath == "auto" || walkPath == "random")
        result.walk = freeSpaceWalk(result, walkChosenForUser, walkPath == "random", options.seed);
    else if (walkPath == "orbit")
        result.walk = orbitWalk(result);
    else if (!walkPath.empty())
    {
        result.walk = readWalk(walkPath);
        result.walkSource = walkPath;
    }
    if (result.walk.keys.empty())
        throw SceneError("walk '" + result.walkSource + "' has no views");

    if (options.width != 0)
    {
        result.walk.width = options.width;
        result.walk.height = options.height;
    }
    return result;
}
} // namespace osgVis::apps
