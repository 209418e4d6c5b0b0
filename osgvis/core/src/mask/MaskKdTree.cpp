// SPDX-License-Identifier: MIT
#include <osgVis/core/mask/MaskKdTree.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace osgVis::core
{
namespace
{
bool usable(const Aabb& bounds)
{
    return !bounds.empty() && bounds.finite();
}

double squaredDistance(const Vec3& point, const Aabb& box)
{
    if (box.empty())
        return std::numeric_limits<double>::infinity();
    const Vec3 offset = glm::max(box.min - point, Vec3(0.0)) + glm::max(point - box.max, Vec3(0.0));
    return glm::dot(offset, offset);
}
} // namespace

void MaskKdTree::build(const std::vector<Aabb>& objectBounds, const std::vector<bool>& present, Split split,
                       std::uint32_t maxLeafObjects)
{
    _split = split;
    _maxLeafObjects = std::max<std::uint32_t>(maxLeafObjects, 1);
    _updates = 0;
    _nodes.clear();
    _objectBounds = objectBounds;
    _leafOf.assign(objectBounds.size(), None);
    _objectStamp.assign(objectBounds.size(), 0.0);

    std::vector<ObjectId> ids;
    Aabb sceneBounds;
    for (ObjectId id = 0; id < objectBounds.size(); ++id)
    {
        const bool isPresent = id >= present.size() || present[id];
        if (isPresent && usable(objectBounds[id]))
        {
            ids.push_back(id);
            sceneBounds.expand(objectBounds[id]);
        }
    }
    chooseSplitAxes(sceneBounds);
    if (!ids.empty())
        buildNode(ids, 0, ids.size(), None);
}

void MaskKdTree::rebuild()
{
    std::vector<bool> present(_leafOf.size());
    for (std::size_t id = 0; id < _leafOf.size(); ++id)
        present[id] = _leafOf[id] != None;
    // note: build() overwrites _objectBounds, so it must not read from it.
    const std::vector<Aabb> bounds = std::move(_objectBounds);
    build(bounds, present, _split, _maxLeafObjects);
}

void MaskKdTree::chooseSplitAxes(const Aabb& sceneBounds)
{
    std::iota(_axes, _axes + 3, 0);
    _axisCount = 3;
    if (_split != Split::Planar)
        return;
    // The up axis is the one of smallest extent (z on ties and on an empty scene).
    const Vec3 extent = sceneBounds.empty() ? Vec3(0.0) : sceneBounds.extent();
    int up = 2;
    for (int axis = 1; axis >= 0; --axis)
    {
        if (extent[axis] < extent[up])
            up = axis;
    }
    _axisCount = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (axis != up)
            _axes[_axisCount++] = axis;
    }
    _axes[2] = up;
}

std::uint32_t MaskKdTree::buildNode(std::vector<ObjectId>& ids, std::size_t first, std::size_t count,
                                    std::uint32_t parent)
{
    const auto index = static_cast<std::uint32_t>(_nodes.size());
    _nodes.emplace_back();
    Node& node = _nodes.back();
    node.parent = parent;
    node.objectCount = static_cast<std::uint32_t>(count);
    for (std::size_t i = first; i < first + count; ++i)
        node.bounds.expand(_objectBounds[ids[i]]);

    // note: splitNode appends nodes, so `node` must not be used after it.
    if (!splitNode(index, ids, first, count))
    {
        std::vector<ObjectId>& objects = _nodes[index].objects;
        objects.assign(ids.begin() + first, ids.begin() + first + count);
        std::sort(objects.begin(), objects.end());
        for (const ObjectId id : objects)
            _leafOf[id] = index;
    }
    return index;
}

bool MaskKdTree::splitNode(std::uint32_t index, std::vector<ObjectId>& ids, std::size_t first, std::size_t count)
{
    if (count <= _maxLeafObjects)
        return false;
    Aabb centres;
    for (std::size_t i = first; i < first + count; ++i)
        centres.expand(_objectBounds[ids[i]].center());
    const Vec3 extent = centres.extent();
    int axis = -1;
    for (int i = 0; i < _axisCount; ++i)
    {
        if (extent[_axes[i]] > 0.0 && (axis < 0 || extent[_axes[i]] > extent[axis]))
            axis = _axes[i];
    }
    if (axis < 0)
        return false; // all centres coincide along the splittable axes

    const auto begin = ids.begin() + static_cast<std::ptrdiff_t>(first);
    const std::size_t half = count / 2;
    // Ties broken by id: the same input always gives the same halves.
    const auto byCentre = [&](ObjectId a, ObjectId b) {
        const double ca = _objectBounds[a].center()[axis];
        const double cb = _objectBounds[b].center()[axis];
        return ca < cb || (ca == cb && a < b);
    };
    std::nth_element(begin, begin + static_cast<std::ptrdiff_t>(half), begin + static_cast<std::ptrdiff_t>(count),
                     byCentre);
    const double position = _objectBounds[ids[first + half]].center()[axis];
    const std::uint32_t left = buildNode(ids, first, half, index);
    const std::uint32_t right = buildNode(ids, first + half, count - half, index);
    Node& node = _nodes[index];
    node.left = left;
    node.right = right;
    node.axis = static_cast<std::uint8_t>(axis);
    node.splitPosition = position;
    return true;
}

