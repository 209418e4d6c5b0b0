// SPDX-License-Identifier: MIT
#include "TestHierarchies.h"

#include "RayCastVisibility.h"
#include "RegionSampling.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace osgVis::test
{
using namespace core;

std::shared_ptr<DisjointCellTree> kdTreeOf(const Scene& scene, std::uint32_t maxLeafObjects)
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

Bvh::Bvh(const Scene& scene, HierarchyLayout declared, std::uint32_t maxLeafObjects) : _declared(declared)
{
    std::vector<Aabb> boxes;
    for (const SceneObject& o : scene.objects)
        boxes.push_back(o.bounds);
    _tree.build(boxes, maxLeafObjects);
}

void Bvh::traverse(const Vec3& eye, HierarchyVisitor& visitor) const { visit(0, eye, visitor); }

void Bvh::visit(std::uint32_t i, const Vec3& eye, HierarchyVisitor& visitor) const
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

void BackToFront::traverse(const Vec3& eye, HierarchyVisitor& visitor) const { visit(0, eye, visitor); }

void BackToFront::visit(std::uint32_t i, const Vec3& eye, HierarchyVisitor& visitor) const
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

void GrowsAfterFirstWalk::traverse(const Vec3& eye, HierarchyVisitor& visitor) const
{
    if (_walks++ == 0)
        return _tree->traverse(eye, visitor);
    const DisjointCellTree::Node& root = _tree->node(0);
    HierarchyNode node{0, Aabb(root.cell.min - Vec3(1.0), root.cell.max), _tree->objects().data() + root.firstObject,
                       root.objectCount};
    if (visitor.enter(node))
        visitor.leave(node);
}

void HoldsTwice::traverse(const Vec3&, HierarchyVisitor& visitor) const
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

namespace
{
Vec3 direction(double yawDegrees, double pitchDegrees)
{
    const double yaw = yawDegrees * M_PI / 180.0, pitch = pitchDegrees * M_PI / 180.0;
    return {std::cos(pitch) * std::sin(yaw), std::cos(pitch) * std::cos(yaw), std::sin(pitch)};
}
} // namespace

VisibleSet cullAll(VisibilityModule& module, std::size_t objects, const View& view)
{
    VisibleSet visible(objects, true);
    module.cull(view, visible);
    return visible;
}

std::size_t culledOver(VisibilityModule& module, const Scene& scene, const std::vector<View>& views)
{
    std::size_t culled = 0;
    for (const View& view : views)
        culled += scene.objects.size() - cullAll(module, scene.objects.size(), view).count();
    return culled;
}

std::size_t missedByRays(const char* what, VisibilityModule& module, const Scene& scene, const std::vector<View>& views)
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
} // namespace osgVis::test
