// SPDX-License-Identifier: MIT
// Per-view state: two views of one VisibilityGroup (two cull visitor identifiers, as two cameras or
// two eyes) keep separate visible sets. Uses bare cull visitors, no GL.
//
//   □ x=-10          □ x=+10        view A looks down -x, view B down +x, both from the origin
//        ◁ A  ◉  B ▷
#include "TestScenes.h"

#include <osgVis/ViewCuller>
#include <osgVis/VisibilityGroup>

#include <osg/Geode>

#include <gtest/gtest.h>

using osgVis::test::makeBox;

namespace
{
osg::Matrixd lookingAlongX(double direction)
{
    return osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(direction, 0, 0), osg::Vec3d(0, 0, 1));
}
} // namespace

TEST(ViewCuller, EachViewKeepsItsOwnVisibleSet)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");
    for (float x : {-10.f, 10.f})
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(makeBox(osg::Vec3(x - 1, -1, -1), osg::Vec3(x + 1, 1, 1)));
        group->addChild(geode);
    }
    const osg::Matrixd projection = osg::Matrixd::perspective(40.0, 1.0, 0.5, 100.0);

    osg::ref_ptr<osgUtil::CullVisitor> viewA = new osgUtil::CullVisitor;
    viewA->setIdentifier(new osgUtil::CullVisitor::Identifier);
    osg::ref_ptr<osgUtil::CullVisitor> viewB = new osgUtil::CullVisitor;
    viewB->setIdentifier(new osgUtil::CullVisitor::Identifier);

    osgVis::ViewCuller& culler = *group->getViewCuller();
    const auto a = culler.cull(*viewA, *group, lookingAlongX(-1), projection);
    const auto b = culler.cull(*viewB, *group, lookingAlongX(+1), projection);
    ASSERT_TRUE(a.visible && b.visible);
    EXPECT_EQ(a.scene, b.scene); // one extraction, shared
    EXPECT_NE(a.visible, b.visible);
    EXPECT_EQ(a.visible->ids(), (std::vector<osgVis::core::ObjectId>{0}));
    EXPECT_EQ(b.visible->ids(), (std::vector<osgVis::core::ObjectId>{1}));
    EXPECT_EQ(group->getLastStatistics().objects, 2u);
    EXPECT_EQ(group->getLastStatistics().visible, 1u);
    EXPECT_EQ(group->getLastStatistics().trianglesVisible, 12u);

    // A visitor sharing A's identifier (the Renderer's second SceneView) continues A's state.
    osg::ref_ptr<osgUtil::CullVisitor> viewA2 = new osgUtil::CullVisitor;
    viewA2->setIdentifier(viewA->getIdentifier());
    const auto a2 = culler.cull(*viewA2, *group, lookingAlongX(+1), projection);
    EXPECT_EQ(a2.visible, a.visible);
    EXPECT_EQ(b.visible->ids(), (std::vector<osgVis::core::ObjectId>{1}));

    // Changing the children re-extracts.
    osg::ref_ptr<osg::Geode> third = new osg::Geode;
    third->addDrawable(makeBox(osg::Vec3(20, -1, -1), osg::Vec3(22, 1, 1)));
    group->addChild(third);
    const auto afterAdd = culler.cull(*viewB, *group, lookingAlongX(+1), projection);
    EXPECT_NE(afterAdd.scene, a.scene);
    EXPECT_EQ(afterAdd.visible->ids(), (std::vector<osgVis::core::ObjectId>{1, 2}));
}
