// SPDX-License-Identifier: MIT
// The automatic walk on real game levels nobody here made: OpenArena's Quake 3 maps (GPL data, used
// only here, never shipped), read from the Debian packages when they are installed (scripts/deps.sh
// installs openarena-081-maps; openarena-088-data is optional) through OSG's own bsp plugin. Every
// eye must be outside solid geometry by the tests' own brute-force measure, and the walk must see
// the level from inside: most of what lies in the frustum is hidden.
#include "AppProcess.h"
#include "BruteForceRays.h"

#include <SceneSource.h>

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
