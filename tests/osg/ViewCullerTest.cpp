// SPDX-License-Identifier: MIT
// Per-view state: two views of one VisibilityGroup (two cull visitor identifiers, as two cameras or
// two eyes) keep separate visible sets. Uses bare cull visitors, no GL.
//
//   □ x=-10          □ x=+10        view A looks down -x, view B down +x, both from the origin
//        ◁ A  ◉  B ▷
#include "TestScenes.h"

#include <osgVis/ViewCuller>
#include <osgVis/VisibilityGroup>

#include <osg/FrameStamp>
#include <osg/Geode>
#include <osg/MatrixTransform>

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

// Do no harm: with back-off on, the view probes the renderer alone on one block of 8 frames in 8
// (those frames let every object through, flagged in the statistics) and culls with its chain on the
// others; off, it always culls. A probe follows the schedule whatever the frame times.
TEST(ViewCuller, BackOffProbesTheRendererAloneOnItsSchedule)
{
    for (const bool on : {true, false})
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");
        for (float x : {-10.f, 10.f})
        {
            osg::ref_ptr<osg::Geode> geode = new osg::Geode;
            geode->addDrawable(makeBox(osg::Vec3(x - 1, -1, -1), osg::Vec3(x + 1, 1, 1)));
            group->addChild(geode);
        }
        osgVis::core::BackOffOptions options;
        options.enabled = on;
        group->setBackOff(options);
        EXPECT_EQ(group->getBackOffOptions().enabled, on);
        osg::ref_ptr<osgUtil::CullVisitor> view = new osgUtil::CullVisitor;
        view->setIdentifier(new osgUtil::CullVisitor::Identifier);
        const osg::Matrixd projection = osg::Matrixd::perspective(40.0, 1.0, 0.5, 100.0);
        std::vector<unsigned> skipped;
        for (unsigned frame = 0; frame < 72; ++frame)
        {
            const auto result = group->getViewCuller()->cull(*view, *group, lookingAlongX(-1), projection);
            const osgVis::CullStatistics figures = group->getLastStatistics();
            EXPECT_EQ(figures.backOff, on);
            EXPECT_EQ(result.everything, figures.backedOff) << "a skipped frame tells the drawables not to look up";
            if (figures.backedOff)
            {
                skipped.push_back(frame);
                EXPECT_EQ(result.visible->count(), 2u) << "a skipped frame lets every object through";
            }
            else
                EXPECT_EQ(result.visible->ids(), (std::vector<osgVis::core::ObjectId>{0})) << frame;
        }
        const std::vector<unsigned> probe{56, 57, 58, 59, 60, 61, 62, 63}; // the 8th block of 8
        EXPECT_EQ(skipped, on ? probe : std::vector<unsigned>{});
    }
}

// An application may change the graph between two culls of one frame: a second camera culled after a
// first one's cull callback moved something, or two culls with one frame stamp. Each cull compares
// the watch, so the second sees the box moved into its view (it used to compare once per frame
// number and cull the box where it had been).
TEST(ViewCuller, AChangeBetweenTwoCullsOfOneFrameIsSeen)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");
    osg::ref_ptr<osg::MatrixTransform> mover = new osg::MatrixTransform;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(osg::Vec3(-11, -1, -1), osg::Vec3(-9, 1, 1))); // in A's view, behind B
    mover->addChild(geode);
    group->addChild(mover);
    const osg::Matrixd projection = osg::Matrixd::perspective(40.0, 1.0, 0.5, 100.0);

    osg::ref_ptr<osg::FrameStamp> frameStamp = new osg::FrameStamp;
    frameStamp->setFrameNumber(7);
    osg::ref_ptr<osgUtil::CullVisitor> viewA = new osgUtil::CullVisitor;
    osg::ref_ptr<osgUtil::CullVisitor> viewB = new osgUtil::CullVisitor;
    for (osgUtil::CullVisitor* view : {viewA.get(), viewB.get()})
    {
        view->setIdentifier(new osgUtil::CullVisitor::Identifier);
        view->setFrameStamp(frameStamp.get());
    }
    osgVis::ViewCuller& culler = *group->getViewCuller();
    EXPECT_EQ(culler.cull(*viewA, *group, lookingAlongX(-1), projection).visible->count(), 1u);
    EXPECT_EQ(culler.cull(*viewB, *group, lookingAlongX(+1), projection).visible->count(), 0u);

    mover->setMatrix(osg::Matrixd::translate(20, 0, 0)); // as A's cull callback would: now ahead of B
    EXPECT_EQ(culler.cull(*viewB, *group, lookingAlongX(+1), projection).visible->count(), 1u)
        << "the same frame's second cull must see the box moved into its view";
    EXPECT_EQ(culler.cull(*viewA, *group, lookingAlongX(-1), projection).visible->count(), 0u);
}
