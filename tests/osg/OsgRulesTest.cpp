// SPDX-License-Identifier: MIT
// OSG decides what OSG decides (issue 54): what the cull traversal brings to a VisibilityGroup (the
// traversal mask, the state set above it, near and far computed by OSG) and what a node states below
// it (culling inactive, a Transform the kit does not know, the depth test off) is OSG's rule; the kit
// removes only what a wall this view draws, drawn as it is drawn, proves hidden. Bare cull visitors
// (TestView), no GL. Each test first shows that the wall hides the boxes behind it in every occlusion
// mode used here, so a pass is not a mode that occludes nothing.
//
//   eye at the origin looking down +x (z up), 40° square frustum from 0.5 to 1000.
//
//        ◉ ─────▶   ▌ wall x ∈ [10, 11], |y|, |z| ≤ 20      □ □ boxes at x = 25, y = 0 and y = 4
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/VisibilityGroup>

#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/Multisample>
#include <osg/PolygonMode>
#include <osg/Scissor>

#include <gtest/gtest.h>

#include <functional>
#include <string>

using osgVis::test::makeBox;
using osgVis::test::TestView;

namespace
{
using Drawn = std::set<const osg::Drawable*>;

const char* const OcclusionModes[] = {"octree", "mask", "cdt", "frustum+octree"};

struct WallScene
{
    osg::ref_ptr<osg::Group> root = new osg::Group; // above the group: state a camera would bring
    osg::ref_ptr<osgVis::VisibilityGroup> group;
    osg::ref_ptr<osg::Geode> wall = new osg::Geode;
    osg::ref_ptr<osg::Geometry> behind[2];

    explicit WallScene(const std::string& mode) : group(new osgVis::VisibilityGroup(mode))
    {
        wall->addDrawable(makeBox(osg::Vec3(10, -20, -20), osg::Vec3(11, 20, 20)));
        group->addChild(wall);
        for (int i = 0; i < 2; ++i)
        {
            const osg::Vec3 centre(25, 4.f * float(i), 0);
            behind[i] = makeBox(centre - osg::Vec3(1, 1, 1), centre + osg::Vec3(1, 1, 1));
            osg::ref_ptr<osg::Geode> geode = new osg::Geode;
            geode->addDrawable(behind[i]);
            group->addChild(geode);
        }
        root->addChild(group);
    }
    bool drawsBehind(const Drawn& drawn, int i) const { return drawn.count(behind[i].get()) != 0; }
};

// Frames drawn by a fresh view (several, so temporal modes settle), the last one's drawables.
Drawn settled(osg::Node& root, osgUtil::CullVisitor* cv = nullptr)
{
    TestView view(cv);
    Drawn drawn;
    for (int frame = 0; frame < 3; ++frame)
        drawn = view.draw(root);
    return drawn;
}

// The premise of every test below: with nothing of OSG's rules in play the wall hides both boxes.
void expectWallHides(const std::string& mode)
{
    WallScene scene(mode);
    const Drawn drawn = settled(*scene.root);
    EXPECT_FALSE(scene.drawsBehind(drawn, 0) || scene.drawsBehind(drawn, 1)) << mode << ": the wall hid nothing";
}

// An eye-following transform, as osghangglide's sky: its matrix is the cull visitor's eye point.
class FollowTheEye : public osg::Transform
{
public:
    bool computeLocalToWorldMatrix(osg::Matrix& matrix, osg::NodeVisitor* nv) const override
    {
        if (osgUtil::CullVisitor* cv = nv ? nv->asCullVisitor() : nullptr)
            matrix.preMultTranslate(cv->getEyeLocal());
        return true;
    }
    bool computeWorldToLocalMatrix(osg::Matrix& matrix, osg::NodeVisitor* nv) const override
    {
        if (osgUtil::CullVisitor* cv = nv ? nv->asCullVisitor() : nullptr)
            matrix.postMultTranslate(-cv->getEyeLocal());
        return true;
    }
};
} // namespace

