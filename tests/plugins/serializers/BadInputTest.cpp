// SPDX-License-Identifier: MIT
// Damaged files with osgVis nodes: the reader answers an error or warns and gives a sane node; it
// never crashes, never throws, and never trusts a count more than the data behind it.
#include "SerializerScenes.h"
#include "SerializerTestSupport.h"

#include <osgVis/Occluder>
#include <osgVis/VisibilityGroup>

#include <osg/NodeVisitor>

#include <gtest/gtest.h>

namespace
{
using osgVis::VisibilityGroup;
using osgVis::test::SerializerFormat;

const SerializerFormat ascii{"osgt", "Ascii"};
const SerializerFormat binary{"osgb", "Binary"};

class SerializerBadInput : public testing::Test
{
protected:
    void SetUp() override { osgVis::test::useBuiltPlugins(); }
};

std::string replaceOnce(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "no \"" << from << "\" in\n" << text;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

TEST_F(SerializerBadInput, UnknownModeWarnsAndCullsWithFrustum)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeDemoScene();
    const std::string text = replaceOnce(osgVis::test::writeToString(*original, ascii), "Modes \"frustum+octree\"",
                                         "Modes \"frustum+warpdrive\"");
    osgVis::test::CapturedWarnings warnings;
    const osg::ref_ptr<osg::Node> node = osgVis::test::readFromString(text, ascii);

    auto* loaded = dynamic_cast<VisibilityGroup*>(node.get());
    ASSERT_NE(loaded, nullptr);
    EXPECT_EQ(loaded->getModes(), "frustum");
    EXPECT_EQ(loaded->getNumChildren(), original->getNumChildren());
    EXPECT_NE(warnings.text().find("osgVis::VisibilityGroup \"osgvis-demo\""), std::string::npos) << warnings.text();
    EXPECT_NE(warnings.text().find("warpdrive"), std::string::npos) << warnings.text();
    EXPECT_NE(warnings.text().find("culling with \"frustum\""), std::string::npos) << warnings.text();
}

// The round-trip scene without its geometry: only osgVis nodes. note: OSG 3.6's own osg::Geometry
// wrapper crashes on some truncations (a null primitive set reaches Geometry::setPrimitiveSetList), so
// the truncation test keeps to what our wrappers read.
osg::ref_ptr<VisibilityGroup> osgVisNodesOnly()
{
    osg::ref_ptr<VisibilityGroup> scene = osgVis::test::makeRoundTripScene();
    struct RemoveDrawables : osg::NodeVisitor
    {
        RemoveDrawables() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::Group& group) override
        {
            for (unsigned i = group.getNumChildren(); i-- > 0;)
                if (group.getChild(i)->asDrawable())
                    group.removeChild(i);
            traverse(group);
        }
    } removeDrawables;
    scene->accept(removeDrawables);
    return scene;
}

// Every prefix of a binary file: an error or a node, and a node is one the truncation could leave.
TEST_F(SerializerBadInput, TruncatedBinaryNeverCrashes)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVisNodesOnly();
    ASSERT_EQ(original->getNumChildren(), 4u);
    const std::string data = osgVis::test::writeToString(*original, binary);
    ASSERT_GT(data.size(), 300u);
    ASSERT_NE(osgVis::test::readFromString(data, binary), nullptr);
    osgVis::test::CapturedWarnings quiet; // the reader's complaints are expected here
    unsigned errors = 0;
    for (std::size_t length = 0; length < data.size(); ++length)
    {
        const osg::ref_ptr<osg::Node> node = osgVis::test::readFromString(data.substr(0, length), binary);
        if (!node)
        {
            ++errors;
            continue;
        }
        const auto* group = dynamic_cast<const VisibilityGroup*>(node.get());
        ASSERT_NE(group, nullptr) << "prefix of " << length << " bytes";
        EXPECT_LE(group->getNumChildren(), original->getNumChildren()) << "prefix of " << length << " bytes";
    }
    EXPECT_GT(errors, 0u);
}

// "Polygons 9" with two behind it: the wrapper keeps the two, warns, and the rest of the file loads.
TEST_F(SerializerBadInput, PolygonCountLargerThanTheData)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    const std::string text =
        replaceOnce(osgVis::test::writeToString(*original, ascii), "Polygons 2 {", "Polygons 9 {");
    osgVis::test::CapturedWarnings warnings;
    const osg::ref_ptr<osg::Node> node = osgVis::test::readFromString(text, ascii);

    EXPECT_NE(warnings.text().find("osgVis::Occluder \"screen\": 2 polygons where the file promises 9"),
              std::string::npos)
        << warnings.text();
    auto* group = dynamic_cast<VisibilityGroup*>(node.get());
    ASSERT_NE(group, nullptr);
    ASSERT_EQ(group->getNumChildren(), original->getNumChildren());
    auto* occluder = dynamic_cast<osgVis::Occluder*>(group->getChild(0));
    ASSERT_NE(occluder, nullptr);
    EXPECT_EQ(occluder->getPolygons(), static_cast<osgVis::Occluder*>(original->getChild(0))->getPolygons());
    EXPECT_EQ(group->getChild(4)->getName(), "free-box");
}

// A vertex count of four billion: read until the data ends, no allocation of that size.
TEST_F(SerializerBadInput, HugeVertexCountIsNotTrusted)
{
    const osg::ref_ptr<VisibilityGroup> original = osgVis::test::makeRoundTripScene();
    const std::string text =
        replaceOnce(osgVis::test::writeToString(*original, ascii), "Polygon 4 {", "Polygon 4000000000 {");
    osgVis::test::CapturedWarnings warnings;
    const osg::ref_ptr<osg::Node> node = osgVis::test::readFromString(text, ascii);

    EXPECT_NE(warnings.text().find("osgVis::Occluder::Polygons"), std::string::npos) << warnings.text();
    if (!node)
        return;
    auto* group = dynamic_cast<VisibilityGroup*>(node.get());
    ASSERT_NE(group, nullptr);
    auto* occluder = dynamic_cast<osgVis::Occluder*>(group->getChild(0));
    ASSERT_NE(occluder, nullptr);
    EXPECT_TRUE(occluder->getPolygons().empty());
}
} // namespace
