// SPDX-License-Identifier: MIT
#include <osgVis/gen/Generator.h>

#include "NameTable.h"
#include "Scenes.h"

#include <osg/LightModel>

#include <algorithm>
#include <stdexcept>

namespace osgVis::gen
{
namespace
{
constexpr Named<SceneKind> kindNames[] = {{SceneKind::Office, "office"},
                                          {SceneKind::City, "city"},
                                          {SceneKind::Tetra, "tetra"},
                                          {SceneKind::Floor, "floor"},
                                          {SceneKind::Forest, "forest"}};

// Under a plain headlight, floors and ceilings seen edge-on get no diffuse light and draw black; a
// global ambient term keeps every surface readable in screenshots, and two-sided lighting lights
// walls and polygons seen from behind.
void addReadableLighting(osg::Group& root)
{
    osg::ref_ptr<osg::LightModel> lightModel = new osg::LightModel;
    lightModel->setAmbientIntensity(osg::Vec4(0.45f, 0.45f, 0.45f, 1.0f));
    lightModel->setTwoSided(true);
    root.getOrCreateStateSet()->setAttributeAndModes(lightModel.get());
}

GeneratedScene mesh(SceneModel scene, double density)
{
    GeneratedScene generated{buildSceneGraph(scene.model, density), std::move(scene.walk)};
    addReadableLighting(*generated.root);
    return generated;
}
} // namespace

std::uint64_t defaultTriangles(SceneKind kind, ForestLayout layout)
{
    switch (kind)
    {
    case SceneKind::Floor:
        return 300000;
    case SceneKind::Forest:
        // The paper's dense forest has ~385 000 triangles in 32 trees of ~12 000.
        return layout == ForestLayout::Dense ? 385000 : 12000 * std::uint64_t(forestTreeCount(layout));
    default:
        return GenerateOptions{}.triangles;
    }
}

std::uint64_t minTrianglesFor(SceneKind kind, ForestLayout layout)
{
    switch (kind)
    {
    case SceneKind::Floor:
        // The floor's layout is the same for every seed up to doors and furniture; its coarsest
        // meshing has about 57 000 triangles, so budgets below this could not land within 10 %.
        return 60000;
    case SceneKind::Forest:
        // A tree has at most 31 tubes (12 triangles at the coarsest) and 31 clumps (8): 620.
        return std::max<std::uint64_t>(minTriangles, 750 * std::uint64_t(forestTreeCount(layout)));
    default:
        return minTriangles;
    }
}

GeneratedScene generate(const GenerateOptions& options)
{
    const std::uint64_t lowest = minTrianglesFor(options.kind, options.forestLayout);
    if (options.triangles < lowest || options.triangles > maxTriangles)
        throw std::invalid_argument("triangle budget " + std::to_string(options.triangles) + " is outside [" +
                                    std::to_string(lowest) + ", " + std::to_string(maxTriangles) + "] for " +
                                    sceneKindName(options.kind));
    SceneModel scene;
    switch (options.kind)
    {
    case SceneKind::Office:
        scene = officeModel(options.triangles, options.seed);
        break;
    case SceneKind::City:
        scene = cityModel(options.triangles, options.seed);
        break;
    case SceneKind::Tetra:
        scene = tetraModel(options.triangles, options.seed);
        break;
    case SceneKind::Floor:
        scene = floorModel(options.seed);
        break;
    case SceneKind::Forest:
        scene = forestModel(options.forestLayout, options.seed);
        break;
    }
    const double density = calibrateDensity(scene.model, options.triangles);
    return mesh(std::move(scene), density);
}

SceneKind parseSceneKind(const std::string& name)
{
    return parseNamed(kindNames, name, "scene kind");
}

const char* sceneKindName(SceneKind kind)
{
    return nameOf(kindNames, kind);
}

std::vector<std::string> sceneKindNames()
{
    return namesIn(kindNames);
}

GeneratedScene adversarialScene(const std::string& name)
{
    // Coarsest meshing: every face one cell, so the scenes stay tiny and their geometry exact.
    return mesh(adversarialModel(name), 0.0);
}
} // namespace osgVis::gen
