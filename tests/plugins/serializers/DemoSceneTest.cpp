// SPDX-License-Identifier: MIT
// data/osgvis-demo.osgt, the scene the README opens in stock osgviewer, is makeDemoScene() as written by
// this plugin. Regenerate it with --gtest_also_run_disabled_tests --gtest_filter=DemoScene.DISABLED_*.
#include "SceneComparison.h"
#include "SerializerScenes.h"
#include "SerializerTestSupport.h"

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <filesystem>

namespace
{
const std::string demoFile = std::string(OSGVIS_SOURCE_DIR) + "/data/osgvis-demo.osgt";

TEST(DemoScene, DataFileIsTheGeneratedScene)
{
    osgVis::test::useBuiltPlugins();
    const osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile(demoFile);
    ASSERT_NE(loaded, nullptr) << demoFile;
    osgVis::test::expectSameGraph(*osgVis::test::makeDemoScene(), *loaded);
    EXPECT_LT(std::filesystem::file_size(demoFile), 100u * 1024u);
}

TEST(DemoScene, DISABLED_WriteDataFile)
{
    osgVis::test::useBuiltPlugins();
    ASSERT_TRUE(osgDB::writeNodeFile(*osgVis::test::makeDemoScene(), demoFile));
}
} // namespace
