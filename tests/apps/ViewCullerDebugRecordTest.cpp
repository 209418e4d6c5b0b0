// SPDX-License-Identifier: MIT
// osgVis::ViewCuller hands an attached core::DebugRecord to every stage of its views' chains, clears
// it before each query, and stops when it is detached. No GL: the culler runs on bare cull visitors.
#include "RecordingTestModule.h"

#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osg/ShapeDrawable>
#include <osgUtil/CullVisitor>

#include <gtest/gtest.h>

using namespace osgVis;

namespace
{
test::RecordedScene recordedScene()
{
    test::RecordedScene recorded;
    recorded.node = core::Aabb(core::Vec3(2, 2, 0), core::Vec3(8, 5, 1));
    recorded.occluder = {core::Vec3(2, -2, 0), core::Vec3(8, -2, 0), core::Vec3(8, -2, 3)};
    recorded.eyeCell = core::Aabb(core::Vec3(-1, -5, 0), core::Vec3(1, -3, 2));
    return recorded;
}

osg::ref_ptr<VisibilityGroup> groupWithOneBox(const std::string& modes)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(0, 0, 0), 1.0f)));
    osg::ref_ptr<VisibilityGroup> group = new VisibilityGroup;
    group->addChild(geode.get());
    group->setModes(modes);
    return group;
}

ViewCuller::Result cullOnce(VisibilityGroup& group, osgUtil::CullVisitor& view)
{
    const osg::Matrixd lookAtBox =
        osg::Matrixd::lookAt(osg::Vec3d(0, -10, 0), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1));
    const osg::Matrixd projection = osg::Matrixd::perspective(60.0, 1.0, 0.1, 100.0);
    return group.getViewCuller()->cull(view, group, lookAtBox, projection);
}
} // namespace

TEST(ViewCullerDebugRecord, EveryQueryOfAnAttachedRecordStartsClean)
{
    test::registerRecordingTestModule(recordedScene());
    osg::ref_ptr<VisibilityGroup> group = groupWithOneBox(std::string("frustum+") + test::RecordingTestModule::Name);
    osg::ref_ptr<osgUtil::CullVisitor> view = new osgUtil::CullVisitor;
    view->setIdentifier(new osgUtil::CullVisitor::Identifier);

    core::DebugRecord record;
    group->getViewCuller()->setDebugRecord(&record);
    for (int query = 0; query < 3; ++query)
    {
        const ViewCuller::Result result = cullOnce(*group, *view);
        ASSERT_NE(result.visible, nullptr);
        EXPECT_TRUE(result.visible->test(0)) << "the box is in view and the recorder culls nothing";
    }
    // The recorder appends without clearing: one node means the culler cleared before every query.
    const core::DebugRecord copy = group->getViewCuller()->getDebugRecord();
    ASSERT_EQ(copy.nodes.size(), 1u);
    EXPECT_EQ(copy.nodes[0].state, core::NodeState::Invisible);
    EXPECT_EQ(copy.nodes[0].bounds.min, core::Vec3(2, 2, 0));
    EXPECT_EQ(copy.nodes[0].bounds.max, core::Vec3(8, 5, 1));
    ASSERT_EQ(copy.activeOccluders.size(), 1u);
    EXPECT_EQ(copy.activeOccluders[0].size(), 3u);
    EXPECT_EQ(copy.eyeCell.min, core::Vec3(-1, -5, 0));
    EXPECT_EQ(record.nodes.size(), 1u) << "the attached record itself is the one written";
}

TEST(ViewCullerDebugRecord, DetachedRecordIsNoLongerWritten)
{
    test::registerRecordingTestModule(recordedScene());
    osg::ref_ptr<VisibilityGroup> group = groupWithOneBox(test::RecordingTestModule::Name);
    osg::ref_ptr<osgUtil::CullVisitor> view = new osgUtil::CullVisitor;
    view->setIdentifier(new osgUtil::CullVisitor::Identifier);

    core::DebugRecord record;
    group->getViewCuller()->setDebugRecord(&record);
    cullOnce(*group, *view);
    ASSERT_EQ(record.nodes.size(), 1u);

    group->getViewCuller()->setDebugRecord(nullptr);
    record.clear();
    cullOnce(*group, *view);
    EXPECT_TRUE(record.nodes.empty());
    EXPECT_TRUE(group->getViewCuller()->getDebugRecord().nodes.empty());
}

TEST(ViewCullerDebugRecord, ViewsCreatedAfterAttachingAlsoRecord)
{
    test::registerRecordingTestModule(recordedScene());
    osg::ref_ptr<VisibilityGroup> group = groupWithOneBox("frustum");
    core::DebugRecord record;
    group->getViewCuller()->setDebugRecord(&record);
    // A mode change rebuilds every view's chain; the new chains must get the record too.
    group->setModes(test::RecordingTestModule::Name);
    osg::ref_ptr<osgUtil::CullVisitor> view = new osgUtil::CullVisitor;
    view->setIdentifier(new osgUtil::CullVisitor::Identifier);
    cullOnce(*group, *view);
    EXPECT_EQ(record.nodes.size(), 1u);
    EXPECT_FALSE(record.eyeCell.empty());
}
