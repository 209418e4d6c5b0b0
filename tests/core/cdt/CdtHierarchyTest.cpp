// SPDX-License-Identifier: MIT
// The cdt module on a renderer's own hierarchy (visibility API, ordered traversal by callback): a
// renderer kd-tree built as the module builds its own gives exactly the module's sets; a BVH
// (overlapping boxes) is walked under the depth-only rule and keeps everything the rays see; a
// hierarchy that lies about being disjoint is caught and walked as overlapping; a traversal out
// of front-to-back order keeps every candidate; an unusable one is replaced by the module's tree.
#include "BoxScenes.h"
#include "RayCastVisibility.h"
#include "RegionSampling.h"

#include <osgVis/core/cdt/CdtModule.h>
#include <osgVis/core/spatial/DisjointCellTree.h>
#include <osgVis/core/spatial/KdTree.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
std::shared_ptr<DisjointCellTree> kdTreeOf(const Scene& scene, std::uint32_t maxLeafObjects = 1)
{
    std::vector<Aabb> bounds(scene.objects.size());
    std::vector<bool> present(scene.objects.size(), true);
    for (const SceneObject& o : scene.objects)
    {
        bounds[o.id] = o.bounds;
        present[o.id] = !(o.flags & OBJECT_ALWAYS_VISIBLE);
    }
    auto tree = std::make_shared<DisjointCellTree>();
    tree->build(bounds, present, maxLeafObjects);
    return tree;
}

/// A BVH (spatial/KdTree: tight boxes, median splits) as a renderer's scene graph would have it:
/// nodes overlap; the nearer child box first.
class Bvh : public TraversalHierarchy
{
public:
    Bvh(const Scene& scene, HierarchyLayout declared) : _declared(declared)
    {
        std::vector<Aabb> boxes;
        for (const SceneObject& o : scene.objects)
            boxes.push_back(o.bounds);
        _tree.build(boxes, 3);
    }
    HierarchyLayout layout() const override { return _declared; }
    std::uint32_t nodeCount() const override { return std::uint32_t(_tree.nodes().size()); }
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override { visit(0, eye, visitor); }

private:
    void visit(std::uint32_t i, const Vec3& eye, HierarchyVisitor& visitor) const
    {
        const KdTree::Node& n = _tree.nodes()[i];
        HierarchyNode node;
        node.id = i;
        node.region = n.bounds;
        if (n.leaf())
        {
            node.objects = _tree.items().data() + n.firstItem;
            node.objectCount = n.itemCount;
        }
        if (!visitor.enter(node))
            return;
        if (!n.leaf())
        {
            const bool leftFirst = _tree.nodes()[n.left].bounds.distance(eye) <= _tree.nodes()[n.right].bounds.distance(eye);
            visit(leftFirst ? n.left : n.right, eye, visitor);
            visit(leftFirst ? n.right : n.left, eye, visitor);
        }
        visitor.leave(node);
    }
    KdTree _tree;
    HierarchyLayout _declared;
};

/// A kd-tree walked back to front although it says disjoint: its own traversal order is wrong.
class BackToFront : public TraversalHierarchy
{
public:
    explicit BackToFront(std::shared_ptr<DisjointCellTree> tree) : _tree(std::move(tree)) {}
    HierarchyLayout layout() const override { return HierarchyLayout::Disjoint; }
    std::uint32_t nodeCount() const override { return _tree->nodeCount(); }
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override { visit(0, eye, visitor); }

private:
    void visit(std::uint32_t i, const Vec3& eye, HierarchyVisitor& visitor) const
    {
        const DisjointCellTree::Node& n = _tree->node(i);
        HierarchyNode node;
        node.id = i;
        node.region = n.cell;
        node.objects = _tree->objects().data() + n.firstObject;
        node.objectCount = n.objectCount;
        if (!visitor.enter(node))
            return;
        if (!n.leaf())
        {
            const bool lowFirst = eye[n.axis] >= n.split; // the far child first
            visit(lowFirst ? n.left : n.right, eye, visitor);
            visit(lowFirst ? n.right : n.left, eye, visitor);
        }
        visitor.leave(node);
    }
    std::shared_ptr<DisjointCellTree> _tree;
};

