// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// What a module knows about a TraversalHierarchy before it trusts a traversal of it: one full walk
/// at setScene records every node (region, held objects, subtree objects, tight contents) and
/// checks what the renderer declared (docs/visapi.md, "Ordered traversal"):
///  - unusable (the module must walk its own tree): a node id out of range or met twice, an object
///    id out of range or held twice, no object held at all;
///  - declared Disjoint but not (a child outside its parent, overlapping siblings, an object outside
///    the node holding it): used as Overlapping, which a module may only use for grouping.
/// During a cull, HierarchyIndex::Walk follows a traversal: it refuses nodes that differ from the
/// recorded ones and, for Disjoint, siblings out of front-to-back order; a module that sees a
/// refusal keeps every candidate of that query.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/TraversalHierarchy.h>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::core
{
class HierarchyIndex
{
public:
    static constexpr std::uint32_t None = ~std::uint32_t(0);
    struct Node
    {
        Aabb region;
        Aabb contents; ///< tight box of the subtree's objects (empty: none)
        std::uint32_t firstObject = 0, heldCount = 0, subtreeEnd = 0; ///< into objects(): held, then the rest of the subtree
        std::uint32_t childCount = 0;
        std::uint32_t firstChild = 0; ///< into childIds(): the node's children in recorded order
        bool recorded = false;
        bool leaf() const { return childCount == 0; }
    };

    /// Walks `hierarchy` once (from the centre of the scene) and checks it against `scene`'s objects.
    void build(const TraversalHierarchy& hierarchy, const Scene& scene);
    bool usable() const { return _usable; }
    /// The layout the checks allow: the declared one, or Overlapping when Disjoint was not true.
    HierarchyLayout layout() const { return _layout; }
    /// Why the hierarchy is unusable or was taken as Overlapping ("" when neither).
    const std::string& problem() const { return _problem; }
    const Node& node(std::uint32_t id) const { return _nodes[id]; }
    const std::vector<ObjectId>& objects() const { return _objects; }
    /// Children of node n: childIds()[n.firstChild .. n.firstChild + n.childCount).
    const std::vector<std::uint32_t>& childIds() const { return _childIds; }
    /// The nodes the traversal entered at the top (usually one root), in recorded order.
    const std::vector<std::uint32_t>& roots() const { return _roots; }
    /// True when some node holds the object (objects outside the hierarchy stay visible).
    bool holds(ObjectId id) const { return id < _held.size() && _held[id]; }

    /// Follows one traversal: enter/leave in the visitor's order. enter returns the recorded node,
    /// or nullptr when the traversal strays (unknown id, another parent, region or object count than
    /// recorded, a Disjoint sibling in front of an earlier one): the query must then keep every
    /// candidate. Each enter that returns a node needs one leave: from the visitor's leave, or at
    /// once when the visitor skips the node's children.
    class Walk
    {
    public:
        /// `ordered` false: a module that needs no front-to-back order (octree: each box is tested
        /// on its own) accepts siblings in any order.
        Walk(const HierarchyIndex& index, const Vec3& eye, bool ordered = true);
        const Node* enter(const HierarchyNode& node);
        void leave();
        std::size_t depth() const { return _stack.size(); }
        /// Begins a new walk from `eye`, keeping this one's buffers (a warm walk allocates nothing).
        void restart(const Vec3& eye)
        {
            _eye = eye;
            _stack.clear();
            _entered.clear();
        }

    private:
        struct Level
        {
            std::uint32_t id;
            std::size_t enteredBegin; ///< the level's children entered so far: _entered[enteredBegin..]
        };
        const HierarchyIndex& _index;
        Vec3 _eye;
        bool _ordered;
        std::vector<Level> _stack;
        std::vector<std::uint32_t> _entered;
    };

private:
    friend class Walk;
    bool _usable = false;
    HierarchyLayout _layout = HierarchyLayout::Overlapping;
    std::string _problem;
    std::vector<Node> _nodes;
    std::vector<ObjectId> _objects;
    std::vector<bool> _held;
    std::vector<std::uint32_t> _declared; ///< per node: the object count the renderer gave
    std::vector<std::uint32_t> _parents;
    std::vector<std::uint32_t> _childIds;
    std::vector<std::uint32_t> _roots;
};
} // namespace osgVis::core