TEST(OsgRules, TheWallHidesTheBoxesWhenNoRuleApplies)
{
    for (const char* mode : OcclusionModes)
        expectWallHides(mode);
}

namespace
{
// The wall under node mask `wallMask`, culled by a view whose traversal (cull) mask is 0x1.
Drawn drawnWithCullMaskOne(WallScene& scene, osg::Node::NodeMask wallMask)
{
    scene.wall->setNodeMask(wallMask);
    osg::ref_ptr<osgUtil::CullVisitor> cv = new osgUtil::CullVisitor;
    TestView view(cv.get());
    cv->setTraversalMask(0x1); // a camera's cull mask
    Drawn drawn;
    for (int frame = 0; frame < 3; ++frame)
        drawn = view.draw(*scene.root);
    return drawn;
}
} // namespace

TEST(OsgRules, AWallTheTraversalMaskLeavesOutHidesNothing)
{
    for (const char* mode : OcclusionModes)
    {
        WallScene scene(mode);
        const Drawn drawn = drawnWithCullMaskOne(scene, 0x2);
        EXPECT_FALSE(drawn.count(scene.wall->getDrawable(0))) << mode;
        EXPECT_TRUE(scene.drawsBehind(drawn, 0) && scene.drawsBehind(drawn, 1)) << mode;
        EXPECT_TRUE(scene.group->getLastStatistics().leftToOsg) << mode;
    }
}

TEST(OsgRules, ATraversalMaskThatDrawsTheWallKeepsItsOcclusion)
{
    for (const char* mode : OcclusionModes)
    {
        WallScene scene(mode);
        const Drawn drawn = drawnWithCullMaskOne(scene, 0x3);
        EXPECT_FALSE(scene.drawsBehind(drawn, 0) || scene.drawsBehind(drawn, 1)) << mode;
    }
}

TEST(OsgRules, StateAboveTheGroupThatLetsNothingOccludeHidesNothing)
{
    const auto wireFrame = [](osg::StateSet& ss) {
        ss.setAttribute(new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
    };
    const auto noDepthWrite = [](osg::StateSet& ss) { ss.setAttribute(new osg::Depth(osg::Depth::LESS, 0, 1, false)); };
    const auto noColour = [](osg::StateSet& ss) { ss.setAttribute(new osg::ColorMask(false, false, false, false)); };
    const auto coverage = [](osg::StateSet& ss) { ss.setMode(GL_SAMPLE_ALPHA_TO_COVERAGE_ARB, osg::StateAttribute::ON); };
    const auto scissor = [](osg::StateSet& ss) {
        ss.setAttributeAndModes(new osg::Scissor(0, 0, 128, 128), osg::StateAttribute::ON);
    };
    const auto depthTestOff = [](osg::StateSet& ss) { ss.setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF); };
    const std::pair<const char*, std::function<void(osg::StateSet&)>> states[] = {
        {"wire-frame", wireFrame},   {"no depth write", noDepthWrite}, {"colour mask", noColour},
        {"alpha to coverage", coverage}, {"scissor", scissor},          {"depth test off", depthTestOff}};
    for (const auto& [name, set] : states)
        for (const char* mode : OcclusionModes)
        {
            WallScene scene(mode);
            set(*scene.root->getOrCreateStateSet());
            const Drawn drawn = settled(*scene.root);
            EXPECT_TRUE(scene.drawsBehind(drawn, 0) && scene.drawsBehind(drawn, 1)) << name << ", " << mode;
        }
}

TEST(OsgRules, TheSameStateOnTheWallItselfStopsItOccluding)
{
    for (const char* mode : OcclusionModes)
    {
        WallScene scene(mode);
        scene.wall->getOrCreateStateSet()->setAttribute(new osg::ColorMask(false, false, false, false));
        const Drawn drawn = settled(*scene.root);
        EXPECT_TRUE(scene.drawsBehind(drawn, 0) && scene.drawsBehind(drawn, 1)) << mode;
        EXPECT_FALSE(scene.group->getLastStatistics().leftToOsg) << mode;
    }
}