/// Holds object 0 at the root and again in the first leaf.
class HoldsTwice : public TraversalHierarchy
{
public:
    HierarchyLayout layout() const override { return HierarchyLayout::Overlapping; }
    std::uint32_t nodeCount() const override { return 2; }
    void traverse(const Vec3&, HierarchyVisitor& visitor) const override
    {
        static const ObjectId zero = 0;
        HierarchyNode root{0, Aabb({-1e3, -1e3, -1e3}, {1e3, 1e3, 1e3}), &zero, 1};
        HierarchyNode child{1, root.region, &zero, 1};
        if (!visitor.enter(root))
            return;
        if (visitor.enter(child))
            visitor.leave(child);
        visitor.leave(root);
    }
};

Vec3 direction(double yawDegrees, double pitchDegrees)
{
    const double yaw = yawDegrees * M_PI / 180.0, pitch = pitchDegrees * M_PI / 180.0;
    return {std::cos(pitch) * std::sin(yaw), std::cos(pitch) * std::cos(yaw), std::sin(pitch)};
}

std::vector<View> cityViews(int count)
{
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<View> views;
    for (int i = 0; i < count; ++i)
    {
        const Vec3 eye(-5.0 + 30.0 * std::floor(unit(random) * 6.0) + 4.0 * (unit(random) - 0.5),
                       -5.0 + 180.0 * unit(random), 0.2 + 12.0 * unit(random) * unit(random));
        const Vec3 d = direction(360.0 * unit(random), i % 5 == 0 ? 80.0 : 30.0 * (unit(random) - 0.5));
        views.push_back(lookFrom(eye, d, std::abs(d.z) > 0.99 ? Vec3(0, 1, 0) : Vec3(0, 0, 1), 60.0, 128, 96));
    }
    return views;
}

VisibleSet cullAll(CdtModule& module, std::size_t objects, const View& view)
{
    VisibleSet visible(objects, true);
    module.cull(view, visible);
    return visible;
}

/// Objects the rays see that `module` culls on some view (0 expected); prints its efficacy.
std::size_t missedByRays(const char* what, CdtModule& module, const Scene& scene, const std::vector<View>& views)
{
    const RayCastVisibility rays(scene);
    std::size_t missed = 0, hidden = 0, culled = 0;
    for (const View& view : views)
    {
        const RayCastResult seen = rays.cast(view);
        const VisibleSet answer = cullAll(module, scene.objects.size(), view);
        for (ObjectId id = 0; id < scene.objects.size(); ++id)
        {
            missed += seen.visible[id] && !answer.test(id);
            if (!seen.visible[id] && view.frustum.classify(scene.objects[id].bounds) != Containment::Outside)
                ++hidden, culled += !answer.test(id);
        }
    }
    std::printf("[ %-13s ] %s: %zu views, occlusion efficacy %.3f\n", module.name(), what, views.size(),
                hidden ? double(culled) / double(hidden) : 0.0);
    return missed;
}
} // namespace

