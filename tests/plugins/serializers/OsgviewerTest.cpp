// SPDX-License-Identifier: MIT
// Stock osgviewer (Debian's openscenegraph) opens data/osgvis-demo.osgt and culls with osgVis: from
// its home eye (on the bound's -Y side looking +Y, Z up; osgGA::CameraManipulator::computeHomePosition)
// the wall hides all ten boxes. ViewCuller reports extractions at INFO and each cull at DEBUG_INFO.
#include "AppProcess.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

namespace
{
TEST(Osgviewer, CullsTheDemoSceneBehindItsWall)
{
    if (!osgVis::test::haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/with-display.sh)";
    // note: single-threaded because OSG's notify stream is one for all threads: a line the cull thread
    // writes while the main thread writes another can come out mangled or lost.
    const osgVis::test::AppRun run = osgVis::test::runApp(
        "/usr/bin/env", "OSG_LIBRARY_PATH='" OSGVIS_BINARY_DIR "/lib' OSG_RUN_FRAME_COUNT=5 OSG_WINDOW='0 0 320 240' "
                        "OSG_THREADING=SingleThreaded OSG_NOTIFY_LEVEL=DEBUG_INFO '" OSGVIEWER_EXE
                        "' '" OSGVIS_SOURCE_DIR "/data/osgvis-demo.osgt'");
    ASSERT_EQ(run.exitCode, 0) << run.output;

    EXPECT_NE(run.output.find("osgVis: osgvis-demo: extracted 11 objects (132 triangles), modes frustum+octree"),
              std::string::npos)
        << run.output;

    const std::regex cullLine(R"(osgVis: osgvis-demo: frame (\d+): (\d+) of (\d+) objects visible)");
    std::istringstream lines(run.output);
    unsigned culls = 0;
    for (std::string line; std::getline(lines, line);)
    {
        std::smatch match;
        if (!std::regex_search(line, match, cullLine))
            continue;
        ++culls;
        EXPECT_EQ(match[3], "11") << line;
        // The wall alone: the ten boxes behind it are culled.
        EXPECT_EQ(match[2], "1") << line;
    }
    EXPECT_GE(culls, 5u);
}
} // namespace
