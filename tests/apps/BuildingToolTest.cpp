// SPDX-License-Identifier: MIT
// The viewer's building tool (keys b and B): a box dropped ahead of the eye and the deletion of the
// building nearest the view centre reach the culling through dirtyScene, as a re-extraction with
// stable ids (Inserted / Removed), and the VisibilityGroup's visible set follows. No GL.
//
//   eye at (0, 0, 1.7) looking down +x; buildings (named "building") at x = 30 on the axis and at
//   (30, 12) beside it; ground (named "street") at z = 0.
#include "../../apps/osgvisviewer/BuildingTool.h"
#include "../osg/TestScenes.h"

#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osgUtil/CullVisitor>

#include <gtest/gtest.h>

using osgVis::core::ObjectId;
using osgVis::core::SceneChange;
using osgVis::test::makeBox;

namespace
{
const osg::Matrixd eyeView =
    osg::Matrixd::lookAt(osg::Vec3d(0, 0, 1.7), osg::Vec3d(1, 0, 1.7), osg::Vec3d(0, 0, 1));

struct Town
{
    osg::ref_ptr<osg::Group> model = new osg::Group;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> street = makeBox(osg::Vec3(-50, -50, -0.1f), osg::Vec3(50, 50, 0));
    osg::ref_ptr<osg::Geometry> ahead = makeBox(osg::Vec3(28, -2, 0), osg::Vec3(32, 2, 10));
    osg::ref_ptr<osg::Geometry> beside = makeBox(osg::Vec3(28, 10, 0), osg::Vec3(32, 14, 10));
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");

    Town()
    {
        street->setName("street");
        ahead->setName("building");
        beside->setName("building");
        for (osg::Geometry* g : {street.get(), ahead.get(), beside.get()})
            geode->addDrawable(g);
        model->addChild(geode);
        group->addChild(model);
    }

    osg::ref_ptr<const osgVis::ExtractedScene> cull()
    {
        osg::ref_ptr<osgUtil::CullVisitor> cv = new osgUtil::CullVisitor;
        cv->setIdentifier(identifier.get());
        const osg::Matrixd projection = osg::Matrixd::perspective(60.0, 1.0, 0.1, 500.0);
        visible = group->getViewCuller()->cull(*cv, *group, eyeView, projection).visible->ids();
        return group->getViewCuller()->getScene();
    }

    osg::ref_ptr<osgUtil::CullVisitor::Identifier> identifier = new osgUtil::CullVisitor::Identifier;
    std::vector<ObjectId> visible;
};
} // namespace

TEST(BuildingTool, DropsABoxAheadOfTheEyeOnTheGround)
{
    Town town;
    town.cull();
    int changes = 0;
    osgVis::viewer::BuildingTool tool(*town.model, [&] { ++changes; town.group->dirtyScene(); });
    EXPECT_EQ(changes, 0);
    osg::Node* dropped = tool.dropAhead(eyeView);
    ASSERT_NE(dropped, nullptr);
    EXPECT_EQ(changes, 1);
    EXPECT_EQ(dropped->getName(), "dropped building");

    const auto scene = town.cull();
    ASSERT_EQ(scene->scene.objects.size(), 4u);
    const osgVis::core::Aabb& box = scene->scene.objects[3].bounds;
    EXPECT_NEAR(box.min.x, 5.0, 1e-5); // near face 5 m ahead of the eye
    EXPECT_NEAR(box.max.x, 11.0, 1e-5);
    EXPECT_NEAR(box.min.y, -3.0, 1e-5);
    EXPECT_NEAR(box.max.y, 3.0, 1e-5);
    EXPECT_NEAR(box.min.z, -0.1, 1e-5); // the model's lowest point
    EXPECT_NEAR(box.max.z, 9.9, 1e-5);
    ASSERT_EQ(scene->changes.size(), 1u);
    EXPECT_EQ(scene->changes[0].kind, SceneChange::Kind::Inserted);
    EXPECT_EQ(scene->changes[0].objects, (std::vector<ObjectId>{3}));
    EXPECT_EQ(town.visible, (std::vector<ObjectId>{0, 1, 2, 3}));
}

TEST(BuildingTool, DeletesTheBuildingNearestTheViewCentre)
{
    Town town;
    town.cull();
    osgVis::viewer::BuildingTool tool(*town.model, [&] { town.group->dirtyScene(); });
    EXPECT_EQ(tool.removeNearestCentre(eyeView), "building");
    EXPECT_FALSE(town.geode->containsDrawable(town.ahead.get()));
    EXPECT_TRUE(town.geode->containsDrawable(town.beside.get()));

    const auto scene = town.cull();
    ASSERT_EQ(scene->changes.size(), 1u);
    EXPECT_EQ(scene->changes[0].kind, SceneChange::Kind::Removed);
    EXPECT_EQ(scene->changes[0].objects, (std::vector<ObjectId>{1}));
    EXPECT_EQ(town.visible, (std::vector<ObjectId>{0, 2}));

    // Next the one beside; never the street; then nothing is left to delete.
    EXPECT_EQ(tool.removeNearestCentre(eyeView), "building");
    EXPECT_FALSE(town.geode->containsDrawable(town.beside.get()));
    EXPECT_EQ(tool.removeNearestCentre(eyeView), "");
    EXPECT_TRUE(town.geode->containsDrawable(town.street.get()));
}

TEST(BuildingTool, ADroppedBuildingCanBeDeletedAndNothingBehindTheEyeIs)
{
    Town town;
    osgVis::viewer::BuildingTool tool(*town.model, {});
    const osg::Matrixd lookingBack =
        osg::Matrixd::lookAt(osg::Vec3d(0, 0, 1.7), osg::Vec3d(-1, 0, 1.7), osg::Vec3d(0, 0, 1));
    EXPECT_EQ(tool.removeNearestCentre(lookingBack), "");
    ASSERT_NE(tool.dropAhead(lookingBack), nullptr);
    EXPECT_EQ(tool.removeNearestCentre(lookingBack), "dropped building");
    EXPECT_EQ(tool.removeNearestCentre(lookingBack), "");
    EXPECT_EQ(town.geode->getNumDrawables(), 3u);
}
