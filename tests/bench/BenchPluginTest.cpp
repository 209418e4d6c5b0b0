// SPDX-License-Identifier: MIT
// osgvisbench with a plugin module (lib/osgvis-modules/osgvis_module_cfrustum.so) among its modes:
// its rows are there, it misses nothing, and every view's visible set (the per-view digest) is the
// built-in frustum module's, alone and in front of the octree; a broken plugin stops the run before
// any work with the plugin's file and reason; --help says plugins are modes.
#include "AppProcess.h"
#include "BenchJson.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace osgVis::test;

namespace
{
// The text of `"key": [ ... ]` inside mode `mode`'s per-view record.
std::string perViewArray(const std::string& json, const std::string& mode, const std::string& key)
{
    const std::size_t perView = json.find("\"per_view\": {");
    const std::size_t begin = perView == std::string::npos ? perView : json.find("\"" + mode + "\": {", perView);
    if (begin == std::string::npos)
        return {};
    const std::size_t at = json.find("\"" + key + "\": [", begin);
    return at == std::string::npos ? std::string() : json.substr(at, json.find(']', at) - at);
}
} // namespace

TEST(BenchPlugin, PluginModeAnswersWhatFrustumAnswers)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs a display (scripts/with-display.sh)";
    const std::filesystem::path json = scratchDirectory("bench", "plugin") / "plugin.json";
    const AppRun run = runApp(OSGVIS_BENCH_EXE, "--generate city --triangles 5000 --views 8 --size 160x128 "
                                                "--modes frustum,cfrustum,frustum+octree,cfrustum+octree --json '" +
                                                    json.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    for (const char* mode : {"frustum", "cfrustum", "frustum+octree", "cfrustum+octree"})
    {
        const std::string row = modeObject(text, mode);
        ASSERT_FALSE(row.empty()) << mode << " in " << text;
        EXPECT_EQ(numberField(row, "false_invisible"), 0.0) << row;
        EXPECT_LT(numberField(row, "drawn_fraction").value_or(1), 1.0) << row;
    }
    const std::string digests = perViewArray(text, "frustum", "view_digest");
    ASSERT_FALSE(digests.empty()) << text;
    EXPECT_EQ(perViewArray(text, "cfrustum", "view_digest"), digests);
    EXPECT_EQ(perViewArray(text, "cfrustum", "view_objects"), perViewArray(text, "frustum", "view_objects"));
    EXPECT_EQ(perViewArray(text, "cfrustum+octree", "view_digest"),
              perViewArray(text, "frustum+octree", "view_digest"));
}

TEST(BenchPlugin, BrokenPluginStopsTheRunWithItsFileAndReason)
{
    setenv("OSGVIS_MODULE_PATH", OSGVIS_BROKEN_MODULE_DIR, 1); // the bench inherits it
    const AppRun run =
        runApp(OSGVIS_BENCH_EXE, "--generate city --triangles 5000 --modes frustum,frustum+broken-refuses");
    unsetenv("OSGVIS_MODULE_PATH");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("mode 'broken-refuses': plugin " OSGVIS_BROKEN_MODULE_DIR
                              "/osgvis_module_broken-refuses.so: osgvis_module_entry returned no callback table"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("oracle:"), std::string::npos) << "no heavy work before the check: " << run.output;
}

TEST(BenchPlugin, HelpSaysPluginsAreModes)
{
    const AppRun run = runApp(OSGVIS_BENCH_EXE, "--help");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("loads the plugin osgvis_module_<name>.so from OSGVIS_MODULE_PATH"), std::string::npos)
        << run.output;
}
