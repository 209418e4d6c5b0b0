// SPDX-License-Identifier: MIT
// The bench's progressive cell-portal table (Teller & Séquin's Table 2): present exactly when a
// cellportal mode runs, the stages in the paper's order, and each stage drawing no more than the
// stages it is nested in (cell-to-cell ⊇ cell-to-object ⊇ eye-to-object, cell-to-cell ⊇ eye-to-cell
// ⊇ eye-to-object; cell-to-object and eye-to-cell are not nested).
#include "AppProcess.h"
#include "BenchJson.h"
#include "ProgressiveJson.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace osgVis::test;

namespace
{
AppRun runBench(const std::string& arguments)
{
    return runApp(OSGVIS_BENCH_EXE, arguments);
}

std::filesystem::path scratchJson()
{
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    return scratchDirectory("bench", test->name()) / "bench.json";
}

constexpr double tolerance = 1e-12;

void expectNestedStages(const std::vector<ProgressiveStageRow>& rows, const std::string& output)
{
    ASSERT_EQ(rows.size(), 5u) << output;
    const char* const order[] = {"entire model", "cell-to-cell", "cell-to-object", "eye-to-cell", "eye-to-object"};
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        EXPECT_EQ(rows[i].stage, order[i]);
        EXPECT_GT(rows[i].drawnFraction, 0.0) << rows[i].stage;
        EXPECT_LE(rows[i].drawnFraction, 1.0 + tolerance) << rows[i].stage;
        EXPECT_GT(rows[i].objectsFraction, 0.0) << rows[i].stage;
        EXPECT_LE(rows[i].objectsFraction, 1.0 + tolerance) << rows[i].stage;
    }
    EXPECT_EQ(rows[0].drawnFraction, 1.0);
    EXPECT_EQ(rows[0].objectsFraction, 1.0);
    const auto& cellToCell = rows[1];
    const auto& cellToObject = rows[2];
    const auto& eyeToCell = rows[3];
    const auto& eyeToObject = rows[4];
    for (auto fraction : {&ProgressiveStageRow::drawnFraction, &ProgressiveStageRow::objectsFraction})
    {
        EXPECT_LE(cellToObject.*fraction, cellToCell.*fraction + tolerance);
        EXPECT_LE(eyeToObject.*fraction, cellToObject.*fraction + tolerance);
        EXPECT_LE(eyeToCell.*fraction, cellToCell.*fraction + tolerance);
        EXPECT_LE(eyeToObject.*fraction, eyeToCell.*fraction + tolerance);
    }
    // Walking through an office, the eye never sees all of it.
    EXPECT_LT(eyeToObject.drawnFraction, 1.0);
}
} // namespace

TEST(BenchProgressive, CullOnlyRunReportsTheNestedStages)
{
    const auto json = scratchJson();
    const AppRun run = runBench("--generate office --triangles 5000 --views 12 --cull-only --threads 1 "
                                "--modes cellportal --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    expectNestedStages(progressiveRows(readText(json)), run.output);
    EXPECT_NE(run.output.find("progressive cell-portal table"), std::string::npos) << run.output;
}

TEST(BenchProgressive, AbsentWithoutACellPortalMode)
{
    const auto json = scratchJson();
    const AppRun run = runBench("--generate office --triangles 5000 --views 4 --cull-only --threads 1 "
                                "--modes frustum --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    EXPECT_TRUE(hasKey(text, "progressive")) << text;
    EXPECT_TRUE(progressiveRows(text).empty()) << text;
    EXPECT_EQ(run.output.find("progressive cell-portal table"), std::string::npos) << run.output;
}

TEST(BenchProgressive, RenderedRunPrintsTheTableAfterTheModes)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/test.sh provides Xvfb)";
    const auto json = scratchJson();
    const AppRun run = runBench("--generate office --triangles 5000 --views 8 --size 160x128 "
                                "--modes frustum,cellportal --json '" + json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    expectNestedStages(progressiveRows(text), run.output);
    EXPECT_EQ(numberField(modeObject(text, "cellportal"), "false_invisible"), 0.0) << text;
    const std::size_t modeTable = run.output.find("false-invis");
    const std::size_t progressive = run.output.find("progressive cell-portal table");
    ASSERT_NE(progressive, std::string::npos) << run.output;
    EXPECT_LT(modeTable, progressive) << run.output;
}
