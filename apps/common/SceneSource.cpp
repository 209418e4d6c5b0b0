// SPDX-License-Identifier: MIT
#include "SceneSource.h"

#include "AutoWalk.h"

#include <osgVis/VisibilityGroup>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/gen/Generator.h>

#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace osgVis::apps
{
namespace
{
osg::ref_ptr<osg::Node> readModel(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw SceneError("cannot read scene '" + path + "': no such file");
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(path);
    if (!model)
        throw SceneError("cannot read scene '" + path + "': no OpenSceneGraph plugin could load it");
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
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".pvs";
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
// cellportal VisibilityGroup so that the caller's own modes wrap it; the baked data stay registered
// for any cellportal module given this model.
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
                         "': it did not load as a cellportal VisibilityGroup holding one model");
    std::cerr << "scene '" << path << "': baked cell-portal data " << trustLine(*group) << std::endl;
    return group->getChild(0);
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
        result.name = "generated " + options.generateKind + " (" + std::to_string(options.triangles) +
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

    std::string walkPath = options.walkPath;
    if (walkPath.empty() && options.generateKind.empty())
        walkPath = isPvsPath(options.scenePath) ? walkForPvs(options.scenePath) : walkBeside(options.scenePath);
    if (!walkPath.empty())
    {
        result.walk = readWalk(walkPath);
        result.walkSource = walkPath;
    }
    else if (result.walkSource.empty())
    {
        try
        {
            result.walk = makeOrbitWalk(result.objects->scene.bounds());
        }
        catch (const std::invalid_argument& e)
        {
            throw SceneError("scene '" + result.name + "' has no walk and no usable bounds for one: " + e.what());
        }
        result.walkSource = "automatic orbit";
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
