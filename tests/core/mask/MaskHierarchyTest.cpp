// SPDX-License-Identifier: MIT
// The mask module on a renderer's own hierarchy (visibility API, ordered traversal by callback): a
// renderer tree built exactly as the module builds its kd-tree gives exactly the module's sets and
// marks along a walk (temporal coherence included); disjoint cells holding objects at inner nodes
// and a BVH keep everything the rays see, in either traversal order; a traversal that strays marks
// nothing; an unusable hierarchy is replaced by the module's own tree. Scene changes on a renderer's
// hierarchy are in MaskModuleTest (Dynamic, OnRendererKdTree).
#include "BoxScenes.h"
#include "RegionSampling.h"
#include "TestHierarchies.h"

#include <osgVis/core/mask/MaskKdTree.h>
#include <osgVis/core/mask/MaskModule.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
/// The module's own kd-tree (same inputs, same split rule) as a renderer would hand it over: node
/// ids are the tree's indices, the nearer child first.
class RendererMaskKdTree : public TraversalHierarchy
{
public:
    RendererMaskKdTree(const Scene& scene, MaskKdTree::Split split, std::uint32_t maxLeafObjects)
    {
        std::vector<Aabb> bounds(scene.objects.size());
        std::vector<bool> present(scene.objects.size());
        for (const SceneObject& o : scene.objects)
        {
            bounds[o.id] = o.bounds;
            present[o.id] = !(o.flags & (OBJECT_DYNAMIC | OBJECT_ALWAYS_VISIBLE));
        }
        _tree.build(bounds, present, split, maxLeafObjects);
    }
    HierarchyLayout layout() const override { return HierarchyLayout::Overlapping; }
    std::uint32_t nodeCount() const override { return std::uint32_t(_tree.nodes().size()); }
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override { visit(_tree.root(), eye, visitor); }

private:
    void visit(std::uint32_t i, const Vec3& eye, HierarchyVisitor& visitor) const
    {
        const MaskKdTree::Node& n = _tree.node(i);
        HierarchyNode node{i, n.bounds, n.objects.data(), n.objects.size()};
        if (!visitor.enter(node))
            return;
        if (!n.leaf())
        {
            const bool leftFirst = _tree.node(n.left).bounds.distance(eye) <= _tree.node(n.right).bounds.distance(eye);
            visit(leftFirst ? n.left : n.right, eye, visitor);
            visit(leftFirst ? n.right : n.left, eye, visitor);
        }
        visitor.leave(node);
    }
    MaskKdTree _tree;
};

/// Three legs of 50 frames down the street x = 25, 30 frames a second at 0.45 units/s (under the
/// speed bound the walk's modules are given, so marks outlive frames), each leg with its own fixed
/// gaze (marks hold only while the orientation stays): ahead, turned right, looking up a little.
constexpr double kWalkSpeedBound = 0.5;
std::vector<View> streetWalk()
{
    std::vector<View> walk;
    for (int f = 0; f < 150; ++f)
    {
        const int leg = f / 50;
        const double yaw = (leg == 0 ? 0.0 : leg == 1 ? 25.0 : -10.0) * M_PI / 180.0;
        const double pitch = leg < 2 ? -0.03 : 0.2;
        const Vec3 eye(25.0, -5.0 + 45.0 * leg + 0.015 * (f % 50), 1.7);
        View view = lookFrom(eye, {std::sin(yaw), std::cos(yaw), pitch}, {0, 0, 1}, 60.0, 128, 96);
        view.time = f / 30.0;
        walk.push_back(view);
    }
    return walk;
}

} // namespace