std::uint32_t MaskKdTree::leafOf(ObjectId id) const
{
    return id < _leafOf.size() ? _leafOf[id] : None;
}

void MaskKdTree::ensureObject(ObjectId id)
{
    if (id < _leafOf.size())
        return;
    _objectBounds.resize(std::size_t(id) + 1);
    _leafOf.resize(std::size_t(id) + 1, None);
    _objectStamp.resize(std::size_t(id) + 1, 0.0);
}

void MaskKdTree::insert(ObjectId id, const Aabb& bounds)
{
    move(id, bounds);
}

void MaskKdTree::remove(ObjectId id)
{
    if (!contains(id))
        return;
    detach(id);
    ++_updates;
}

void MaskKdTree::move(ObjectId id, const Aabb& bounds)
{
    ensureObject(id);
    detach(id);
    attach(id, bounds);
    ++_updates;
}

void MaskKdTree::detach(ObjectId id)
{
    _objectStamp[id] = 0.0;
    const std::uint32_t leaf = _leafOf[id];
    if (leaf == None)
        return;
    std::vector<ObjectId>& objects = _nodes[leaf].objects;
    objects.erase(std::find(objects.begin(), objects.end(), id));
    for (std::uint32_t n = leaf; n != None; n = _nodes[n].parent)
        --_nodes[n].objectCount;
    _leafOf[id] = None;
}

void MaskKdTree::attach(ObjectId id, const Aabb& bounds)
{
    _objectBounds[id] = bounds;
    if (!usable(bounds))
        return;
    // An empty tree keeps the split axes of its build (z up when that scene was empty too).
    if (_nodes.empty())
        _nodes.emplace_back();

    const Vec3 centre = bounds.center();
    std::uint32_t leaf = root();
    while (!_nodes[leaf].leaf())
    {
        const Node& node = _nodes[leaf];
        leaf = squaredDistance(centre, _nodes[node.right].bounds) < squaredDistance(centre, _nodes[node.left].bounds)
                   ? node.right
                   : node.left;
    }
    clearStampsUpFrom(leaf);
    _nodes[leaf].objects.push_back(id);
    _leafOf[id] = leaf;
    growUpFrom(leaf, bounds);

    if (_nodes[leaf].objects.size() > 2 * std::size_t(_maxLeafObjects))
    {
        // The leaf's stamp is clear (just pushed to its objects), so its new children start clear too.
        std::vector<ObjectId> objects = std::move(_nodes[leaf].objects);
        _nodes[leaf].objects.clear();
        if (!splitNode(leaf, objects, 0, objects.size()))
            _nodes[leaf].objects = std::move(objects);
    }
}

void MaskKdTree::clearStampsUpFrom(std::uint32_t node)
{
    std::vector<std::uint32_t> path;
    for (std::uint32_t n = node; n != None; n = _nodes[n].parent)
        path.push_back(n);
    // Root first, so a stamp high up travels down the whole path before the path is cleared.
    for (auto it = path.rbegin(); it != path.rend(); ++it)
    {
        Node& current = _nodes[*it];
        if (current.leaf())
        {
            for (const ObjectId id : current.objects)
                _objectStamp[id] = std::max(_objectStamp[id], current.stamp);
        }
        else
        {
            _nodes[current.left].stamp = std::max(_nodes[current.left].stamp, current.stamp);
            _nodes[current.right].stamp = std::max(_nodes[current.right].stamp, current.stamp);
        }
        current.stamp = 0.0;
    }
}

void MaskKdTree::growUpFrom(std::uint32_t node, const Aabb& bounds)
{
    for (std::uint32_t n = node; n != None; n = _nodes[n].parent)
    {
        _nodes[n].bounds.expand(bounds);
        ++_nodes[n].objectCount;
    }
}

void MaskKdTree::markNode(std::uint32_t node, double until)
{
    if (node < _nodes.size())
        _nodes[node].stamp = std::max(_nodes[node].stamp, until);
}

void MaskKdTree::markObject(ObjectId id, double until)
{
    if (contains(id))
        _objectStamp[id] = std::max(_objectStamp[id], until);
}

bool MaskKdTree::hidden(ObjectId id, double time) const
{
    const std::uint32_t leaf = leafOf(id);
    if (leaf == None)
        return false;
    if (_objectStamp[id] > time)
        return true;
    for (std::uint32_t n = leaf; n != None; n = _nodes[n].parent)
    {
        if (_nodes[n].stamp > time)
            return true;
    }
    return false;
}

void MaskKdTree::clearMarks()
{
    std::fill(_objectStamp.begin(), _objectStamp.end(), 0.0);
    for (Node& node : _nodes)
        node.stamp = 0.0;
}
} // namespace osgVis::core
