// SPDX-License-Identifier: MIT
// Object enumeration: the same rule as the adapter's extraction (active children, node mask != 0,
// one object per drawable instance, depth-first, children in index order, path root..drawable).

#include "OracleTestScenes.h"

#include <osgVis/oracle/OracleObject.h>
#include <osgVis/oracle/RayCast.h>

#include <osg/MatrixTransform>
#include <osg/Switch>

#include <gtest/gtest.h>

using namespace oracletest;
using osgVis::oracle::enumerateObjects;

//  root
//  ├─ geodeA: a0, a1
//  ├─ switch: [off] hidden, [on] geodeB: b0
//  ├─ masked (mask 0): geodeC: c0
//  ├─ mtLeft  → geodeShared: s
//  └─ mtRight → geodeShared: s
TEST(OracleEnumeration, DepthFirstActiveInstances)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> geodeA = new osg::Geode;
    geodeA->addDrawable(makeBox({0, 0, 0}, {1, 1, 1}, "a0"));
    geodeA->addDrawable(makeBox({3, 0, 0}, {1, 1, 1}, "a1"));
    root->addChild(geodeA.get());
    osg::ref_ptr<osg::Switch> sw = new osg::Switch;
    sw->addChild(inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "hidden")), false);
    sw->addChild(inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "b0")), true);
    root->addChild(sw.get());
    osg::ref_ptr<osg::Group> masked = new osg::Group;
    masked->setNodeMask(0);
    masked->addChild(inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "c0")));
    root->addChild(masked.get());
    osg::ref_ptr<osg::Geode> geodeShared = inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "s"));
    osg::ref_ptr<osg::MatrixTransform> left = new osg::MatrixTransform(osg::Matrixd::translate(-5, 0, 0));
    osg::ref_ptr<osg::MatrixTransform> right = new osg::MatrixTransform(osg::Matrixd::translate(5, 0, 0));
    left->addChild(geodeShared.get());
    right->addChild(geodeShared.get());
    root->addChild(left.get());
    root->addChild(right.get());

    const auto objects = enumerateObjects(*root);
    ASSERT_EQ(objects.size(), 5u);
    const char* names[] = {"a0", "a1", "b0", "s", "s"};
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
        EXPECT_EQ(objects[i].drawable->getName(), names[i]);
        ASSERT_FALSE(objects[i].path.empty());
        EXPECT_EQ(objects[i].path.front(), root.get());
        EXPECT_EQ(objects[i].path.back(), objects[i].drawable.get());
        EXPECT_FALSE(objects[i].transparent);
    }
    EXPECT_EQ(objects[0].path, (osg::NodePath{root.get(), geodeA.get(), geodeA->getDrawable(0)}));
    EXPECT_EQ(objects[3].path, (osg::NodePath{root.get(), left.get(), geodeShared.get(), geodeShared->getDrawable(0)}));
    EXPECT_EQ(objects[4].path, (osg::NodePath{root.get(), right.get(), geodeShared.get(), geodeShared->getDrawable(0)}));
    EXPECT_EQ(objects[3].drawable, objects[4].drawable);
    EXPECT_EQ(objects[3].world.getTrans(), osg::Vec3d(-5, 0, 0));
    EXPECT_EQ(objects[4].world.getTrans(), osg::Vec3d(5, 0, 0));
}

TEST(OracleEnumeration, TransparencyFollowsOverrideAndProtected)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Group> blended = new osg::Group;
    blended->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::ON);
    osg::ref_ptr<osg::Geode> plain = inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "blended"));
    osg::ref_ptr<osg::Geode> turnedOff = inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "blend-off"));
    turnedOff->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::OFF);
    blended->addChild(plain.get());
    blended->addChild(turnedOff.get());
    root->addChild(blended.get());

    osg::ref_ptr<osg::Group> forcedOff = new osg::Group;
    forcedOff->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    osg::ref_ptr<osg::Geode> overridden = inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "overridden"));
    overridden->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::ON);
    osg::ref_ptr<osg::Geode> isProtected = inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "protected"));
    isProtected->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    forcedOff->addChild(overridden.get());
    forcedOff->addChild(isProtected.get());
    root->addChild(forcedOff.get());

    osg::ref_ptr<osg::Geode> hinted = inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "hinted"));
    hinted->getOrCreateStateSet()->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    root->addChild(hinted.get());

    const auto objects = enumerateObjects(*root);
    ASSERT_EQ(objects.size(), 5u);
    EXPECT_TRUE(objects[0].transparent);  // blended
    EXPECT_FALSE(objects[1].transparent); // blend-off
    EXPECT_FALSE(objects[2].transparent); // overridden
    EXPECT_TRUE(objects[3].transparent);  // protected
    EXPECT_TRUE(objects[4].transparent);  // hinted
}

// The ray caster alone, no GL: a box behind a box, seen and hidden.
TEST(OracleRayCast, NearestOpaqueHitWins)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(inGeode(makeBox({0, 0, 0}, {2, 2, 2}, "front")));
    root->addChild(inGeode(makeBox({0, 0, -8}, {1, 1, 1}, "hidden")));
    root->addChild(inGeode(makeBox({6, 0, -8}, {1, 1, 1}, "beside")));
    const Camera camera = lookDownZ(20, 40, 1, 100);
    const auto objects = enumerateObjects(*root);
    const auto visible = osgVis::oracle::rayCastVisible(root.get(), {}, camera.view, camera.projection, 64, 64);
    EXPECT_EQ(visible, (std::vector<std::uint32_t>{0, 2}));
    EXPECT_EQ(osgVis::oracle::RayCaster(objects).triangleCount(), 36u);
    // A 2×2 subgrid per pixel sees the same here.
    EXPECT_EQ(osgVis::oracle::rayCastVisible(root.get(), objects, camera.view, camera.projection, 64, 64, 2), visible);
}
