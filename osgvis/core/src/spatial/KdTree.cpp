// SPDX-License-Identifier: MIT
#include <osgVis/core/spatial/KdTree.h>

#include <algorithm>

namespace osgVis::core
{
void KdTree::build(const std::vector<Aabb>& boxes, std::uint32_t maxLeafItems)
{
    _nodes.clear();
    _items.clear();
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
    {
        if (!boxes[i].empty() && boxes[i].finite())
            _items.push_back(i);
    }
    if (_items.empty())
        return;
    buildNode(boxes, 0, static_cast<std::uint32_t>(_items.size()), std::max<std::uint32_t>(maxLeafItems, 1));
}

std::uint32_t KdTree::buildNode(const std::vector<Aabb>& boxes, std::uint32_t first, std::uint32_t count,
                                std::uint32_t maxLeafItems)
{
    const auto index = static_cast<std::uint32_t>(_nodes.size());
    _nodes.emplace_back();

    Aabb bounds;
    Aabb centroids;
    for (std::uint32_t i = first; i < first + count; ++i)
    {
        bounds.expand(boxes[_items[i]]);
        centroids.expand(boxes[_items[i]].center());
    }
    Node node;
    node.bounds = bounds;
    node.firstItem = first;
    node.itemCount = count;

    if (count > maxLeafItems)
    {
        const Vec3 extent = centroids.extent();
        const int axis = (extent.x >= extent.y && extent.x >= extent.z) ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::uint32_t half = count / 2;
        const auto begin = _items.begin() + first;
        const auto byAxis = [&](std::uint32_t a, std::uint32_t b) {
            return boxes[a].center()[axis] < boxes[b].center()[axis];
        };
        std::nth_element(begin, begin + half, begin + count, byAxis);
        const double rightMin = boxes[*(begin + half)].center()[axis];
        const double leftMax = boxes[*std::max_element(begin, begin + half, byAxis)].center()[axis];
        node.axis = static_cast<std::uint8_t>(axis);
        node.split = 0.5 * (leftMax + rightMin);
        // note: children are built before the parent is stored, as emplace_back may reallocate.
        node.left = buildNode(boxes, first, half, maxLeafItems);
        node.right = buildNode(boxes, first + half, count - half, maxLeafItems);
    }
    _nodes[index] = node;
    return index;
}

void KdTree::traverseFrontToBack(const Vec3& eye, const std::function<bool(std::uint32_t nodeIndex)>& visit) const
{
    if (_nodes.empty())
        return;
    std::vector<std::uint32_t> stack;
    stack.reserve(64);
    stack.push_back(0);
    while (!stack.empty())
    {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        if (!visit(index))
            continue;
        const Node& node = _nodes[index];
        if (node.leaf())
            continue;
        // The child on the eye's side of the split goes on top of the stack, so it is visited first.
        const bool leftNear = eye[node.axis] <= node.split;
        stack.push_back(leftNear ? node.right : node.left);
        stack.push_back(leftNear ? node.left : node.right);
    }
}
} // namespace osgVis::core
