// SPDX-License-Identifier: MIT
// osgvisgen as a user runs it: clear messages and a non-zero exit on bad input, the scene and its
// walk on disk otherwise.
#include "AppProcess.h"

#include <osgVis/core/scene/Walk.h>
#include <osgVis/gen/SceneStats.h>

#include <osg/PagedLOD>
#include <osgDB/ReadFile>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace
{
using osgVis::test::AppRun;

AppRun osgvisgen(const std::string& arguments)
{
    return osgVis::test::runApp(OSGVISGEN_BINARY, arguments);
}

// Emptied at the first call of each test, kept for the rest of it.
std::filesystem::path scratchDir()
{
    static std::string lastTest;
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::filesystem::path dir = std::filesystem::path(OSGVIS_BINARY_DIR) / "tests" / "gen" / test;
    if (test != lastTest)
        osgVis::test::scratchDirectory("gen", test);
    lastTest = test;
    return dir;
}

void expectFailure(const std::string& arguments, const std::string& message)
{
    const AppRun run = osgvisgen(arguments);
    EXPECT_NE(run.exitCode, 0) << arguments;
    EXPECT_LT(run.exitCode, 128) << arguments << ": crashed\n" << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << " printed:\n" << run.output;
}
} // namespace

TEST(GenApp, RejectsBadArgumentsWithAClearMessage)
{
    const std::string out = (scratchDir() / "x.osgb").string();
    expectFailure("--kind castle -o " + out, "unknown scene kind 'castle'");
    expectFailure("--kind office --triangles lots -o " + out, "--triangles expects a non-negative integer, got 'lots'");
    expectFailure("--kind office --triangles 12abc -o " + out,
                  "--triangles expects a non-negative integer, got '12abc'");
    expectFailure("--kind office --triangles -5 -o " + out, "--triangles expects a non-negative integer, got '-5'");
    expectFailure("--kind office --triangles 999 -o " + out,
                  "--triangles must lie between 1000 and 50000000, got '999'");
    expectFailure("--kind office --triangles 50000001 -o " + out,
                  "--triangles must lie between 1000 and 50000000, got '50000001'");
    expectFailure("--kind office --triangles 99999999999999999999999 -o " + out, "--triangles");
    expectFailure("--kind office --seed x -o " + out, "--seed expects a non-negative integer, got 'x'");
    expectFailure("--kind office", "missing output path");
    expectFailure("--kind office -o", "-o expects a value");
    expectFailure("-o " + out, "missing --kind");
    expectFailure("--kind city --adversarial ortho -o " + out, "not both");
    expectFailure("--adversarial no-such-scene -o " + out, "unknown adversarial scene");
    expectFailure("--frobnicate", "unknown option '--frobnicate' (see --help)");
    expectFailure("--kind city --layout line -o " + out, "--layout goes with --kind forest only");
    expectFailure("--kind forest --layout jungle -o " + out, "unknown forest layout 'jungle'");
    expectFailure("--kind forest --triangles 23999 -o " + out, "outside [24000");
    expectFailure("--kind tetra --triangles 1000 -o /nonexistent-dir/deeper/x.osgb", "cannot write");
    expectFailure("--kind city --paged " + out + " --tiles 0", "--tiles must lie between 1 and 65536, got '0'");
    expectFailure("--kind city --paged " + out + " --page-range -3", "--page-range needs a positive distance");
    expectFailure("--adversarial ortho --paged " + out, "--paged goes with --kind only");
    expectFailure("--kind city --paged /proc/no-such/dir", "osgvisgen: ");
    expectFailure("--kind tetra --triangles 1000 -o " + (scratchDir() / "x.unknownextension").string(), "cannot write");
}

TEST(GenApp, HelpAndListTellTheTruth)
{
    const AppRun help = osgvisgen("--help");
    EXPECT_EQ(help.exitCode, 0);
    for (const char* option :
         {"--kind", "--layout", "--triangles", "--seed", "--adversarial", "-o", "--list", "--paged", "--tiles", "--page-range"})
        EXPECT_NE(help.output.find(option), std::string::npos) << option;
    const AppRun list = osgvisgen("--list");
    EXPECT_EQ(list.exitCode, 0);
    for (const char* name :
         {"office", "city", "tetra", "floor", "forest", "single", "dense", "thin-slit", "moving-occluder"})
        EXPECT_NE(list.output.find(name), std::string::npos) << name;
}

TEST(GenApp, WritesTheSceneAndItsWalkAndSaysSo)
{
    const auto dir = scratchDir();
    const std::string scene = (dir / "office.osgb").string();
    const AppRun run = osgvisgen("--kind office --triangles 5000 --seed 3 -o " + scene);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("office"), std::string::npos);
    EXPECT_NE(run.output.find("triangles"), std::string::npos);
    EXPECT_NE(run.output.find(scene), std::string::npos);

    osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile(scene);
    ASSERT_TRUE(loaded.valid());
    const auto triangles = osgVis::gen::sceneStats(*loaded).triangles;
    EXPECT_NEAR(double(triangles), 5000.0, 500.0);
    EXPECT_NE(run.output.find(std::to_string(triangles) + " triangles"), std::string::npos) << run.output;

    const osgVis::core::Walk walk = osgVis::core::Walk::load((dir / "office.walk").string());
    EXPECT_GE(walk.keys.size(), 200u);

    const AppRun adversarial = osgvisgen("--adversarial thin-slit -o " + (dir / "slit.osgb").string());
    ASSERT_EQ(adversarial.exitCode, 0) << adversarial.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "slit.walk"));
    std::filesystem::remove_all(dir);
}

