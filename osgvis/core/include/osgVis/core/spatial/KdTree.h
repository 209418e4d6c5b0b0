// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// kd-tree over object bounds (median split on the longest axis) with front-to-back traversal.
#include <osgVis/core/geometry/Aabb.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace osgVis::core
{
class KdTree
{
public:
    struct Node
    {
        Aabb bounds;                 ///< union of the items below (tight)
        std::uint32_t left = 0;      ///< child indices; 0 for leaves (the root is node 0)
        std::uint32_t right = 0;
        std::uint32_t firstItem = 0; ///< range into items(), covering the whole subtree
        std::uint32_t itemCount = 0;
        std::uint8_t axis = 0;
        double split = 0.0;          ///< left items have centroid[axis] <= split <= right items' centroids
        bool leaf() const { return left == 0 && right == 0; }
    };

    /// Items are indices into `boxes`; empty and non-finite boxes are left out (callers keep those
    /// objects: nothing is known about where they are).
    void build(const std::vector<Aabb>& boxes, std::uint32_t maxLeafItems = 4);
    bool empty() const { return _nodes.empty(); }
    const std::vector<Node>& nodes() const { return _nodes; }
    const std::vector<std::uint32_t>& items() const { return _items; }
    const Node& root() const { return _nodes.front(); }

    /// Visits nodes nearest-first as seen from `eye` (the child containing / nearer to the eye
    /// first). The visitor returns false to skip the node's subtree.
    void traverseFrontToBack(const Vec3& eye, const std::function<bool(std::uint32_t nodeIndex)>& visit) const;

private:
    std::uint32_t buildNode(const std::vector<Aabb>& boxes, std::uint32_t first, std::uint32_t count,
                            std::uint32_t maxLeafItems);
    std::vector<Node> _nodes;
    std::vector<std::uint32_t> _items;
};
} // namespace osgVis::core
