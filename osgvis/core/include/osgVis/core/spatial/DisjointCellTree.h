// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The spatial subdivision Luka's traversal walks (§2.2.4): a kd-tree of disjoint cells. An object
/// lies in the deepest cell that holds its whole box, so a leaf's objects lie inside the leaf's
/// cell, and an inner node holds the objects that straddle its split plane ("incident" objects,
/// §2.3.1). Front to back from the eye, the cells of a kd-tree are ordered along every ray: a ray
/// never meets a cell after one the traversal visits later, which is what lets an occluder inside
/// an earlier cell hide a later cell without any depth test.
///
/// It is a TraversalHierarchy (Disjoint), so a renderer without a hierarchy of its own may build
/// one and hand it to the modules, and the cdt module walks its own tree through the same calls.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/TraversalHierarchy.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
class DisjointCellTree : public TraversalHierarchy
{
public:
    static constexpr std::uint32_t None = ~std::uint32_t(0);
    struct Node
    {
        Aabb cell;                    ///< the node's region of space (children split it)
        Aabb contents;                ///< tight box of every object in the subtree (empty: none)
        std::uint32_t left = None, right = None;
        std::uint8_t axis = 0;
        double split = 0.0;
        std::uint32_t firstObject = 0, objectCount = 0; ///< objects held here, into objects()
        bool leaf() const { return left == None; }
    };

    /// Objects with empty or non-finite bounds, or present[id] false, are left out: the owner
    /// must keep them visible.
    void build(const std::vector<Aabb>& bounds, const std::vector<bool>& present, std::uint32_t maxLeafObjects);
    bool empty() const { return _nodes.empty(); }
    const Node& node(std::uint32_t i) const { return _nodes[i]; }
    std::uint32_t root() const { return 0; }
    std::size_t size() const { return _nodes.size(); }
    const std::vector<ObjectId>& objects() const { return _objects; }
    bool contains(ObjectId id) const { return id < _inTree.size() && _inTree[id]; }

    HierarchyLayout layout() const override { return HierarchyLayout::Disjoint; }
    std::uint32_t nodeCount() const override { return std::uint32_t(_nodes.size()); }
    /// Node ids are node indices; the child on the eye's side of the split first.
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override;

private:
    std::uint32_t buildNode(const Aabb& cell, std::vector<ObjectId>& ids, int depth);
    void visit(std::uint32_t index, const Vec3& eye, HierarchyVisitor& visitor) const;
    const std::vector<Aabb>* _bounds = nullptr;
    std::uint32_t _maxLeafObjects = 4;
    std::vector<Node> _nodes;
    std::vector<ObjectId> _objects;
    std::vector<bool> _inTree;
};
} // namespace osgVis::core