TEST(MaskHierarchy, RendererTreeBuiltLikeItsOwnGivesExactlyItsSetsAndMarks)
{
    City city = makeCity();
    const std::vector<View> walk = streetWalk();
    for (const MaskKdTree::Split split : {MaskKdTree::Split::Planar, MaskKdTree::Split::Full})
    {
        MaskOptions options;
        options.tree = split == MaskKdTree::Split::Planar ? MaskOptions::Tree::Planar : MaskOptions::Tree::Full;
        options.maxEyeSpeed = kWalkSpeedBound;
        MaskModule own(options), walked(options);
        own.setScene(city.scene);
        Scene withHierarchy = city.scene;
        withHierarchy.hierarchy = std::make_shared<RendererMaskKdTree>(city.scene, split, options.maxLeafObjects);
        walked.setScene(withHierarchy);
        ASSERT_TRUE(walked.walksSceneHierarchy());
        EXPECT_FALSE(own.walksSceneHierarchy());
        EXPECT_EQ(walked.hierarchyProblem(), "");
        std::size_t culled = 0, critical = 0;
        for (std::size_t f = 0; f < walk.size(); ++f)
        {
            const VisibleSet a = cullAll(own, city.scene.objects.size(), walk[f]);
            const VisibleSet b = cullAll(walked, city.scene.objects.size(), walk[f]);
            ASSERT_EQ(a.ids(), b.ids()) << "frame " << f;
            const MaskModule::Statistics s = own.lastStatistics(), t = walked.lastStatistics();
            EXPECT_EQ(s.critical, t.critical) << "frame " << f;
            EXPECT_EQ(s.occluderObjects, t.occluderObjects) << "frame " << f;
            EXPECT_EQ(s.nodesTested, t.nodesTested) << "frame " << f;
            EXPECT_EQ(s.nodesMarked, t.nodesMarked) << "frame " << f;
            EXPECT_EQ(s.objectsMarked, t.objectsMarked) << "frame " << f;
            EXPECT_EQ(s.culled, t.culled) << "frame " << f;
            EXPECT_EQ(t.nodesStrayed, 0u);
            culled += city.scene.objects.size() - a.count();
            critical += s.critical != MaskModule::CriticalReason::None;
        }
        EXPECT_GT(culled, walk.size() * 50) << "the comparison is not between two empty answers";
        EXPECT_LT(critical, walk.size() / 2) << "frames between critical ones read the marks";
    }
}

TEST(MaskHierarchy, DisjointCellsAndBvhInEitherOrderKeepWhatTheRaysSee)
{
    City city = makeCity();
    std::vector<View> views = streetWalk();
    views.resize(50); // the first leg (the rays are slow)
    for (const View& view : cityViews(12))
    {
        views.push_back(view);
        views.back().time = views[views.size() - 2].time + 0.5; // each its own critical frame
    }
    MaskModule own, ownAgain;
    own.setScene(city.scene);
    ownAgain.setScene(city.scene);
    EXPECT_EQ(missedByRays("own kd-tree", own, city.scene, views), 0u); // the efficacy beside the others
    const std::size_t built = culledOver(ownAgain, city.scene, views);
    const std::shared_ptr<TraversalHierarchy> hierarchies[] = {kdTreeOf(city.scene),
                                                               std::make_shared<BackToFront>(kdTreeOf(city.scene)),
                                                               std::make_shared<Bvh>(city.scene, HierarchyLayout::Overlapping)};
    const char* names[] = {"renderer kd-tree", "kd-tree back to front", "BVH"};
    for (int h = 0; h < 3; ++h)
    {
        Scene scene = city.scene;
        scene.hierarchy = hierarchies[h];
        MaskModule module;
        module.setScene(scene);
        ASSERT_TRUE(module.walksSceneHierarchy()) << names[h];
        EXPECT_EQ(missedByRays(names[h], module, scene, views), 0u) << names[h];
        MaskModule again;
        again.setScene(scene);
        EXPECT_GT(culledOver(again, scene, views), built * 7 / 10) << names[h] << ": its nodes serve the marking";
        EXPECT_EQ(again.lastStatistics().nodesStrayed, 0u) << names[h] << ": order is not needed, so not checked";
    }
}

TEST(MaskHierarchy, TraversalThatStraysMarksNothing)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<GrowsAfterFirstWalk>(kdTreeOf(city.scene));
    MaskModule module;
    module.setScene(city.scene); // the recording walk
    ASSERT_TRUE(module.walksSceneHierarchy());
    for (const View& view : streetWalk())
    {
        const VisibleSet answer = cullAll(module, city.scene.objects.size(), view);
        EXPECT_EQ(answer.count(), city.scene.objects.size());
        if (module.lastStatistics().critical != MaskModule::CriticalReason::None)
        {
            EXPECT_EQ(module.lastStatistics().nodesStrayed, 1u);
        }
    }
}

TEST(MaskHierarchy, UnusableHierarchyIsReplacedByTheModulesOwnTree)
{
    expectUnusableHierarchyReplaced<MaskModule, MaskOptions>();
}
