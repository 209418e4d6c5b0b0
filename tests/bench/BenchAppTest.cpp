// End-to-end checks of osgvisbench: runs the built binary on tiny generated scenes (a few thousand
// triangles, 8 views at 160x128, seconds on llvmpipe) and reads back its JSON. What must hold on
// every scene: conservative modes miss nothing, `exact` draws exactly the oracle's set, OSG's own
// culling is frustum culling (it never beats the frustum module's efficacy, and both skip some of
// the scene), and bad input ends with a message and a non-zero status, never a crash.
#include "AppProcess.h"
#include "BadModelFiles.h"
#include "BenchJson.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace osgVis::test;

namespace
{
AppRun runBench(const std::string& arguments)
{
    return runApp(OSGVIS_BENCH_EXE, arguments);
}

std::filesystem::path scratchFile(const std::string& name)
{
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    return scratchDirectory("bench", test->name()) / name;
}

const char* const modeFields[] = {"false_invisible",    "efficacy",       "efficacy_objects",
                                  "occlusion_efficacy", "overestimation", "drawn_fraction",
                                  "cull_ms_median",     "cull_ms_p99",    "fps",
                                  "speedup_vs_osg",     "fps_vs_exact"};

void expectBenchInvariants(const std::string& kind, const std::string& extraModes)
{
    const std::filesystem::path json = scratchFile(kind + ".json");
    const AppRun run =
        runBench("--generate " + kind + " --triangles 5000 --views 8 --size 160x128 --modes osg,frustum,exact" +
                 extraModes + " --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    ASSERT_FALSE(text.empty()) << run.output;

    for (const char* key :
         {"scene", "triangles", "objects", "views", "size", "command", "oracle", "supersample", "modes"})
        EXPECT_TRUE(hasKey(text, key)) << key;
    EXPECT_EQ(numberField(text, "views"), 8.0);
    EXPECT_GT(numberField(text, "objects").value_or(0), 1.0);

    const std::string osg = modeObject(text, "osg");
    const std::string frustum = modeObject(text, "frustum");
    const std::string exact = modeObject(text, "exact");
    for (const std::string* mode : {&osg, &frustum, &exact})
    {
        ASSERT_FALSE(mode->empty()) << text;
        for (const char* field : modeFields)
            EXPECT_TRUE(hasKey(*mode, field)) << field << " in " << *mode;
        EXPECT_GT(numberField(*mode, "fps").value_or(0), 0.0) << *mode;
        EXPECT_GE(numberField(*mode, "cull_ms_median").value_or(-1), 0.0) << *mode;
    }

    EXPECT_EQ(numberField(frustum, "false_invisible"), 0.0) << frustum;
    EXPECT_EQ(numberField(osg, "false_invisible"), 0.0) << osg;
    EXPECT_EQ(numberField(exact, "false_invisible"), 0.0) << exact;
    EXPECT_NEAR(numberField(exact, "overestimation").value_or(0), 1.0, 1e-9) << exact;
    EXPECT_NEAR(numberField(exact, "efficacy").value_or(0), 1.0, 1e-9) << exact;
    EXPECT_NEAR(numberField(osg, "speedup_vs_osg").value_or(0), 1.0, 1e-9) << osg;
    EXPECT_NEAR(numberField(exact, "fps_vs_exact").value_or(0), 1.0, 1e-9) << exact;

    // OSG's default cull is frustum culling on bounds: it cannot cull more of the hidden objects
    // than the frustum module, and on a walk through the scene both leave part of it undrawn.
    EXPECT_LT(numberField(osg, "efficacy").value_or(1), numberField(frustum, "efficacy").value_or(0) + 1e-9);
    EXPECT_LT(numberField(osg, "drawn_fraction").value_or(1), 1.0) << osg;
    EXPECT_LT(numberField(frustum, "drawn_fraction").value_or(1), 1.0) << frustum;
    EXPECT_GE(numberField(frustum, "overestimation").value_or(0), 1.0) << frustum;
}
} // namespace

TEST(BenchApp, CityMeetsTheContract)
{
    expectBenchInvariants("city", "");
}

TEST(BenchApp, OfficeMeetsTheContractAndRunsOcclusionQueries)
{
    expectBenchInvariants("office", ",osg-oq");
}

TEST(BenchApp, UnknownModeExitsTwoBeforeAnyWork)
{
    const AppRun run = runBench("--generate city --triangles 5000 --modes osg,no-such-mode");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("unknown mode 'no-such-mode'"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("frustum"), std::string::npos) << "lists the valid modes: " << run.output;
    EXPECT_EQ(run.output.find("oracle:"), std::string::npos) << "no heavy work before the check: " << run.output;
}

TEST(BenchApp, MissingSceneFileFailsWithMessage)
{
    const AppRun run = runBench("--scene /nonexistent/scene.osgb --modes osg");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_LT(run.exitCode, 128) << "must not crash: " << run.output;
    EXPECT_NE(run.output.find("/nonexistent/scene.osgb"), std::string::npos) << run.output;
}

TEST(BenchApp, MalformedWalkFailsWithMessage)
{
    const std::filesystem::path walk = scratchFile("bad.walk");
    std::ofstream(walk) << "this is not a walk\n";
    const AppRun run = runBench("--generate city --triangles 5000 --walk '" + walk.string() + "' --modes osg");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_LT(run.exitCode, 128) << "must not crash: " << run.output;
    EXPECT_NE(run.output.find("walk"), std::string::npos) << run.output;
}

TEST(BenchApp, BadCommandLineExitsTwo)
{
    EXPECT_EQ(runBench("--generate city --views many").exitCode, 2);
    EXPECT_EQ(runBench("--modes osg").exitCode, 2) << "neither --scene nor --generate";
}

TEST(BenchApp, UnusableModelsFailWithMessage)
{
    const auto dir = scratchDirectory("bench", "unusable-models");
    const AppRun empty = runBench("--scene '" + writeEmptyModel(dir).string() + "' --modes osg");
    EXPECT_EQ(empty.exitCode, 1) << empty.output;
    EXPECT_NE(empty.output.find("has no drawables"), std::string::npos) << empty.output;

    const AppRun garbage = runBench("--scene '" + writeGarbageModel(dir).string() + "' --modes osg");
    EXPECT_EQ(garbage.exitCode, 1) << garbage.output;
    EXPECT_NE(garbage.output.find("cannot read scene"), std::string::npos) << garbage.output;
}

TEST(BenchApp, NanGeometryIsKeptAndNeverCrashes)
{
    const auto dir = scratchDirectory("bench", "nan-model");
    const std::filesystem::path json = dir / "nan.json";
    const AppRun run = runBench("--scene '" + writeNanModel(dir).string() +
                                "' --modes osg,frustum --views 4 --size 160x128 --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    EXPECT_EQ(numberField(text, "objects"), 1.0) << text;
    // Its bounds are not finite, so frustum may not cull it in any view.
    EXPECT_EQ(numberField(modeObject(text, "frustum"), "drawn_fraction"), 1.0) << text;
    EXPECT_EQ(numberField(modeObject(text, "frustum"), "false_invisible"), 0.0) << text;
}
