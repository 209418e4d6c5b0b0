// SPDX-License-Identifier: MIT
// osgvisbench --dynamic end to end on a tiny city (5000 triangles, 8 views at 160x128): cars drive
// every frame, buildings are dropped and deleted at fixed frames, the oracle renders each frame's
// scene, and conservative modes still miss nothing. With 8 views the changes are exactly: 12 cars
// moved at frames 1..7, 3 buildings dropped at frames 2 and 4, 3 deleted at frames 2 and 5.
#include "AppProcess.h"
#include "BenchJson.h"

#include <gtest/gtest.h>

#include <string>

using namespace osgVis::test;

namespace
{
const std::string expectedChanges = "dynamic changes: 96 (84 car moves, 6 buildings dropped, 6 buildings removed)";

AppRun runDynamicBench(const std::string& modes, const std::filesystem::path& json)
{
    return runApp(OSGVIS_BENCH_EXE, "--generate city --triangles 5000 --views 8 --size 160x128 --dynamic --modes " +
                                        modes + " --json '" + json.string() + "'");
}

std::filesystem::path scratchFile(const std::string& name)
{
    return scratchDirectory("bench-dynamic", ::testing::UnitTest::GetInstance()->current_test_info()->name()) / name;
}

void expectNoFalseInvisible(const std::string& json, const std::string& mode)
{
    const std::string object = modeObject(json, mode);
    ASSERT_FALSE(object.empty()) << json;
    EXPECT_EQ(numberField(object, "false_invisible"), 0.0) << mode;
    EXPECT_GT(numberField(object, "drawn_fraction").value_or(0.0), 0.0) << mode;
}
} // namespace

TEST(BenchDynamic, FrustumAndOctreeMissNothingWhileTheSceneChanges)
{
    const std::filesystem::path json = scratchFile("dynamic.json");
    const AppRun run = runDynamicBench("osg,frustum,octree", json);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find(expectedChanges), std::string::npos) << run.output;
    const std::string text = readText(json);
    EXPECT_EQ(numberField(text, "views"), 8.0);
    for (const char* mode : {"osg", "frustum", "octree"})
        expectNoFalseInvisible(text, mode);
    // The octree culls by occlusion too: it must draw less than frustum culling alone.
    EXPECT_LT(numberField(modeObject(text, "octree"), "drawn_fraction").value_or(1.0),
              numberField(modeObject(text, "frustum"), "drawn_fraction").value_or(0.0));
}

TEST(BenchDynamic, SameSeedSameRun)
{
    const std::filesystem::path first = scratchFile("first.json"), second = scratchFile("second.json");
    ASSERT_EQ(runDynamicBench("frustum", first).exitCode, 0);
    ASSERT_EQ(runDynamicBench("frustum", second).exitCode, 0);
    EXPECT_EQ(numberField(modeObject(readText(first), "frustum"), "drawn_fraction"),
              numberField(modeObject(readText(second), "frustum"), "drawn_fraction"));
    EXPECT_EQ(numberField(readText(first), "objects"), numberField(readText(second), "objects"));
}

// Runs once the lead's mask module is registered; skipped while `mask` is an unknown mode.
TEST(BenchDynamic, MaskMissesNothingWhileTheSceneChanges)
{
    const std::filesystem::path json = scratchFile("mask.json");
    const AppRun run = runDynamicBench("frustum+mask", json);
    if (run.exitCode == 2 && run.output.find("mask") != std::string::npos &&
        run.output.find("unknown") != std::string::npos)
        GTEST_SKIP() << "mask module not registered yet";
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find(expectedChanges), std::string::npos) << run.output;
    expectNoFalseInvisible(readText(json), "frustum+mask");
}

TEST(BenchDynamic, RefusesModesThatCannotFollowChanges)
{
    for (const char* mode : {"exact", "osg-oq"})
    {
        const AppRun run = runDynamicBench(mode, scratchFile(std::string(mode) + ".json"));
        EXPECT_EQ(run.exitCode, 1) << run.output;
        EXPECT_NE(run.output.find(std::string("--dynamic runs osg and module-chain modes only, not '") + mode + "'"),
                  std::string::npos)
            << run.output;
    }
}