TEST(GenApp, PagedDatabaseLoadsTileByTileAsStockOsgDoes)
{
    const auto dir = scratchDir() / "paged";
    const AppRun run = osgvisgen("--kind city --triangles 20000 --tiles 24 --page-range 500 --paged " + dir.string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find((dir / "root.osgb").string()), std::string::npos) << run.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "root.walk"));
    EXPECT_TRUE(std::filesystem::exists(dir / "culled.osgt"));
    EXPECT_FALSE(std::filesystem::exists(scratchDir() / "paged.osgb")); // no -o: the paged files only

    // Read as osgviewer reads it: the tiles' directory comes from the root file's own path.
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile((dir / "root.osgb").string());
    ASSERT_TRUE(root.valid());
    osg::Group* group = root->asGroup();
    ASSERT_TRUE(group);
    EXPECT_GE(group->getNumChildren(), 12u);
    EXPECT_LE(group->getNumChildren(), 24u);
    std::uint64_t triangles = 0;
    std::size_t objects = 0;
    for (unsigned i = 0; i < group->getNumChildren(); ++i)
    {
        auto* paged = dynamic_cast<osg::PagedLOD*>(group->getChild(i));
        ASSERT_TRUE(paged) << i;
        EXPECT_EQ(paged->getNumChildren(), 0u);
        EXPECT_EQ(paged->getCenterMode(), osg::LOD::USER_DEFINED_CENTER);
        EXPECT_GT(paged->getRadius(), 0.0f);
        EXPECT_EQ(paged->getMaxRange(0), 500.0f);
        osg::ref_ptr<osg::Node> tile = osgDB::readRefNodeFile(paged->getDatabasePath() + paged->getFileName(0));
        ASSERT_TRUE(tile.valid()) << paged->getDatabasePath() << paged->getFileName(0);
        // Every tile lies within the sphere its PagedLOD states.
        const osg::BoundingSphere stated(paged->getCenter(), paged->getRadius());
        const osg::BoundingSphere actual = tile->getBound();
        EXPECT_LE((actual.center() - stated.center()).length() + actual.radius(), stated.radius() * 1.8f) << i;
        const osgVis::gen::SceneStats stats = osgVis::gen::sceneStats(*tile);
        triangles += stats.triangles;
        objects += stats.objects;
    }
    // Every drawable instance of the scene is in exactly one tile.
    const AppRun whole = osgvisgen("--kind city --triangles 20000 -o " + (scratchDir() / "whole.osgb").string());
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    osg::ref_ptr<osg::Node> unpaged = osgDB::readRefNodeFile((scratchDir() / "whole.osgb").string());
    ASSERT_TRUE(unpaged.valid());
    const osgVis::gen::SceneStats expected = osgVis::gen::sceneStats(*unpaged);
    EXPECT_EQ(triangles, expected.triangles);
    EXPECT_EQ(objects, expected.objects);
    std::filesystem::remove_all(scratchDir());
}

TEST(GenApp, FloorDefaultsToThreeHundredThousandTriangles)
{
    const auto dir = scratchDir();
    const std::string scene = (dir / "floor.osgb").string();
    const AppRun run = osgvisgen("--kind floor -o " + scene);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile(scene);
    ASSERT_TRUE(loaded.valid());
    const osgVis::gen::SceneStats stats = osgVis::gen::sceneStats(*loaded);
    EXPECT_NEAR(double(stats.triangles), 300000.0, 30000.0);
    EXPECT_NE(run.output.find(std::to_string(stats.objects) + " objects"), std::string::npos) << run.output;
    expectFailure("--kind floor --triangles 59999 -o " + scene, "outside [60000, 50000000] for floor");
    std::filesystem::remove_all(dir);
}

TEST(GenApp, ForestLayoutsDefaultToTwelveThousandTrianglesATree)
{
    const auto dir = scratchDir();
    const std::pair<const char*, double> layouts[] = {{"single", 12000.0}, {"line", 72000.0}};
    for (const auto& [layout, wanted] : layouts)
    {
        const std::string scene = (dir / (std::string(layout) + ".osgb")).string();
        const AppRun run = osgvisgen(std::string("--kind forest --layout ") + layout + " -o " + scene);
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_NE(run.output.find(std::string("forest ") + layout), std::string::npos) << run.output;
        osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile(scene);
        ASSERT_TRUE(loaded.valid());
        EXPECT_NEAR(double(osgVis::gen::sceneStats(*loaded).triangles), wanted, 0.1 * wanted) << layout;
    }
    std::filesystem::remove_all(dir);
}
