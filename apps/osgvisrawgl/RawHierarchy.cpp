// SPDX-License-Identifier: MIT
#include "RawHierarchy.h"

#include <algorithm>
#include <cmath>

namespace osgVis::rawgl
{
namespace
{
constexpr std::uint32_t None = ~0u;

bool hasBounds(const RawObject& o)
{
    for (int k = 0; k < 3; ++k)
        if (!(o.boundsMin[k] <= o.boundsMax[k]) || !std::isfinite(o.boundsMin[k]) || !std::isfinite(o.boundsMax[k]))
            return false;
    return true;
}
} // namespace

RawHierarchy::RawHierarchy(const RawScene& scene)
{
    _nodes.push_back({{RawObject::Huge, RawObject::Huge, RawObject::Huge}, {-RawObject::Huge, -RawObject::Huge, -RawObject::Huge}, {}, {}});
    for (std::uint32_t root : scene.rootNodes)
    {
        const std::uint32_t child = build(scene, root);
        if (child == None)
            continue;
        _nodes[0].children.push_back(child);
        for (int k = 0; k < 3; ++k)
        {
            _nodes[0].min[k] = std::min(_nodes[0].min[k], _nodes[child].min[k]);
            _nodes[0].max[k] = std::max(_nodes[0].max[k], _nodes[child].max[k]);
        }
    }
}

std::uint32_t RawHierarchy::build(const RawScene& scene, std::uint32_t rawNode)
{
    const RawNode& source = scene.nodes[rawNode];
    Node node{{RawObject::Huge, RawObject::Huge, RawObject::Huge}, {-RawObject::Huge, -RawObject::Huge, -RawObject::Huge}, {}, {}};
    auto grow = [&](const double* lo, const double* hi)
    {
        for (int k = 0; k < 3; ++k)
            node.min[k] = std::min(node.min[k], lo[k]), node.max[k] = std::max(node.max[k], hi[k]);
    };
    for (std::uint32_t id : source.objects)
        if (hasBounds(scene.objects[id]))
        {
            node.objects.push_back(id);
            grow(scene.objects[id].boundsMin, scene.objects[id].boundsMax);
        }
    for (std::uint32_t c : source.children)
    {
        const std::uint32_t child = build(scene, c);
        if (child == None)
            continue;
        node.children.push_back(child);
        grow(_nodes[child].min.data(), _nodes[child].max.data());
    }
    if (node.objects.empty() && node.children.empty())
        return None;
    _nodes.push_back(std::move(node));
    return std::uint32_t(_nodes.size() - 1);
}

osgvis_hierarchy_desc RawHierarchy::desc()
{
    return {OSGVIS_HIERARCHY_OVERLAPPING, std::uint32_t(_nodes.size()), this, &RawHierarchy::traverse, nullptr};
}

void RawHierarchy::traverse(void* self, const double eye[3], const osgvis_hierarchy_visitor* visitor)
{
    const auto& h = *static_cast<const RawHierarchy*>(self);
    if (!h._nodes[0].children.empty())
        h.visit(0, eye, *visitor);
}

double RawHierarchy::distance(std::uint32_t node, const double eye[3]) const
{
    double d2 = 0;
    for (int k = 0; k < 3; ++k)
    {
        const double d = std::max({_nodes[node].min[k] - eye[k], 0.0, eye[k] - _nodes[node].max[k]});
        d2 += d * d;
    }
    return d2;
}

void RawHierarchy::visit(std::uint32_t index, const double eye[3], const osgvis_hierarchy_visitor& visitor) const
{
    const Node& n = _nodes[index];
    osgvis_hierarchy_node node{};
    node.id = index;
    std::copy(n.min.begin(), n.min.end(), node.region_min);
    std::copy(n.max.begin(), n.max.end(), node.region_max);
    node.objects = n.objects.empty() ? nullptr : n.objects.data();
    node.object_count = std::uint32_t(n.objects.size());
    if (!visitor.enter(visitor.state, &node))
        return;
    // Nearest box first: over overlapping boxes this orders nothing along rays, but it is the order
    // in which occluders are most likely met (the module checks nothing more of a BVH).
    std::vector<std::uint32_t> order = n.children;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return distance(a, eye) < distance(b, eye); });
    for (std::uint32_t child : order)
        visit(child, eye, visitor);
    if (visitor.leave)
        visitor.leave(visitor.state, &node);
}
} // namespace osgVis::rawgl
