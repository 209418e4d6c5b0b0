// SPDX-License-Identifier: MIT
// osgvisviewer refuses bad input with a message that names the problem and a non-zero exit code,
// before it opens any window (so these tests need no display).
#include "BadModelFiles.h"
#include "ViewerProcess.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/scene/Walk.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

using osgVis::test::runViewer;
using osgVis::test::scratchDirectory;

TEST(ViewerErrors, UnknownModeListsTheModes)
{
    const auto run = runViewer("--generate office --triangles 2000 --mode no-such-culler");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find("no-such-culler"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("osg"), std::string::npos) << run.output;
    for (const std::string& module : osgVis::core::moduleNames())
        EXPECT_NE(run.output.find(module), std::string::npos) << "mode list lacks " << module << ":\n" << run.output;
}

// A plugin that is found but unusable is named with its reason, not reported as an unknown mode.
TEST(ViewerErrors, BrokenPluginModeNamesTheFileAndReason)
{
    setenv("OSGVIS_MODULE_PATH", OSGVIS_BROKEN_MODULE_DIR, 1); // the viewer inherits it
    const auto run = runViewer("--generate office --triangles 2000 --mode frustum+broken-nocull");
    unsetenv("OSGVIS_MODULE_PATH");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_LT(run.exitCode, 128) << "must not crash: " << run.output;
    EXPECT_NE(run.output.find("mode 'broken-nocull': plugin " OSGVIS_BROKEN_MODULE_DIR
                              "/osgvis_module_broken-nocull.so: the callback table has no cull"),
              std::string::npos)
        << run.output;
}

TEST(ViewerErrors, MissingModelIsNamed)
{
    const std::string dir = scratchDirectory("missing-model");
    const std::string model = dir + "/not-there.osgt";
    const auto run = runViewer("\"" + model + "\" --mode osg --headless \"" + dir + "/out\"");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find(model), std::string::npos) << run.output;
}

TEST(ViewerErrors, MalformedWalkReportsTheParsersLine)
{
    const std::string dir = scratchDirectory("malformed-walk");
    osgVis::core::Walk walk;
    osgVis::core::WalkKey key;
    key.eye = osgVis::core::Vec3(0.0, -10.0, 2.0);
    walk.keys.push_back(key);
    std::ostringstream text;
    walk.write(text);
    const std::string valid = text.str();
    const auto lines = std::count(valid.begin(), valid.end(), '\n');

    const std::string path = dir + "/bad.walk";
    std::ofstream(path) << valid << "view 1 2 3\n"; // a view needs ten values
    const auto run = runViewer("--generate office --triangles 2000 --mode osg --walk \"" + path + "\" --headless \"" +
                               dir + "/out\"");
    EXPECT_NE(run.exitCode, 0);
    const std::string expected = path + ":" + std::to_string(lines + 1) + ":";
    EXPECT_NE(run.output.find(expected), std::string::npos) << "expected '" << expected << "' in:\n" << run.output;
}

TEST(ViewerErrors, UnwritableOutputFolderFails)
{
    const std::string dir = scratchDirectory("unwritable-out");
    const std::string blocker = dir + "/a-file";
    std::ofstream(blocker) << "not a folder\n";
    const auto run = runViewer("--generate office --triangles 2000 --mode osg --headless \"" + blocker + "/out\"");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find(blocker), std::string::npos) << run.output;
}

TEST(ViewerErrors, UnusableModelsAreRefused)
{
    const std::string dir = scratchDirectory("unusable-models");
    const auto empty =
        runViewer("\"" + osgVis::test::writeEmptyModel(dir).string() + "\" --headless \"" + dir + "/out\"");
    EXPECT_EQ(empty.exitCode, 1) << empty.output;
    EXPECT_NE(empty.output.find("has no drawables"), std::string::npos) << empty.output;

    const auto garbage =
        runViewer("\"" + osgVis::test::writeGarbageModel(dir).string() + "\" --headless \"" + dir + "/out\"");
    EXPECT_EQ(garbage.exitCode, 1) << garbage.output;
    EXPECT_NE(garbage.output.find("cannot read scene"), std::string::npos) << garbage.output;
}

TEST(ViewerErrors, UnknownThreadingModelOrAsyncValueIsRefused)
{
    const auto model = runViewer("--generate office --triangles 2000 --threading Fastest");
    EXPECT_NE(model.exitCode, 0);
    EXPECT_NE(model.output.find("DrawThreadPerContext"), std::string::npos) << model.output;
    const auto async = runViewer("--generate office --triangles 2000 --async maybe");
    EXPECT_NE(async.exitCode, 0);
    EXPECT_NE(async.output.find("--async"), std::string::npos) << async.output;
}