TEST(OsgRules, AnObjectDrawnWithoutTheDepthTestIsNeverOccluded)
{
    for (const char* mode : OcclusionModes)
    {
        WallScene scene(mode);
        osg::StateSet* marker = scene.behind[0]->getOrCreateStateSet();
        marker->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        marker->setRenderBinDetails(10, "RenderBin");
        const Drawn drawn = settled(*scene.root);
        EXPECT_TRUE(scene.drawsBehind(drawn, 0)) << mode;
        EXPECT_FALSE(scene.drawsBehind(drawn, 1)) << mode << ": the other box stays hidden";
    }
    for (const char* mode : OcclusionModes)
    {
        WallScene scene(mode);
        scene.behind[0]->getOrCreateStateSet()->setAttribute(new osg::Depth(osg::Depth::ALWAYS));
        EXPECT_TRUE(scene.drawsBehind(settled(*scene.root), 0)) << mode << ", depth function ALWAYS";
    }
}

TEST(OsgRules, WithNearAndFarComputedByOsgNothingIsCulledOnTheFarPlane)
{
    for (const char* mode : {"frustum", "octree", "cdt", "frustum+octree", "mask"})
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(mode);
        osg::ref_ptr<osg::Geode> far = new osg::Geode;
        far->addDrawable(makeBox(osg::Vec3(1500, -5, -5), osg::Vec3(1510, 5, 5))); // beyond the projection's 1000
        group->addChild(far);
        osg::ref_ptr<osg::Geode> near = new osg::Geode;
        near->addDrawable(makeBox(osg::Vec3(20, 3, -1), osg::Vec3(22, 5, 1))); // beside the far one, not in front
        group->addChild(near);

        if (std::string(mode).rfind("frustum", 0) == 0)
        {
            osg::ref_ptr<osgUtil::CullVisitor> fixed = new osgUtil::CullVisitor;
            EXPECT_FALSE(settled(*group, fixed.get()).count(far->getDrawable(0)))
                << mode << ": with fixed planes the far plane clips it, and the kit culls it";
        }

        osg::ref_ptr<osgUtil::CullVisitor> computed = new osgUtil::CullVisitor;
        TestView view(computed.get());
        computed->setComputeNearFarMode(osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
        Drawn drawn;
        for (int frame = 0; frame < 3; ++frame)
            drawn = view.draw(*group);
        EXPECT_TRUE(drawn.count(far->getDrawable(0))) << mode;
        EXPECT_TRUE(drawn.count(near->getDrawable(0))) << mode;
    }
}

TEST(OsgRules, ACullingInactiveEyeFollowingTransformIsNeverCulled)
{
    for (const char* mode : {"frustum", "octree", "mask", "cdt", "frustum+octree"})
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(mode);
        osg::ref_ptr<FollowTheEye> sky = new FollowTheEye;
        sky->setCullingActive(false);
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        // 20 to 30 ahead of wherever the eye is; where the extraction (no eye) puts it, the eye at
        // x = 100 has it behind its back
        geode->addDrawable(makeBox(osg::Vec3(20, -5, -5), osg::Vec3(30, 5, 5)));
        sky->addChild(geode);
        group->addChild(sky);

        const osg::Vec3d eye(100, 0, 0);
        const osg::Matrixd view = osg::Matrixd::lookAt(eye, eye + osg::Vec3d(1, 0, 0), osg::Vec3d(0, 0, 1));
        TestView test;
        Drawn drawn;
        for (int frame = 0; frame < 3; ++frame)
            drawn = test.draw(*group, view);
        EXPECT_TRUE(drawn.count(geode->getDrawable(0))) << mode;
    }
}
