// SPDX-License-Identifier: MIT
#pragma once
// Renderer hierarchies for the tests of modules that walk Scene::hierarchy (visibility API,
// ordered traversal by callback): a kd-tree of disjoint cells as a renderer could build it, a BVH
// (overlapping tight boxes, declared either way), a kd-tree walked back to front, and one that holds
// an object twice. Also the city views and checks those tests share.
#include "BoxScenes.h"

#include <osgVis/core/module/VisibilityModule.h>
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/TraversalHierarchy.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/spatial/DisjointCellTree.h>
#include <osgVis/core/spatial/KdTree.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace osgVis::test
{
/// The scene's objects (always-visible ones left out) in a kd-tree of disjoint cells.
std::shared_ptr<core::DisjointCellTree> kdTreeOf(const core::Scene& scene, std::uint32_t maxLeafObjects = 1);

/// A BVH (spatial/KdTree: tight boxes, median splits) as a renderer's scene graph would have it:
/// nodes overlap; the nearer child box first.
class Bvh : public core::TraversalHierarchy
{
public:
    Bvh(const core::Scene& scene, core::HierarchyLayout declared, std::uint32_t maxLeafObjects = 3);
    core::HierarchyLayout layout() const override { return _declared; }
    std::uint32_t nodeCount() const override { return std::uint32_t(_tree.nodes().size()); }
    void traverse(const core::Vec3& eye, core::HierarchyVisitor& visitor) const override;

private:
    void visit(std::uint32_t i, const core::Vec3& eye, core::HierarchyVisitor& visitor) const;
    core::KdTree _tree;
    core::HierarchyLayout _declared;
};

/// A kd-tree walked back to front although it says disjoint: its own traversal order is wrong.
class BackToFront : public core::TraversalHierarchy
{
public:
    explicit BackToFront(std::shared_ptr<core::DisjointCellTree> tree) : _tree(std::move(tree)) {}
    core::HierarchyLayout layout() const override { return core::HierarchyLayout::Disjoint; }
    std::uint32_t nodeCount() const override { return _tree->nodeCount(); }
    void traverse(const core::Vec3& eye, core::HierarchyVisitor& visitor) const override;

private:
    void visit(std::uint32_t i, const core::Vec3& eye, core::HierarchyVisitor& visitor) const;
    std::shared_ptr<core::DisjointCellTree> _tree;
};

/// A kd-tree whose root region grows after the first traversal (the recording one): every later
/// walk strays at once.
class GrowsAfterFirstWalk : public core::TraversalHierarchy
{
public:
    explicit GrowsAfterFirstWalk(std::shared_ptr<core::DisjointCellTree> tree) : _tree(std::move(tree)) {}
    core::HierarchyLayout layout() const override { return core::HierarchyLayout::Disjoint; }
    std::uint32_t nodeCount() const override { return _tree->nodeCount(); }
    void traverse(const core::Vec3& eye, core::HierarchyVisitor& visitor) const override;

private:
    std::shared_ptr<core::DisjointCellTree> _tree;
    mutable int _walks = 0;
};

/// Holds object 0 at the root and again in the first leaf.
class HoldsTwice : public core::TraversalHierarchy
{
public:
    core::HierarchyLayout layout() const override { return core::HierarchyLayout::Overlapping; }
    std::uint32_t nodeCount() const override { return 2; }
    void traverse(const core::Vec3& eye, core::HierarchyVisitor& visitor) const override;
};

/// The module's answer when every object starts visible.
core::VisibleSet cullAll(core::VisibilityModule& module, std::size_t objects, const core::View& view);

/// Objects the module culls over all the views, each culled from everything visible.
std::size_t culledOver(core::VisibilityModule& module, const core::Scene& scene, const std::vector<core::View>& views);

/// Objects the ray-cast reference sees that `module` culls on some view (0 expected); prints the
/// occlusion efficacy (in-frustum objects the rays do not see that the module culls).
std::size_t missedByRays(const char* what, core::VisibilityModule& module, const core::Scene& scene,
                         const std::vector<core::View>& views);

/// `count` views over makeCity(): eyes in and above the streets, some gazing steeply up.
std::vector<core::View> cityViews(int count);

/// A module handed an unusable hierarchy (HoldsTwice) says why and answers as on its own tree;
/// with Options::sceneHierarchy false it ignores a usable one. Module: walksSceneHierarchy(),
/// hierarchyProblem().
template <class Module, class Options>
void expectUnusableHierarchyReplaced()
{
    City city = makeCity();
    Module own;
    own.setScene(city.scene);
    core::Scene broken = city.scene;
    broken.hierarchy = std::make_shared<HoldsTwice>();
    Module module;
    module.setScene(broken);
    EXPECT_FALSE(module.walksSceneHierarchy());
    EXPECT_EQ(module.hierarchyProblem(), "object 0 is held twice (node 1)");
    for (const core::View& view : cityViews(5))
        EXPECT_EQ(cullAll(module, broken.objects.size(), view).ids(), cullAll(own, city.scene.objects.size(), view).ids());

    Options ignore;
    ignore.sceneHierarchy = false;
    Module ignoring(ignore);
    city.scene.hierarchy = kdTreeOf(city.scene);
    ignoring.setScene(city.scene);
    EXPECT_FALSE(ignoring.walksSceneHierarchy());
}

} // namespace osgVis::test
