// SPDX-License-Identifier: MIT
// Stock osgconv (Debian's openscenegraph) converts osgVis scenes between .osgt and .osgb keeping the
// osgVis classes: osgDB finds osgdb_serializers_osgvis on OSG_LIBRARY_PATH by the class names alone.
#include "SceneComparison.h"
#include "SerializerScenes.h"
#include "SerializerTestSupport.h"

#include "AppProcess.h"

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

namespace
{
namespace fs = std::filesystem;

osgVis::test::AppRun osgconv(const fs::path& from, const fs::path& to)
{
    return osgVis::test::runApp("/usr/bin/env", "OSG_LIBRARY_PATH='" OSGVIS_BINARY_DIR "/lib' '" OSGCONV_EXE "' '" +
                                                    from.string() + "' '" + to.string() + "'");
}

TEST(Osgconv, RoundTripKeepsTheOsgVisClasses)
{
    osgVis::test::useBuiltPlugins();
    const fs::path dir = osgVis::test::scratchDirectory("plugins", "serializers-osgconv");
    const osg::ref_ptr<osgVis::VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    ASSERT_TRUE(osgDB::writeNodeFile(*original, (dir / "scene.osgt").string()));

    const osgVis::test::AppRun toBinary = osgconv(dir / "scene.osgt", dir / "scene.osgb");
    ASSERT_EQ(toBinary.exitCode, 0) << toBinary.output;
    const osgVis::test::AppRun toAscii = osgconv(dir / "scene.osgb", dir / "back.osgt");
    ASSERT_EQ(toAscii.exitCode, 0) << toAscii.output;

    const std::string text = osgVis::test::readText(dir / "back.osgt");
    for (const char* expected : {"osgVis::VisibilityGroup {", "Modes \"frustum+octree\"", "Async TRUE",
                                 "osgVis::Occluder {", "Polygons 2 {", "osgVis::Cell {", "Bounds -4 -2 0 0 2 3",
                                 "osgVis::Portal {", "CellA \"left\"", "CellB \"right\""})
        EXPECT_NE(text.find(expected), std::string::npos) << "no " << expected << " in\n" << text;

    const osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile((dir / "back.osgt").string());
    ASSERT_NE(loaded, nullptr);
    osgVis::test::expectSameGraph(*original, *loaded);
}

// Without the plugin on its path osgconv cannot read the file: it names the class it lacks.
TEST(Osgconv, NamesTheClassWithoutThePlugin)
{
    const fs::path dir = osgVis::test::scratchDirectory("plugins", "serializers-osgconv-noplugin");
    osgVis::test::useBuiltPlugins();
    ASSERT_TRUE(osgDB::writeNodeFile(*osgVis::test::makeDemoScene(), (dir / "scene.osgt").string()));
    const osgVis::test::AppRun run = osgVis::test::runApp(
        "/usr/bin/env", "-u OSG_LIBRARY_PATH '" OSGCONV_EXE "' '" + (dir / "scene.osgt").string() + "' '" +
                            (dir / "scene.osgb").string() + "'");
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("Unsupported wrapper class osgVis::VisibilityGroup"), std::string::npos) << run.output;
}
} // namespace
