// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A renderer's own spatial hierarchy, handed to the modules as a front-to-back traversal by
/// callback (Luka, §3.3 of the visibility API): a module that walks a hierarchy (cdt) walks this
/// one instead of building its own tree. The renderer declares how its nodes relate:
///  - Disjoint (kd-tree, BSP, octree cells): sibling regions do not overlap, a child lies inside its
///    parent, and an object held by a node lies inside that node's region. Front to back then
///    orders the regions along every ray from the eye, which a module may use (cover drawn inside
///    an earlier region hides a later one without depth).
///  - Overlapping (a BVH, a scene graph's bounding boxes): front to back over overlapping boxes
///    does not order their contents, so a module may use the traversal only for its grouping.
/// Nothing the renderer states is trusted blindly: modules check the structure (HierarchyIndex).
#include <osgVis/core/geometry/Aabb.h>

#include <cstddef>
#include <cstdint>

namespace osgVis::core
{
using ObjectId = std::uint32_t;

enum class HierarchyLayout
{
    Disjoint,
    Overlapping,
};

struct HierarchyNode
{
    /// Stable id of the node, below TraversalHierarchy::nodeCount(); the same node has the same id,
    /// the same region and the same objects in every traversal.
    std::uint32_t id = 0;
    /// The node's region (Disjoint) or bounding box (Overlapping), world space: it holds the node's
    /// objects and its children.
    Aabb region;
    const ObjectId* objects = nullptr; ///< objects held at this node (not those of its children)
    std::size_t objectCount = 0;
};

class HierarchyVisitor
{
public:
    virtual ~HierarchyVisitor() = default;
    /// A node is reached; true descends into its children, false skips them (and their objects).
    virtual bool enter(const HierarchyNode& node) = 0;
    /// Every child of the node entered last with `enter` returning true has been left.
    virtual void leave(const HierarchyNode& node) = 0;
};

/// A visitor made of two callables (a module's lambdas sharing its cull's state).
template <class Enter, class Leave>
class LambdaVisitor : public HierarchyVisitor
{
public:
    LambdaVisitor(Enter& onEnter, Leave& onLeave) : _onEnter(onEnter), _onLeave(onLeave) {}
    bool enter(const HierarchyNode& node) override { return _onEnter(node); }
    void leave(const HierarchyNode& node) override { _onLeave(node); }

private:
    Enter& _onEnter;
    Leave& _onLeave;
};

class TraversalHierarchy
{
public:
    virtual ~TraversalHierarchy() = default;
    virtual HierarchyLayout layout() const = 0;
    /// Node ids are below this.
    virtual std::uint32_t nodeCount() const = 0;
    /// Depth first from the root; the children of a node nearest to `eye` first (for Disjoint: in an
    /// order in which no later sibling lies in front of an earlier one as seen from the eye). enter
    /// and leave pair up like brackets; leave is called only for nodes whose enter returned true.
    virtual void traverse(const Vec3& eye, HierarchyVisitor& visitor) const = 0;
};
} // namespace osgVis::core
