// SPDX-License-Identifier: MIT
#include "OcclusionTree.h"

#include <osgVis/core/geometry/ConvexHull2.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
using Point = OcclusionTree::Point;

// Image-plane coordinates are tangents of angles: this much is "on the line".
constexpr double ImageEpsilon = 1e-12;
// A fragment vertex this close to an edge line (relative to its size) touches it; far above the
// rounding of clipped vertices, so a line the fragment really touches is never left out.
constexpr double TouchTolerance = 1e-9;

double cross(const Point& o, const Point& a, const Point& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Appends to `out` the part of a convex polygon (or segment, or point) on one side of the line;
// vertices within ImageEpsilon of it stay on both sides. `polygon` must not live in `out`.
template <class Line>
void clipInto(const Point* polygon, std::size_t n, const Line& line, bool keepPositive, std::vector<Point>& out)
{
    const double sign = keepPositive ? 1.0 : -1.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const std::size_t j = (i + 1) % n;
        const double di = sign * line.at(polygon[i]), dj = sign * line.at(polygon[j]);
        if (di >= -ImageEpsilon)
            out.push_back(polygon[i]);
        if ((di > ImageEpsilon && dj < -ImageEpsilon) || (di < -ImageEpsilon && dj > ImageEpsilon))
            out.push_back(polygon[i] + (polygon[j] - polygon[i]) * (di / (di - dj)));
    }
}

template <class Line>
void extremes(const Point* polygon, std::size_t n, const Line& line, double& lowest, double& highest)
{
    lowest = highest = line.at(polygon[0]);
    for (std::size_t i = 1; i < n; ++i)
    {
        const double d = line.at(polygon[i]);
        lowest = std::min(lowest, d);
        highest = std::max(highest, d);
    }
}
} // namespace

void OcclusionTree::reset(const Vec3& eye, const Vec3& forward, double sceneSize)
{
    _eye = eye;
    _forward = glm::normalize(forward);
    const Vec3 helper = std::abs(_forward.z) < 0.9 ? Vec3(0.0, 0.0, 1.0) : Vec3(1.0, 0.0, 0.0);
    _right = glm::normalize(glm::cross(_forward, helper));
    _up = glm::cross(_right, _forward);
    _sceneSize = std::max(sceneSize, 1e-9);
    _nodes.clear();
    _leaves.clear();
    _occluders.clear();
    _root = Out;
    _work = 0;
}

// Image of a point in front of the eye (false for one at, beside or behind it).
bool OcclusionTree::project(const Vec3& p, Point& image) const
{
    const Vec3 d = p - _eye;
    const double depth = glm::dot(d, _forward);
    if (!(depth > 1e-9 * _sceneSize) || !std::isfinite(depth))
        return false;
    image = Point(glm::dot(d, _right) / depth, glm::dot(d, _up) / depth);
    return std::isfinite(image.x) && std::isfinite(image.y);
}

bool OcclusionTree::insert(const std::vector<Vec3>& vertices, const Plane& plane,
                           const std::vector<double>& edgeMargins)
{
    _work += 1 + vertices.size();
    const std::size_t n = vertices.size();
    if (n < 3 || edgeMargins.size() != n || !(plane.distance(_eye) > 0.0))
        return false;
    _image.resize(n);
    Point centroid(0.0);
    double maxDistance = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!project(vertices[i], _image[i]))
            return false;
        centroid += _image[i] / double(n);
        maxDistance = std::max(maxDistance, glm::length(vertices[i] - _eye));
    }

    // One line per edge, the polygon's interior (its centroid) on the positive side, moved inward
    // so that it keeps at least the margin's angle: a tangent-plane distance t at radius r spans an
    // angle of at least t / (1 + r²).
    _edgeLines.clear();
    for (std::size_t i = 0; i < n; ++i)
    {
        const std::size_t j = (i + 1) % n;
        const Point a = _image[i], b = _image[j];
        Point normal(a.y - b.y, b.x - a.x);
        const double length = glm::length(normal);
        if (!(length > ImageEpsilon))
            return false; // an edge seen end-on
        normal /= length;
        double offset = -glm::dot(normal, a);
        if (glm::dot(normal, centroid) + offset < 0.0)
        {
            normal = -normal;
            offset = -offset;
        }
        const double nearer = std::min(glm::length(vertices[i] - _eye), glm::length(vertices[j] - _eye));
        const double radius2 = std::max(glm::dot(a, a), glm::dot(b, b));
        offset -= edgeMargins[i] / nearer * (1.0 + radius2);
        _edgeLines.push_back({normal, offset});
    }

    // Only the shrunk polygon joins the tree: clipped by its own edge lines, it is what every
    // leaf below may claim, and a polygon the margins shrink to nothing adds nothing.
    for (const Line& line : _edgeLines)
    {
        _clipped.clear();
        clipInto(_image.data(), _image.size(), line, true, _clipped);
        _image.swap(_clipped);
        if (_image.size() < 3)
            return false;
    }
    _occluders.push_back({plane, maxDistance});
    insertShrunkImage(vertices, std::uint32_t(_occluders.size() - 1));
    return true;
}

