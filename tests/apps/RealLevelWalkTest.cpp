// SPDX-License-Identifier: MIT
// The automatic walk on real game levels nobody here made: OpenArena's Quake 3 maps (GPL data, used
// only here, never shipped), read from the Debian packages when they are installed (scripts/deps.sh
// installs openarena-081-maps; openarena-088-data is optional) through OSG's own bsp plugin. Every
// eye must be outside solid geometry by the tests' own brute-force measure, and the walk must see
// the level from inside: most of what lies in the frustum is hidden.
#include "AppProcess.h"
#include "BruteForceRays.h"

#include <Q3PvsMode.h>
#include <SceneSource.h>

#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/Geometry>
#include <osg/NodeVisitor>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

using namespace osgVis;

namespace
{
struct Level
{
    const char* package;
    const char* pk3;
    const char* map;
};

const Level levels[] = {
    {"openarena-081-maps", "/usr/share/games/openarena/baseoa/pak1-maps.pk3", "maps/oa_dm4.bsp"},
    {"openarena-081-maps", "/usr/share/games/openarena/baseoa/pak1-maps.pk3", "maps/ce1m7.bsp"},
    {"openarena-088-data", "/usr/share/games/openarena/baseoa/pak6-patch088.pk3", "maps/aggressor.bsp"},
};

// The map extracted from its .pk3 (a zip) into a scratch folder, or empty when that cannot be done.
std::string extract(const Level& level, std::string& why)
{
    if (!std::filesystem::exists(level.pk3))
    {
        why = std::string(level.pk3) + " is not installed (Debian package " + level.package + ")";
        return {};
    }
    const std::filesystem::path dir = test::scratchDirectory("apps", std::filesystem::path(level.map).stem().string());
    const test::AppRun unzip =
        test::runApp("unzip", std::string("-o -q '") + level.pk3 + "' '" + level.map + "' -d '" + dir.string() + "'");
    if (unzip.exitCode != 0)
    {
        why = "cannot extract " + std::string(level.map) + " with unzip: " + unzip.output;
        return {};
    }
    return (dir / level.map).string();
}
} // namespace

class RealLevelWalk : public ::testing::TestWithParam<Level>
{
};

TEST_P(RealLevelWalk, EveryEyeIsOutsideSolidGeometryAndSeesTheLevelFromInside)
{
    std::string why;
    const std::string path = extract(GetParam(), why);
    if (path.empty())
        GTEST_SKIP() << why;
    apps::SceneRequest request;
    request.scenePath = path;
    request.walkPath = "auto";
    const apps::LoadedScene scene = apps::loadScene(request);
    std::cout << GetParam().map << ": " << scene.objects->scene.objects.size() << " objects, walk: " << scene.walkSource
              << "\n";
    ASSERT_GE(scene.walk.keys.size(), 40u) << scene.walkSource;
    const osg::ref_ptr<ExtractedScene> withTriangles = extractScene(*scene.model);
    std::mt19937 random(11);
    std::size_t inside = 0;
    for (const core::WalkKey& key : scene.walk.keys)
        inside += test::insideByBruteForce(withTriangles->scene, key.eye, random);
    std::cout << GetParam().map << ": " << inside << " of " << scene.walk.keys.size()
              << " views with the eye inside solid geometry\n";
    EXPECT_EQ(inside, 0u);
    const core::Aabb bounds = withTriangles->scene.bounds();
    for (const core::WalkKey& key : scene.walk.keys)
        EXPECT_TRUE(bounds.contains(key.eye)) << "eye outside the level's bounds";
}

INSTANTIATE_TEST_SUITE_P(OpenArena, RealLevelWalk, ::testing::ValuesIn(levels),
                         [](const ::testing::TestParamInfo<Level>& info)
                         { return std::filesystem::path(info.param.map).stem().string(); });

// The level as the game draws it: osgVis::repairLoadedModel gives every polygon face q3map2's own
// triangles (the plugin's fans cover other ground), and the level's own cells cull (the mode
// q3-pvs-approx, by q3map2's cluster PVS) below the frustum alone.
TEST_P(RealLevelWalk, PolygonFacesDrawTheLevelsTrianglesAndItsCellsCull)
{
    std::string why;
    const std::string path = extract(GetParam(), why);
    if (path.empty())
        GTEST_SKIP() << why;
    apps::registerQ3PvsMode();
    apps::SceneRequest request;
    request.scenePath = path;
    request.walkPath = "auto";
    const apps::LoadedScene scene = apps::loadScene(request);

    std::size_t fans = 0, triangleLists = 0;
    struct Counter : osg::NodeVisitor
    {
        std::size_t *fans, *lists;
        Counter(std::size_t* f, std::size_t* l) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), fans(f), lists(l) {}
        void apply(osg::Drawable& drawable) override
        {
            if (const osg::Geometry* g = drawable.asGeometry())
                for (unsigned i = 0; i < g->getNumPrimitiveSets(); ++i)
                {
                    *fans += g->getPrimitiveSet(i)->getMode() == osg::PrimitiveSet::TRIANGLE_FAN;
                    *lists += g->getPrimitiveSet(i)->getMode() == osg::PrimitiveSet::TRIANGLES;
                }
        }
    } counter(&fans, &triangleLists);
    scene.model->accept(counter);
    EXPECT_EQ(fans, 0u) << "a polygon face is still the plugin's fan";
    EXPECT_GT(triangleLists, 0u);

    core::ModuleChain frustum = core::createChain("frustum");
    core::ModuleChain cells = core::createChain("frustum,q3-pvs-approx");
    frustum.setScene(scene.objects->scene);
    cells.setScene(scene.objects->scene);
    std::size_t frustumKept = 0, cellsKept = 0;
    for (const core::WalkKey& key : scene.walk.keys)
    {
        const core::View view = core::makeView(key.viewMatrix(), scene.walk.projection.matrix(scene.walk.aspect()),
                                               key.time, scene.walk.width, scene.walk.height);
        core::VisibleSet a(scene.objects->scene.objects.size(), true), b(scene.objects->scene.objects.size(), true);
        frustum.cull(view, a);
        cells.cull(view, b);
        frustumKept += a.count();
        cellsKept += b.count();
        core::VisibleSet both = a;
        both.intersectWith(b);
        EXPECT_EQ(both, b) << "the level's cells keep only what the frustum keeps";
    }
    std::cout << GetParam().map << ": the frustum keeps " << frustumKept << " objects over the walk, with the level's cells "
              << cellsKept << "\n";
    // oa_dm4 0.36, aggressor 0.60 of the frustum's; ce1m7's PVS is coarse (0.86).
    EXPECT_LT(double(cellsKept), 0.9 * double(frustumKept));
}
