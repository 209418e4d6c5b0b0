#include "SceneSource.h"

#include "AutoWalk.h"

#include <osgVis/gen/Generator.h>

#include <osgDB/ReadFile>

#include <filesystem>

namespace osgVis::viewer
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
} // namespace

ViewerScene loadViewerScene(const ViewerOptions& options)
{
    ViewerScene result;
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
        result.model = readModel(options.scenePath);
        result.name = options.scenePath;
    }

    result.objects = extractScene(*result.model, ExtractionOptions{false});
    if (result.objects->scene.objects.empty())
        throw SceneError("scene '" + result.name + "' has no drawables: nothing to walk through");

    std::string walkPath = options.walkPath;
    if (walkPath.empty() && options.generateKind.empty())
        walkPath = walkBeside(options.scenePath);
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
} // namespace osgVis::viewer