OcclusionTree::Ref& OcclusionTree::at(Slot slot)
{
    if (slot.node < 0)
        return _root;
    Node& node = _nodes[std::size_t(slot.node)];
    return slot.positive ? node.positive : node.negative;
}

// Pushes the part of _region on one side of the line as a fragment headed for `slot` (its points
// at the end of _arena), unless that part has no area.
void OcclusionTree::pushClipped(const Line& line, bool positive, Slot slot)
{
    const std::size_t begin = _arena.size();
    clipInto(_region.data(), _region.size(), line, positive, _arena);
    if (_arena.size() - begin >= 3)
        _fragments.push_back({slot, std::uint32_t(begin), std::uint32_t(_arena.size() - begin)});
    else
        _arena.resize(begin);
}

// Sends the shrunk image (_image) down the tree, split by every line it crosses; each fragment
// that reaches a leaf joins it. Fragments live on a stack whose points sit, in the same order, at
// the end of _arena, so nothing is allocated once the buffers have grown.
void OcclusionTree::insertShrunkImage(const std::vector<Vec3>& polygon, std::uint32_t occluder)
{
    _arena.assign(_image.begin(), _image.end());
    _fragments.clear();
    _fragments.push_back({Slot{-1, true}, 0, std::uint32_t(_image.size())});
    ++_work;
    while (!_fragments.empty())
    {
        ++_work;
        Fragment& top = _fragments.back();
        const Ref ref = at(top.slot);
        const Point* points = _arena.data() + top.begin;
        if (ref < 0)
        {
            addToLeaf(top.slot, ref, points, top.count, polygon, occluder);
            _arena.resize(top.begin);
            _fragments.pop_back();
            continue;
        }
        const Line line = _nodes[std::size_t(ref)].line;
        double lowest, highest;
        extremes(points, top.count, line, lowest, highest);
        if (lowest >= -ImageEpsilon || highest <= ImageEpsilon)
        {
            // Wholly on one side (a fragment lying on the line goes to the positive side).
            top.slot = Slot{ref, lowest >= -ImageEpsilon};
            continue;
        }
        _region.assign(points, points + top.count);
        _arena.resize(top.begin);
        _fragments.pop_back();
        pushClipped(line, true, Slot{ref, true});
        pushClipped(line, false, Slot{ref, false});
    }
}

// A fragment of the current occluder's shrunk image reaches a leaf: inside the occluder's edge
// lines the leaf becomes "in" (with one occluder more), outside them it stays what it was. Only
// the lines the fragment touches are needed: the leaf's cell is convex, so a cell part outside a
// line the fragment keeps clear of would join the fragment through a point on that line.
void OcclusionTree::addToLeaf(Slot slot, Ref ref, const Point* fragment, std::size_t count,
                              const std::vector<Vec3>& polygon, std::uint32_t occluder)
{
    Leaf leaf;
    if (ref != Out)
    {
        const Leaf& old = _leaves[std::size_t(InLeaf - ref)];
        if (old.count == MaxLeafOccluders || coversBehind(old, polygon))
            return; // nothing this fragment could add (or no room for it)
        leaf = old;
    }
    leaf.occluders[leaf.count++] = occluder;
    _leaves.push_back(leaf);
    Ref next = InLeaf - Ref(_leaves.size() - 1);
    for (std::size_t i = _edgeLines.size(); i-- > 0;)
    {
        const Line& line = _edgeLines[i];
        const bool touches = std::any_of(
            fragment, fragment + count,
            [&](const Point& p) { return line.at(p) <= TouchTolerance * (1.0 + std::abs(p.x) + std::abs(p.y)); });
        if (!touches)
            continue;
        _nodes.push_back({line, next, ref});
        next = Ref(_nodes.size() - 1);
    }
    at(slot) = next;
}

