// SPDX-License-Identifier: MIT
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
#include <algorithm>
#include <string>
#include <vector>

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

// The entries of the array after `"key": [` in `json` (numbers or quoted strings, as written).
std::vector<std::string> arrayField(const std::string& json, const std::string& key)
{
    std::vector<std::string> entries;
    const std::size_t at = json.find("\"" + key + "\": [");
    if (at == std::string::npos)
        return entries;
    const std::size_t begin = json.find('[', at) + 1, end = json.find(']', begin);
    std::string entry;
    for (std::size_t i = begin; i < end; ++i)
        if (json[i] == ',')
            entries.push_back(entry), entry.clear();
        else if (json[i] != ' ')
            entry += json[i];
    if (!entry.empty())
        entries.push_back(entry);
    return entries;
}

// The `per_view` record of one mode: five arrays of one entry per view that agree with the mode's row.
void expectPerViewRecord(const std::string& json, const std::string& mode, const std::string& row, double views,
                         double sceneTriangles)
{
    const std::size_t perView = json.find("\"per_view\": {");
    ASSERT_NE(perView, std::string::npos);
    const std::size_t begin = json.find("\"" + mode + "\": {", perView);
    ASSERT_NE(begin, std::string::npos) << mode;
    const std::string record = json.substr(begin, json.find('}', begin) - begin);
    const std::vector<std::string> triangles = arrayField(record, "view_triangles");
    const std::vector<std::string> missed = arrayField(record, "view_false_invisible");
    const std::vector<std::string> digests = arrayField(record, "view_digest");
    ASSERT_EQ(triangles.size(), std::size_t(views)) << record;
    ASSERT_EQ(arrayField(record, "view_objects").size(), std::size_t(views)) << record;
    ASSERT_EQ(arrayField(record, "view_cull_ms").size(), std::size_t(views)) << record;
    ASSERT_EQ(missed.size(), std::size_t(views)) << record;
    ASSERT_EQ(digests.size(), std::size_t(views)) << record;
    double drawn = 0.0, falseInvisible = 0.0;
    for (std::size_t v = 0; v < triangles.size(); ++v)
    {
        drawn += std::stod(triangles[v]);
        falseInvisible += std::stod(missed[v]);
        EXPECT_EQ(digests[v].size(), 18u) << "16 hex digits in quotes: " << digests[v];
    }
    EXPECT_NEAR(drawn / (views * sceneTriangles), numberField(row, "drawn_fraction").value_or(-1), 1e-9) << record;
    EXPECT_EQ(falseInvisible, numberField(row, "false_invisible").value_or(-1)) << record;
}

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

    const double sceneTriangles = numberField(text, "triangles").value_or(0);
    expectPerViewRecord(text, "osg", osg, 8.0, sceneTriangles);
    expectPerViewRecord(text, "frustum", frustum, 8.0, sceneTriangles);
    expectPerViewRecord(text, "exact", exact, 8.0, sceneTriangles);
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

// The JSON's mode rows with every timing field dropped: what must agree between two runs.
std::string timelessModes(const std::string& json)
{
    std::string kept;
    std::size_t begin = json.find("\"modes\"");
    const std::size_t end = json.find("\"per_view\"");
    for (std::size_t at = begin; at < end;)
    {
        const std::size_t line = json.find('\n', at);
        const std::string text = json.substr(at, line - at);
        if (text.find("_ms_") == std::string::npos && text.find("fps") == std::string::npos &&
            text.find("speedup") == std::string::npos)
            kept += text + "\n";
        at = line + 1;
    }
    return kept;
}

