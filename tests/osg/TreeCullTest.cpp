// SPDX-License-Identifier: MIT
// The visible set lands on the graph where the cull traversal stands (issue 46): below plain groups,
// geodes and transforms, VisibilityGroup and osgVis::CullVisitor skip hidden subtrees and drawables
// themselves, with no callback on those drawables, and the render graph holds exactly the visible
// ones, each with its own model-view matrix; below a Switch the callbacks still decide.
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <osg/FrameStamp>
#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/Switch>
#include <osgUtil/RenderStage>
#include <osgUtil/SceneView>

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace
{
using osgVis::test::makeBox;

osg::ref_ptr<osg::Geode> boxAt(float x, float y, const std::string& name)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> box = makeBox(osg::Vec3(x - 1, y - 1, -1), osg::Vec3(x + 1, y + 1, 1));
    box->setName(name);
    geode->addDrawable(box);
    return geode;
}

// The eye at the origin looks along +x: boxes at x > 0 are in view, those at x < 0 behind it.
// front / back: plain groups three deep; mixed: a group with a transform holding one box in view and
// one behind; switched: a Switch with one box in view and one behind.
osg::ref_ptr<osg::Group> content()
{
    osg::ref_ptr<osg::Group> content = new osg::Group;
    osg::ref_ptr<osg::Group> front = new osg::Group, back = new osg::Group;
    osg::ref_ptr<osg::Group> frontInner = new osg::Group, backInner = new osg::Group;
    frontInner->addChild(boxAt(20, 0, "front"));
    backInner->addChild(boxAt(-20, 0, "back"));
    front->addChild(frontInner);
    back->addChild(backInner);
    osg::ref_ptr<osg::Group> mixed = new osg::Group;
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrixd::translate(0, 5, 0));
    moved->addChild(boxAt(30, 0, "moved in view"));
    moved->addChild(boxAt(-30, 0, "moved behind"));
    mixed->addChild(moved);
    mixed->addChild(back); // a second path to the hidden group
    osg::ref_ptr<osg::Switch> switched = new osg::Switch;
    switched->addChild(boxAt(25, -5, "switched in view"));
    switched->addChild(boxAt(-25, -5, "switched behind"));
    content->addChild(front);
    content->addChild(back);
    content->addChild(mixed);
    content->addChild(switched);
    return content;
}

void collect(const osgUtil::RenderBin& bin, std::multimap<std::string, osg::Matrixd>& out)
{
    for (const osgUtil::StateGraph* graph : bin.getStateGraphList())
        for (const osg::ref_ptr<osgUtil::RenderLeaf>& leaf : graph->_leaves)
            out.emplace(leaf->getDrawable()->getName(), *leaf->_modelview);
    for (const auto& nested : bin.getRenderBinList())
        collect(*nested.second, out);
}

// The drawables one cull put in the render graph, by name, with their model-view matrices. OSG's
// own culling is off unless `osgCulls`: what is left out, osgVis left out.
std::multimap<std::string, osg::Matrixd> cullOnce(osg::Node* root, osgUtil::CullVisitor* visitor, bool osgCulls = false)
{
    osg::ref_ptr<osgUtil::SceneView> sceneView = new osgUtil::SceneView;
    sceneView->setDefaults();
    for (osg::CullSettings* settings : {static_cast<osg::CullSettings*>(sceneView.get()),
                                        static_cast<osg::CullSettings*>(sceneView->getCamera())})
    {
        settings->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        if (!osgCulls)
            settings->setCullingMode(osg::CullSettings::NO_CULLING);
    }
    if (visitor)
        sceneView->setCullVisitor(visitor);
    sceneView->setSceneData(root);
    sceneView->setViewport(0, 0, 640, 480);
    sceneView->setProjectionMatrixAsPerspective(60.0, 640.0 / 480.0, 0.5, 1000.0);
    sceneView->setViewMatrixAsLookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(1, 0, 0), osg::Z_AXIS);
    osg::ref_ptr<osg::FrameStamp> frameStamp = new osg::FrameStamp;
    sceneView->setFrameStamp(frameStamp.get());
    sceneView->cull();
    std::multimap<std::string, osg::Matrixd> drawn;
    collect(*sceneView->getRenderStage(), drawn);
    return drawn;
}