// An occluder of the leaf already hides everything behind the polygon: the polygon lies wholly
// behind (or on) its plane, so every ray meets that occluder first.
bool OcclusionTree::coversBehind(const Leaf& leaf, const std::vector<Vec3>& polygon) const
{
    for (std::uint32_t i = 0; i < leaf.count; ++i)
    {
        const Plane& plane = _occluders[leaf.occluders[i]].plane;
        if (std::all_of(polygon.begin(), polygon.end(),
                        [&](const Vec3& v) { return plane.distance(v) <= 1e-9 * _sceneSize; }))
            return true;
    }
    return false;
}

bool OcclusionTree::hiddenInLeaf(const Leaf& leaf, const Vec3* points, std::size_t count, double nearest,
                                 double depthTolerance) const
{
    for (std::uint32_t i = 0; i < leaf.count; ++i)
    {
        const Occluder& occluder = _occluders[leaf.occluders[i]];
        // Every ray of the leaf crosses the occluder; a hull farther than all of it, or wholly
        // behind its plane, is met later.
        if (nearest > occluder.maxDistance + depthTolerance)
            return true;
        double highest = occluder.plane.distance(points[0]);
        for (std::size_t p = 1; p < count; ++p)
            highest = std::max(highest, occluder.plane.distance(points[p]));
        if (highest < -depthTolerance)
            return true;
    }
    return false;
}

bool OcclusionTree::hidden(const Aabb& box, double depthTolerance) const
{
    if (box.empty())
        return false;
    Vec3 corners[8];
    for (int c = 0; c < 8; ++c)
        corners[c] = box.corner(c);
    return hidden(corners, 8, box, depthTolerance);
}

bool OcclusionTree::hidden(const Vec3* points, std::size_t count, const Aabb& bounds, double depthTolerance) const
{
    if (_root == Out || count == 0 || bounds.empty())
        return false;
    _work += 1 + count / 4;
    std::vector<Point>& image = _queryImage;
    image.resize(count);
    for (std::size_t i = 0; i < count; ++i)
        if (!project(points[i], image[i]))
            return false; // reaches beside or behind the eye
    convexHullInPlace(image, _queryRegion,
                      [](const Point& o, const Point& a, const Point& b) { return cross(o, a, b); });
    const double nearest = bounds.distance(_eye); // the hull lies in the bounds: no nearer

    // Regions on a stack, their points at the end of _queryArena in the same order.
    _queryArena.assign(image.begin(), image.end());
    _queryStack.clear();
    _queryStack.push_back({_root, 0, std::uint32_t(image.size())});
    while (!_queryStack.empty())
    {
        ++_work;
        QueryRegion& top = _queryStack.back();
        if (top.ref == Out)
            return false;
        const Point* region = _queryArena.data() + top.begin;
        if (top.ref < 0)
        {
            if (!hiddenInLeaf(_leaves[std::size_t(InLeaf - top.ref)], points, count, nearest, depthTolerance))
                return false;
            _queryArena.resize(top.begin);
            _queryStack.pop_back();
            continue;
        }
        const Node& node = _nodes[std::size_t(top.ref)];
        double lowest, highest;
        extremes(region, top.count, node.line, lowest, highest);
        if (lowest >= 0.0)
            top.ref = node.positive;
        else if (highest < 0.0)
            top.ref = node.negative;
        else
        {
            // The region crosses the line: each side goes on with its own part.
            _queryRegion.assign(region, region + top.count);
            _queryArena.resize(top.begin);
            _queryStack.pop_back();
            for (const bool positive : {false, true})
            {
                const std::size_t begin = _queryArena.size();
                clipInto(_queryRegion.data(), _queryRegion.size(), node.line, positive, _queryArena);
                if (_queryArena.size() > begin)
                    _queryStack.push_back({positive ? node.positive : node.negative, std::uint32_t(begin),
                                           std::uint32_t(_queryArena.size() - begin)});
            }
        }
    }
    return true;
}
} // namespace osgVis::core