TEST(BenchApp, OracleCacheGivesTheSameSetsAndIgnoresDamagedFiles)
{
    const std::filesystem::path dir = scratchFile("").parent_path(); // made afresh once: each call wipes it
    const std::filesystem::path cache = dir / "oracle-cache";
    const std::string command = "--generate office --triangles 5000 --views 6 --size 160x128 --modes osg,frustum,"
                                "mask,exact --oracle-cache '" + cache.string() + "' --json ";
    const AppRun first = runBench(command + "'" + (dir / "first.json").string() + "'");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_EQ(first.output.find("from the cache"), std::string::npos) << first.output;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(cache))
        files.push_back(entry.path());
    ASSERT_EQ(files.size(), 1u) << "one file per scene, walk and size";

    const AppRun second = runBench(command + "'" + (dir / "second.json").string() + "'");
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_NE(second.output.find("6 views from the cache"), std::string::npos) << second.output;
    const std::string rows = timelessModes(readText((dir / "first.json")));
    ASSERT_NE(rows.find("false_invisible"), std::string::npos) << rows;
    EXPECT_EQ(timelessModes(readText((dir / "second.json"))), rows);

    // Another size is another key; a truncated file is rendered again, said, and replaced.
    const AppRun resized = runBench("--generate office --triangles 5000 --views 6 --size 128x128 --modes osg "
                                    "--oracle-cache '" + cache.string() + "'");
    ASSERT_EQ(resized.exitCode, 0) << resized.output;
    EXPECT_EQ(resized.output.find("from the cache"), std::string::npos) << resized.output;
    std::filesystem::resize_file(files.front(), std::filesystem::file_size(files.front()) / 2);
    const AppRun damaged = runBench(command + "'" + (dir / "third.json").string() + "'");
    ASSERT_EQ(damaged.exitCode, 0) << damaged.output;
    EXPECT_NE(damaged.output.find("ignoring the cached oracle"), std::string::npos) << damaged.output;
    EXPECT_EQ(timelessModes(readText((dir / "third.json"))), rows);
    const AppRun repaired = runBench(command + "'" + (dir / "fourth.json").string() + "'");
    EXPECT_NE(repaired.output.find("from the cache"), std::string::npos) << repaired.output;

    EXPECT_EQ(runBench("--generate office --dynamic --oracle-cache '" + cache.string() + "'").exitCode, 2);
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

namespace
{
// The rows of the JSON's "threading" array, one text per row.
std::vector<std::string> threadingRows(const std::string& json)
{
    std::vector<std::string> rows;
    const std::size_t start = json.find("\"threading\": [");
    const std::size_t end = json.find("]", start);
    if (start == std::string::npos || end == std::string::npos)
        return rows;
    for (std::size_t at = json.find("{\"mode\"", start); at != std::string::npos && at < end;)
    {
        const std::size_t next = json.find("{\"mode\"", at + 1);
        rows.push_back(json.substr(at, std::min(next, end) - at));
        at = next;
    }
    return rows;
}
} // namespace

TEST(BenchApp, ThreadingTableRunsEveryModelSyncAndAsyncConservatively)
{
    const std::filesystem::path json = scratchFile("threading.json");
    const AppRun run = runBench("--generate city --triangles 5000 --views 12 --size 160x128 --modes osg,frustum+octree"
                                " --threading SingleThreaded,CullDrawThreadPerContext,DrawThreadPerContext,"
                                "CullThreadPerCameraDrawThreadPerContext --async on,off --json '" +
                                json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("threading (osgVis ms"), std::string::npos) << run.output;
    const std::vector<std::string> rows = threadingRows(readText(json));
    ASSERT_EQ(rows.size(), 4u * 3u) << "osg (sync only) and frustum+octree sync and async, per model";
    std::size_t asyncRows = 0;
    for (const std::string& row : rows)
    {
        EXPECT_EQ(numberField(row, "false_invisible"), 0.0) << row;
        EXPECT_GT(numberField(row, "fps").value_or(0), 0.0) << row;
        if (row.find("\"async\": true") != std::string::npos)
        {
            ++asyncRows;
            EXPECT_TRUE(numberField(row, "fallback_frames").has_value()) << row;
        }
        else
        {
            EXPECT_EQ(numberField(row, "views_differing_from_main_pass"), 0.0) << row;
        }
        if (row.find("frustum+octree") != std::string::npos)
        {
            EXPECT_GE(numberField(row, "osgvis_ms_median").value_or(-1), 0.0) << row;
        }
    }
    EXPECT_EQ(asyncRows, 4u);
}

TEST(BenchApp, UnknownThreadingModelOrAsyncValueExitsTwo)
{
    const AppRun model = runBench("--generate city --modes osg --threading Fastest");
    EXPECT_EQ(model.exitCode, 2);
    EXPECT_NE(model.output.find("CullThreadPerCameraDrawThreadPerContext"), std::string::npos) << model.output;
    EXPECT_EQ(runBench("--generate city --modes osg --async maybe").exitCode, 2);
    EXPECT_EQ(runBench("--generate city --modes frustum --async on --cull-only --threads 1").exitCode, 2);
}