std::set<std::string> names(const std::multimap<std::string, osg::Matrixd>& drawn)
{
    std::set<std::string> out;
    for (const auto& entry : drawn)
        out.insert(entry.first);
    return out;
}

struct CallbackCount : osg::NodeVisitor
{
    CallbackCount() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    std::set<std::string> withCallback;
    void apply(osg::Drawable& drawable) override
    {
        if (drawable.getCullCallback())
            withCallback.insert(drawable.getName());
    }
};

const std::set<std::string> InView = {"front", "moved in view", "switched in view"};
} // namespace

TEST(TreeCull, VisibilityGroupDrawsExactlyTheVisibleDrawablesWithoutCallbacksOnPlainPaths)
{
    osg::ref_ptr<osg::Group> plain = new osg::Group;
    plain->addChild(content());
    const auto reference = cullOnce(plain.get(), nullptr, true);
    ASSERT_EQ(names(reference), InView) << "OSG's own frustum culling should keep exactly these";
    ASSERT_EQ(cullOnce(plain.get(), nullptr).size(), 7u) << "without it, everything is drawn";

    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");
    group->addChild(plain->getChild(0));
    const auto drawn = cullOnce(group.get(), nullptr);
    EXPECT_EQ(drawn, reference) << "the same drawables with the same model-view matrices";
    EXPECT_EQ(group->getLastStatistics().visible, 3u);

    // Only the drawables below the Switch, which the walk does not enter, carry a callback.
    CallbackCount callbacks;
    group->accept(callbacks);
    EXPECT_EQ(callbacks.withCallback, (std::set<std::string>{"switched in view", "switched behind"}));
}

TEST(TreeCull, CullVisitorDrawsExactlyTheVisibleDrawablesWithoutCallbacks)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(content());
    const auto reference = cullOnce(root.get(), nullptr, true);
    osg::ref_ptr<osgVis::CullVisitor> visitor = new osgVis::CullVisitor("frustum");
    const auto drawn = cullOnce(root.get(), visitor.get());
    EXPECT_EQ(drawn, reference);
    EXPECT_EQ(visitor->getLastStatistics().visible, 3u);
    CallbackCount callbacks;
    root->accept(callbacks);
    EXPECT_TRUE(callbacks.withCallback.empty());
}

// Baked data set on the group (as the .pvs plugin does) reach every view's chain: view cells whose
// PVS holds the front box alone leave every other box out, where cells computed on the spot keep
// the three in view (and, a volume method without the frustum stage, more).
TEST(TreeCull, BakedDataSetOnTheGroupReachTheViewsChain)
{
    osg::ref_ptr<osg::Group> model = content();
    const osg::ref_ptr<osgVis::ExtractedScene> extracted = osgVis::extractScene(*model);
    auto cells = std::make_shared<osgVis::core::BakedViewCells>();
    cells->fingerprint = osgVis::core::sceneFingerprint(extracted->scene);
    cells->objectCount = std::uint32_t(extracted->scene.objects.size());
    cells->nearDistance = 1.0; // a bake reaching 1 serves views with a near plane from 1/8 (docs/multifocal.md)
    cells->cells.totalCells = 1;
    cells->cells.cellIndices = {0};
    cells->cells.cells = {osgVis::core::Aabb(osgVis::core::Vec3(-1.0), osgVis::core::Vec3(1.0))};
    osgVis::core::VisibleSet pvs(extracted->scene.objects.size());
    for (osgVis::core::ObjectId id = 0; id < extracted->refs.size(); ++id)
        if (extracted->refs[id].node()->getName() == "front")
            pvs.set(id);
    ASSERT_EQ(pvs.count(), 1u);
    cells->cells.pvs = {pvs};

    osg::ref_ptr<osgVis::VisibilityGroup> computed = new osgVis::VisibilityGroup("multifocal");
    computed->addChild(model);
    const std::set<std::string> kept = names(cullOnce(computed.get(), nullptr));
    for (const std::string& name : InView)
        EXPECT_EQ(kept.count(name), 1u) << name;

    osg::ref_ptr<osgVis::VisibilityGroup> baked = new osgVis::VisibilityGroup("multifocal");
    auto data = std::make_shared<osgVis::core::BakedData>();
    data->set<osgVis::core::BakedViewCells>(cells);
    baked->setBakedData(data);
    baked->addChild(model);
    EXPECT_EQ(names(cullOnce(baked.get(), nullptr)), std::set<std::string>{"front"});
}
