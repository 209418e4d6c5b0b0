// SPDX-License-Identifier: MIT
// osgVis nodes written by osgDB in each serializer format and read back: every property, class, name
// and child the same, and the loaded graph extracts to the same occluders, cells and portals.
#include "SceneComparison.h"
#include "SerializerScenes.h"
#include "SerializerTestSupport.h"

#include "AppProcess.h"

#include <osgVis/Occluder>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/api/ModuleSettings.h>

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgUtil/CullVisitor>

#include <gtest/gtest.h>

namespace
{
using osgVis::VisibilityGroup;
using osgVis::test::SerializerFormat;

class SerializerRoundTrip : public testing::TestWithParam<SerializerFormat>
{
protected:
    void SetUp() override { osgVis::test::useBuiltPlugins(); }
};

osg::ref_ptr<VisibilityGroup> asGroup(const osg::ref_ptr<osg::Node>& node)
{
    return dynamic_cast<VisibilityGroup*>(node.get());
}

// The extraction the group's culler makes at its first cull (with the group's extraction options).
osg::ref_ptr<const osgVis::ExtractedScene> cullOnce(VisibilityGroup& group)
{
    osg::ref_ptr<osgUtil::CullVisitor> cv = new osgUtil::CullVisitor;
    const osg::Matrixd eye = osg::Matrixd::lookAt(osg::Vec3d(0, -20, 1), osg::Vec3d(0, 0, 1), osg::Vec3d(0, 0, 1));
    return group.getViewCuller()->cull(*cv, group, eye, osg::Matrixd::perspective(60, 1, 0.1, 100)).scene;
}

TEST_P(SerializerRoundTrip, FileKeepsEveryProperty)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    const std::string file =
        (osgVis::test::scratchDirectory("plugins", "serializers-" + GetParam().extension) / ("scene." + GetParam().extension))
            .string();
    ASSERT_TRUE(osgDB::writeNodeFile(*original, file));

    const osg::ref_ptr<VisibilityGroup> loaded = asGroup(osgDB::readRefNodeFile(file));
    ASSERT_NE(loaded, nullptr);
    EXPECT_EQ(loaded->getModes(), "frustum+octree");
    EXPECT_TRUE(loaded->getAsync());
    osgVis::test::expectSameGraph(*original, *loaded);
}

TEST_P(SerializerRoundTrip, StreamKeepsEveryProperty)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    const osg::ref_ptr<VisibilityGroup> loaded =
        asGroup(osgVis::test::readFromString(osgVis::test::writeToString(*original, GetParam()), GetParam()));
    ASSERT_NE(loaded, nullptr);
    osgVis::test::expectSameGraph(*original, *loaded);

    const auto& occluder = dynamic_cast<const osgVis::Occluder&>(*loaded->getChild(0));
    ASSERT_EQ(occluder.getNumPolygons(), 2u);
    EXPECT_EQ(occluder.getPolygon(1), (osgVis::Occluder::Polygon{{2, 6, 0}, {3.5, 6, 0}, {2.75, 6, 1.125}}));
}

TEST_P(SerializerRoundTrip, AsyncAndExtractionOptionsSurvive)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    const osg::ref_ptr<VisibilityGroup> loaded =
        asGroup(osgVis::test::readFromString(osgVis::test::writeToString(*original, GetParam()), GetParam()));
    ASSERT_NE(loaded, nullptr);
    const osgVis::core::AsyncOptions async = loaded->getAsyncOptions();
    EXPECT_EQ(async.lookAheadFrames, 7u);
    EXPECT_EQ(async.slack, 0.25);
    EXPECT_FALSE(loaded->getExtractionOptions().keepTriangles);
}

// Typed module settings travel in the Modes text and come back as the same settings.
TEST_P(SerializerRoundTrip, ModuleSettingsSurvive)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    osgVis::core::ChainSettings chain = osgVis::core::parseChainSettings("frustum+octree-paper+mask-approx");
    std::get<osgVis::core::OctreeOptions>(chain[1].options).occluders = 64;
    std::get<osgVis::core::MaskOptions>(chain[2].options).shrinkPixels = 2.5;
    original->setChain(chain);
    EXPECT_EQ(original->getModes(), "frustum+octree-paper:occluders=64+mask-approx:shrinkPixels=2.5");

    const osg::ref_ptr<VisibilityGroup> loaded =
        asGroup(osgVis::test::readFromString(osgVis::test::writeToString(*original, GetParam()), GetParam()));
    ASSERT_NE(loaded, nullptr);
    EXPECT_EQ(loaded->getModes(), original->getModes());
    const osgVis::core::ChainSettings read = loaded->getChain();
    ASSERT_EQ(read.size(), 3u);
    EXPECT_EQ(std::get<osgVis::core::OctreeOptions>(read[1].options).occluders, 64u);
    EXPECT_FALSE(std::get<osgVis::core::OctreeOptions>(read[1].options).fuseDisjoint);
    EXPECT_EQ(std::get<osgVis::core::MaskOptions>(read[2].options).shrinkPixels, 2.5);
}

INSTANTIATE_TEST_SUITE_P(Formats, SerializerRoundTrip,
                         testing::Values(SerializerFormat{"osgt", "Ascii"}, SerializerFormat{"osgb", "Binary"},
                                         SerializerFormat{"osgx", "XML"}),
                         [](const testing::TestParamInfo<SerializerFormat>& info) { return info.param.extension; });

// The options are read whether or not the group can report them: a file saying KeepTriangles FALSE
// gives a group whose extraction keeps no triangles.
TEST(SerializerRead, AppliesAsyncAndKeepTrianglesFromAscii)
{
    osgVis::test::useBuiltPlugins();
    osg::ref_ptr<VisibilityGroup> plain = new VisibilityGroup("frustum+octree");
    plain->setName("plain");
    plain->addChild(osgVis::test::makeDemoScene()->getChild(1));
    const SerializerFormat ascii{"osgt", "Ascii"};
    std::string text = osgVis::test::writeToString(*plain, ascii);

    const std::string modesLine = "Modes \"frustum+octree\"";
    const std::size_t at = text.find(modesLine);
    ASSERT_NE(at, std::string::npos) << text;
    text.insert(at + modesLine.size(), "\nAsync TRUE\nAsyncLookAheadFrames 3\nAsyncSlack 0.5\nKeepTriangles FALSE");
    // Async TRUE as the file has it replaces the plain group's own "Async FALSE" line, read next.
    const std::size_t plainAsync = text.find("Async FALSE");
    ASSERT_NE(plainAsync, std::string::npos) << text;
    text.erase(plainAsync, std::string("Async FALSE").size());

    const osg::ref_ptr<VisibilityGroup> loaded = asGroup(osgVis::test::readFromString(text, ascii));
    ASSERT_NE(loaded, nullptr) << text;
    EXPECT_TRUE(loaded->getAsync());
    const osg::ref_ptr<const osgVis::ExtractedScene> scene = cullOnce(*loaded);
    ASSERT_EQ(scene->scene.objects.size(), 1u);
    EXPECT_EQ(scene->scene.objects[0].triangleCount, 12u);
    EXPECT_TRUE(scene->scene.triangles.empty());
    // The same group as written keeps its triangles: the file made the difference.
    EXPECT_EQ(cullOnce(*asGroup(osgVis::test::readFromString(osgVis::test::writeToString(*plain, ascii), ascii)))
                  ->scene.triangles.size(),
              12u);
}
} // namespace
