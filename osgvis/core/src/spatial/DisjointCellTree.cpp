// SPDX-License-Identifier: MIT
// Luka, "Visibility culling with a constrained Delaunay triangulation", §2.2.4: the kd-tree of
// cells the CDT traversal visits front to back.
#include <osgVis/core/spatial/DisjointCellTree.h>

#include <algorithm>

namespace osgVis::core
{
namespace
{
constexpr int MaxDepth = 40;

} // namespace

void DisjointCellTree::build(const std::vector<Aabb>& bounds, const std::vector<bool>& present, std::uint32_t maxLeafObjects)
{
    _bounds = &bounds;
    _maxLeafObjects = std::max<std::uint32_t>(1, maxLeafObjects);
    _nodes.clear();
    _objects.clear();
    _inTree.assign(bounds.size(), false);
    std::vector<ObjectId> ids;
    Aabb all;
    for (ObjectId id = 0; id < bounds.size(); ++id)
    {
        const Aabb& b = bounds[id];
        if (b.empty() || !b.finite() || (id < present.size() && !present[id]))
            continue;
        ids.push_back(id);
        all.expand(b);
        _inTree[id] = true;
    }
    if (ids.empty())
        return;
    _objects.reserve(ids.size());
    buildNode(all, ids, 0);
    _bounds = nullptr;
}

std::uint32_t DisjointCellTree::buildNode(const Aabb& cell, std::vector<ObjectId>& ids, int depth)
{
    const std::uint32_t index = std::uint32_t(_nodes.size());
    _nodes.push_back({});
    _nodes[index].cell = cell;
    Aabb contents;
    for (ObjectId id : ids)
        contents.expand((*_bounds)[id]);
    _nodes[index].contents = contents;

    auto hold = [&](const std::vector<ObjectId>& held) {
        _nodes[index].firstObject = std::uint32_t(_objects.size());
        _nodes[index].objectCount = std::uint32_t(held.size());
        _objects.insert(_objects.end(), held.begin(), held.end());
    };
    if (ids.size() <= _maxLeafObjects || depth >= MaxDepth)
    {
        hold(ids);
        return index;
    }
    // The split with the fewest straddling objects among a few candidate planes per axis (object
    // box faces at quantiles), both sides holding at least an eighth of the objects where that is
    // possible; ties go to the more even split. Straddlers stay here and only hide by depth inside
    // the subtree, so fewer of them is what makes the depth-free rule strong.
    int axis = -1;
    double split = 0.0;
    std::size_t bestStraddling = 0, bestImbalance = 0;
    bool bestBalanced = false;
    std::vector<double> faces;
    for (int a = 0; a < 3; ++a)
    {
        faces.clear();
        for (ObjectId id : ids)
            faces.push_back((*_bounds)[id].min[a]), faces.push_back((*_bounds)[id].max[a]);
        std::sort(faces.begin(), faces.end());
        constexpr int Candidates = 15;
        for (int c = 1; c <= Candidates; ++c)
        {
            const double position = faces[faces.size() * std::size_t(c) / (Candidates + 1)];
            if (!(position > cell.min[a] && position < cell.max[a]))
                continue;
            std::size_t low = 0, high = 0, straddling = 0;
            for (ObjectId id : ids)
            {
                const Aabb& b = (*_bounds)[id];
                low += b.max[a] <= position;
                high += b.min[a] >= position && !(b.max[a] <= position);
                straddling += b.max[a] > position && b.min[a] < position;
            }
            if (low == 0 || high == 0)
                continue;
            const bool balanced = std::min(low, high) * 8 >= ids.size();
            const std::size_t imbalance = low > high ? low - high : high - low;
            const bool better = axis < 0 || (balanced && !bestBalanced) ||
                                (balanced == bestBalanced &&
                                 (straddling < bestStraddling || (straddling == bestStraddling && imbalance < bestImbalance)));
            if (better)
                axis = a, split = position, bestStraddling = straddling, bestImbalance = imbalance, bestBalanced = balanced;
        }
    }
    if (axis < 0)
    {
        hold(ids);
        return index;
    }

    std::vector<ObjectId> below, above, straddling;
    for (ObjectId id : ids)
    {
        const Aabb& b = (*_bounds)[id];
        if (b.max[axis] <= split)
            below.push_back(id);
        else if (b.min[axis] >= split)
            above.push_back(id);
        else
            straddling.push_back(id);
    }
    if (below.empty() || above.empty())
    {
        hold(ids);
        return index;
    }
    hold(straddling);
    _nodes[index].axis = std::uint8_t(axis);
    _nodes[index].split = split;
    Aabb lowCell = cell, highCell = cell;
    lowCell.max[axis] = split;
    highCell.min[axis] = split;
    ids.clear();
    ids.shrink_to_fit();
    const std::uint32_t left = buildNode(lowCell, below, depth + 1);
    const std::uint32_t right = buildNode(highCell, above, depth + 1);
    _nodes[index].left = left;
    _nodes[index].right = right;
    return index;
}

void DisjointCellTree::traverse(const Vec3& eye, HierarchyVisitor& visitor) const
{
    if (!_nodes.empty())
        visit(root(), eye, visitor);
}

void DisjointCellTree::visit(std::uint32_t index, const Vec3& eye, HierarchyVisitor& visitor) const
{
    const Node& n = _nodes[index];
    HierarchyNode node;
    node.id = index;
    node.region = n.cell;
    node.objects = _objects.data() + n.firstObject;
    node.objectCount = n.objectCount;
    if (!visitor.enter(node))
        return;
    if (!n.leaf())
    {
        const bool lowFirst = eye[n.axis] < n.split;
        visit(lowFirst ? n.left : n.right, eye, visitor);
        visit(lowFirst ? n.right : n.left, eye, visitor);
    }
    visitor.leave(node);
}
} // namespace osgVis::core
