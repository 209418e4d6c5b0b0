#include "OcclusionTree.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
using Point = OcclusionTree::Point;

// Image-plane coordinates are tangents of angles: this much is "on the line".
constexpr double ImageEpsilon = 1e-12;

double cross(const Point& o, const Point& a, const Point& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Convex hull (counter-clockwise, Andrew's monotone chain); one or two points stay as they are.
void convexHull(std::vector<Point>& points)
{
    std::sort(points.begin(), points.end(),
              [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
        return;
    std::vector<Point> hull(2 * points.size());
    std::size_t k = 0;
    for (const Point& p : points)
    {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0)
            --k;
        hull[k++] = p;
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    points.swap(hull);
}

// The part of a convex polygon (or segment, or point) on one side of the line; vertices within
// ImageEpsilon of it stay on both sides.
template <class Line>
std::vector<Point> clipped(const std::vector<Point>& polygon, const Line& line, bool keepPositive)
{
    std::vector<Point> out;
    const std::size_t n = polygon.size();
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
    return out;
}

template <class Line> void extremes(const std::vector<Point>& polygon, const Line& line, double& lowest, double& highest)
{
    lowest = highest = line.at(polygon[0]);
    for (std::size_t i = 1; i < polygon.size(); ++i)
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

bool OcclusionTree::insert(const std::vector<Vec3>& vertices, const Plane& plane, const std::vector<double>& edgeMargins)
{
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
    _occluders.push_back({plane, maxDistance});
    insertFragment(Slot{-1, true}, _image, vertices, std::uint32_t(_occluders.size() - 1));
    return true;
}

OcclusionTree::Ref& OcclusionTree::at(Slot slot)
{
    if (slot.node < 0)
        return _root;
    Node& node = _nodes[std::size_t(slot.node)];
    return slot.positive ? node.positive : node.negative;
}

void OcclusionTree::insertFragment(Slot slot, const std::vector<Point>& fragment, const std::vector<Vec3>& polygon,
                                   std::uint32_t occluder)
{
    const Ref ref = at(slot);
    if (ref >= 0)
    {
        const Line line = _nodes[std::size_t(ref)].line;
        double lowest, highest;
        extremes(fragment, line, lowest, highest);
        if (lowest >= -ImageEpsilon || highest <= ImageEpsilon)
        {
            // Wholly on one side (a fragment lying on the line goes to the positive side).
            insertFragment(Slot{ref, lowest >= -ImageEpsilon}, fragment, polygon, occluder);
            return;
        }
        const std::vector<Point> positive = clipped(fragment, line, true);
        const std::vector<Point> negative = clipped(fragment, line, false);
        if (positive.size() >= 3)
            insertFragment(Slot{ref, true}, positive, polygon, occluder);
        if (negative.size() >= 3)
            insertFragment(Slot{ref, false}, negative, polygon, occluder);
        return;
    }

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
    const Ref inside = InLeaf - Ref(_leaves.size() - 1);
    const Ref replaced = chain(inside, ref);
    at(slot) = replaced;
}

// Nodes for the current occluder's edge lines, one under another: inside all of them `inside`,
// outside any of them what the slot held before.
OcclusionTree::Ref OcclusionTree::chain(Ref inside, Ref outside)
{
    Ref next = inside;
    for (std::size_t i = _edgeLines.size(); i-- > 0;)
    {
        _nodes.push_back({_edgeLines[i], next, outside});
        next = Ref(_nodes.size() - 1);
    }
    return next;
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
    std::vector<Point>& image = _queryImage;
    image.resize(count);
    for (std::size_t i = 0; i < count; ++i)
        if (!project(points[i], image[i]))
            return false; // reaches beside or behind the eye
    convexHull(image);
    const double nearest = bounds.distance(_eye); // the hull lies in the bounds: no nearer

    _stack.clear();
    _stack.emplace_back(_root, image);
    while (!_stack.empty())
    {
        const Ref ref = _stack.back().first;
        std::vector<Point> region = std::move(_stack.back().second);
        _stack.pop_back();
        if (ref == Out)
            return false;
        if (ref < 0)
        {
            if (!hiddenInLeaf(_leaves[std::size_t(InLeaf - ref)], points, count, nearest, depthTolerance))
                return false;
            continue;
        }
        const Node& node = _nodes[std::size_t(ref)];
        double lowest, highest;
        extremes(region, node.line, lowest, highest);
        if (lowest >= 0.0)
            _stack.emplace_back(node.positive, std::move(region));
        else if (highest < 0.0)
            _stack.emplace_back(node.negative, std::move(region));
        else
        {
            // The region crosses the line: each side goes on with its own part.
            std::vector<Point> positive = clipped(region, node.line, true);
            std::vector<Point> negative = clipped(region, node.line, false);
            if (!negative.empty())
                _stack.emplace_back(node.negative, std::move(negative));
            if (!positive.empty())
                _stack.emplace_back(node.positive, std::move(positive));
        }
    }
    return true;
}
} // namespace osgVis::core
