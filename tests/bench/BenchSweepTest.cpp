// SPDX-License-Identifier: MIT
// osgvisbench's cull-only sweeps (--speeds, --threads), cube views (--cube) and their command-line
// errors, end to end on a tiny generated city (needs a display for the rendered passes).
#include "AppProcess.h"
#include "BenchJson.h"
#include "SweepJson.h"

#include <osgVis/gen/Generator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <utility>

using namespace osgVis::test;

namespace
{
const char* const TinyCity = "--generate city --triangles 5000 --seed 1 --size 160x128";

AppRun runBench(const std::string& arguments)
{
    return runApp(OSGVIS_BENCH_EXE, arguments);
}

std::filesystem::path scratchJson()
{
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    return scratchDirectory("bench-sweep", test->name()) / "report.json";
}

std::size_t cityWalkKeys()
{
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::City;
    options.triangles = 5000;
    options.seed = 1;
    return osgVis::gen::generate(options).walk.keys.size();
}

// Frames of a sweep at `speed` (docs/benchmark.md): one pass over the walk, at least min(30, keys).
double pacedFrames(std::size_t keys, unsigned speed)
{
    return double(std::max((keys - 1) / speed + 1, std::min<std::size_t>(30, keys)));
}
} // namespace

TEST(BenchSweep, SpeedsTimesThreadsForEveryModuleChainOnly)
{
    const std::filesystem::path json = scratchJson();
    const AppRun run =
        runBench(std::string(TinyCity) + " --views 8 --modes osg,frustum --speeds 1,4 --threads 1,2 --json '" +
                 json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);

    // The rendered report is unchanged beside the sweeps.
    EXPECT_EQ(numberField(text, "views"), 8.0) << text;
    EXPECT_EQ(numberField(modeObject(text, "frustum"), "false_invisible"), 0.0) << text;
    EXPECT_FALSE(modeObject(text, "osg").empty()) << text;

    const std::vector<SweepEntry> entries = sweepEntries(text);
    ASSERT_EQ(entries.size(), 4u) << text;
    const std::size_t keys = cityWalkKeys();
    std::set<std::pair<double, double>> combinations;
    for (const SweepEntry& entry : entries)
    {
        EXPECT_EQ(entry.mode, "frustum") << "osg is no module chain and is not swept";
        combinations.insert({entry.speed, entry.threads});
        EXPECT_EQ(entry.views, pacedFrames(keys, unsigned(entry.speed))) << "speed " << entry.speed;
        ASSERT_TRUE(entry.cullMsMedian && entry.cullMsP99 && entry.visibleMean) << text;
        EXPECT_GE(*entry.cullMsMedian, 0.0);
        EXPECT_GE(*entry.cullMsP99, *entry.cullMsMedian);
        EXPECT_GT(*entry.visibleMean, 0.0);
    }
    EXPECT_EQ(combinations, (std::set<std::pair<double, double>>{{1, 1}, {1, 2}, {4, 1}, {4, 2}}));
    // Same views, same answers, whatever the thread count.
    for (std::size_t i = 0; i + 1 < entries.size(); ++i)
    {
        if (entries[i].speed == entries[i + 1].speed)
        {
            EXPECT_EQ(entries[i].visibleMean, entries[i + 1].visibleMean) << "speed " << entries[i].speed;
        }
    }
    EXPECT_EQ(identicalAcrossThreads(text, "frustum"), true) << text;
    EXPECT_EQ(identicalAcrossThreads(text, "osg"), std::nullopt) << text;
    EXPECT_NE(run.output.find("cull-only sweeps"), std::string::npos) << "the sweep table follows the main table";
}

TEST(BenchSweep, CullOnlyRendersNothing)
{
    const std::filesystem::path json = scratchJson();
    const AppRun run =
        runBench(std::string(TinyCity) + " --modes osg,frustum --speeds 16 --cull-only --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    EXPECT_EQ(run.output.find("oracle:"), std::string::npos) << "no oracle pass: " << run.output;
    EXPECT_TRUE(modeObject(text, "osg").empty()) << text;
    EXPECT_EQ(numberField(text, "views"), 0.0) << "nothing rendered: " << text;
    const std::vector<SweepEntry> entries = sweepEntries(text);
    ASSERT_EQ(entries.size(), 1u) << text;
    EXPECT_EQ(entries[0].speed, 16.0);
    EXPECT_EQ(entries[0].views, pacedFrames(cityWalkKeys(), 16));
}

TEST(BenchSweep, CubeMakesSixViewsPerKeyAndStaysConservative)
{
    const std::filesystem::path json = scratchJson();
    const AppRun run =
        runBench(std::string(TinyCity) + " --views 8 --modes osg,frustum,exact --cube --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    EXPECT_EQ(numberField(text, "views"), 48.0) << text;
    EXPECT_NE(text.find("\"size\": [128, 128]"), std::string::npos) << "cube faces are HxH: " << text;
    EXPECT_NE(text.find("\"cube\": true"), std::string::npos) << text;
    EXPECT_EQ(numberField(modeObject(text, "frustum"), "false_invisible"), 0.0) << text;
    EXPECT_EQ(numberField(modeObject(text, "exact"), "false_invisible"), 0.0) << text;
    EXPECT_NEAR(numberField(modeObject(text, "exact"), "overestimation").value_or(0), 1.0, 1e-9) << text;

    // --fov 360 is the same request.
    const AppRun synonym = runBench(std::string(TinyCity) + " --views 2 --modes frustum --fov 360");
    ASSERT_EQ(synonym.exitCode, 0) << synonym.output;
    EXPECT_NE(synonym.output.find("12 views at 128x128"), std::string::npos) << synonym.output;
}

TEST(BenchSweep, BadSweepArgumentsExitTwoWithAMessage)
{
    const struct
    {
        const char* arguments;
        const char* message;
    } cases[] = {
        {"--speeds 0", "--speeds must lie between 1 and"},
        {"--speeds 1,,2", "--speeds expects a non-negative integer"},
        {"--threads x", "--threads expects a non-negative integer, got 'x'"},
        {"--threads 0", "--threads must lie between 1 and"},
        {"--fov 90", "--fov accepts only 360"},
        {"--cull-only", "--cull-only needs a sweep"},
    };
    for (const auto& bad : cases)
    {
        const AppRun run = runBench(std::string(TinyCity) + " --modes frustum " + bad.arguments);
        EXPECT_EQ(run.exitCode, 2) << bad.arguments << ": " << run.output;
        EXPECT_NE(run.output.find(bad.message), std::string::npos) << bad.arguments << ": " << run.output;
        EXPECT_EQ(run.output.find("oracle:"), std::string::npos) << "no work before the check: " << run.output;
    }
}