TEST(CdtHierarchy, RendererKdTreeGivesExactlyTheOwnTreesSets)
{
    City city = makeCity();
    const std::vector<View> views = cityViews(40);
    for (CdtOptions::Rule rule : {CdtOptions::Rule::Combined, CdtOptions::Rule::DepthFree, CdtOptions::Rule::DepthOnly})
    {
        CdtOptions options;
        options.rule = rule;
        CdtModule own(options);
        own.setScene(city.scene);
        Scene withHierarchy = city.scene;
        withHierarchy.hierarchy = kdTreeOf(city.scene);
        CdtModule walked(options);
        walked.setScene(withHierarchy);
        ASSERT_TRUE(walked.walksSceneHierarchy());
        EXPECT_FALSE(own.walksSceneHierarchy());
        EXPECT_EQ(walked.walkedLayout(), HierarchyLayout::Disjoint);
        EXPECT_EQ(walked.hierarchyProblem(), "");
        std::size_t culled = 0;
        for (std::size_t v = 0; v < views.size(); ++v)
        {
            const VisibleSet a = cullAll(own, city.scene.objects.size(), views[v]);
            const VisibleSet b = cullAll(walked, city.scene.objects.size(), views[v]);
            ASSERT_EQ(a.ids(), b.ids()) << own.name() << ", view " << v;
            EXPECT_FALSE(walked.lastStatistics().traversalStrayed);
            culled += city.scene.objects.size() - a.count();
        }
        EXPECT_GT(culled, views.size() * 100) << "the comparison is not between two empty answers";
    }
}

TEST(CdtHierarchy, OverlappingBvhIsWalkedByDepthAndKeepsWhatTheRaysSee)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<Bvh>(city.scene, HierarchyLayout::Overlapping);
    CdtModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.walksSceneHierarchy());
    EXPECT_EQ(module.walkedLayout(), HierarchyLayout::Overlapping);
    const std::vector<View> views = cityViews(30);
    EXPECT_EQ(missedByRays("renderer BVH", module, city.scene, views), 0u);
    const City plain = makeCity();
    CdtModule own; // for the efficacy beside it
    own.setScene(plain.scene);
    EXPECT_EQ(missedByRays("own kd-tree", own, plain.scene, views), 0u);
    std::size_t culled = 0;
    for (const View& view : views)
        culled += city.scene.objects.size() - cullAll(module, city.scene.objects.size(), view).count();
    EXPECT_GT(culled, views.size() * 50) << "a BVH still groups: occlusion by depth culls";
}

TEST(CdtHierarchy, BvhDeclaredDisjointIsCaughtAndWalkedAsOverlapping)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<Bvh>(city.scene, HierarchyLayout::Disjoint);
    CdtModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.walksSceneHierarchy());
    EXPECT_EQ(module.walkedLayout(), HierarchyLayout::Overlapping);
    EXPECT_NE(module.hierarchyProblem().find("declared disjoint, but"), std::string::npos) << module.hierarchyProblem();
    EXPECT_EQ(missedByRays("BVH said disjoint", module, city.scene, cityViews(30)), 0u);
}

TEST(CdtHierarchy, TraversalOutOfFrontToBackOrderKeepsEveryCandidate)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<BackToFront>(kdTreeOf(city.scene));
    CdtModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.walksSceneHierarchy());
    for (const View& view : cityViews(10))
    {
        const VisibleSet answer = cullAll(module, city.scene.objects.size(), view);
        EXPECT_TRUE(module.lastStatistics().traversalStrayed);
        EXPECT_EQ(answer.count(), city.scene.objects.size());
    }
}

TEST(CdtHierarchy, UnusableHierarchyIsReplacedByTheModulesOwnTree)
{
    City city = makeCity();
    CdtModule own;
    own.setScene(city.scene);
    Scene broken = city.scene;
    broken.hierarchy = std::make_shared<HoldsTwice>();
    CdtModule module;
    module.setScene(broken);
    EXPECT_FALSE(module.walksSceneHierarchy());
    EXPECT_EQ(module.hierarchyProblem(), "object 0 is held twice (node 1)");
    for (const View& view : cityViews(5))
        EXPECT_EQ(cullAll(module, broken.objects.size(), view).ids(), cullAll(own, city.scene.objects.size(), view).ids());

    CdtOptions ignore;
    ignore.sceneHierarchy = false;
    CdtModule ignoring(ignore);
    city.scene.hierarchy = kdTreeOf(city.scene);
    ignoring.setScene(city.scene);
    EXPECT_FALSE(ignoring.walksSceneHierarchy());
}
