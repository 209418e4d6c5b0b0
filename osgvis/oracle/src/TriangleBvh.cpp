// SPDX-License-Identifier: MIT
#include "TriangleBvh.h"

#include <algorithm>
#include <cmath>

namespace osgVis::oracle
{
namespace
{
constexpr std::uint32_t LeafSize = 4;
} // namespace

TriangleBvh::TriangleBvh(std::vector<WorldTriangle> triangles)
    : _triangles(std::move(triangles))
{
    if (_triangles.empty())
        return;
    std::vector<osg::Vec3d> centroids(_triangles.size());
    for (std::size_t i = 0; i < _triangles.size(); ++i)
        centroids[i] = (_triangles[i].a + _triangles[i].b + _triangles[i].c) / 3.0;
    _nodes.reserve(2 * _triangles.size() / LeafSize + 1);
    _nodes.emplace_back();
    build(0, 0, std::uint32_t(_triangles.size()), centroids);
}

// Fills node `index` over triangles [first, first + count), then its subtree.
void TriangleBvh::build(std::uint32_t index, std::uint32_t first, std::uint32_t count,
                        std::vector<osg::Vec3d>& centroids)
{
    osg::BoundingBoxd bounds, centroidBounds;
    for (std::uint32_t i = first; i < first + count; ++i)
    {
        bounds.expandBy(_triangles[i].a);
        bounds.expandBy(_triangles[i].b);
        bounds.expandBy(_triangles[i].c);
        centroidBounds.expandBy(centroids[i]);
    }
    _nodes[index].bounds = bounds;

    const osg::Vec3d extent = centroidBounds._max - centroidBounds._min;
    const int axis = extent.x() >= extent.y() && extent.x() >= extent.z() ? 0 : (extent.y() >= extent.z() ? 1 : 2);
    if (count <= LeafSize || extent[axis] <= 0.0)
    {
        _nodes[index].first = first;
        _nodes[index].count = count;
        return;
    }

    // Median split: order a permutation, then apply it to triangles and centroids together.
    std::vector<std::uint32_t> order(count);
    for (std::uint32_t i = 0; i < count; ++i)
        order[i] = first + i;
    const std::uint32_t half = count / 2;
    std::nth_element(order.begin(), order.begin() + half, order.end(),
                     [&](std::uint32_t l, std::uint32_t r) { return centroids[l][axis] < centroids[r][axis]; });
    std::vector<WorldTriangle> triangles(count);
    std::vector<osg::Vec3d> centres(count);
    for (std::uint32_t i = 0; i < count; ++i)
    {
        triangles[i] = _triangles[order[i]];
        centres[i] = centroids[order[i]];
    }
    std::copy(triangles.begin(), triangles.end(), _triangles.begin() + first);
    std::copy(centres.begin(), centres.end(), centroids.begin() + first);

    const std::uint32_t left = std::uint32_t(_nodes.size());
    _nodes.resize(_nodes.size() + 2); // note: invalidates references into _nodes; use indices
    _nodes[index].first = left;
    _nodes[index].count = 0;
    build(left, first, half, centroids);
    build(left + 1, first + half, count - half, centroids);
}

bool TriangleBvh::hitsBox(const Ray& ray, const osg::BoundingBoxd& box, double tMax, double& tEnter) const
{
    double t0 = 0.0, t1 = tMax;
    for (int axis = 0; axis < 3; ++axis)
    {
        double near = (box._min[axis] - ray.origin[axis]) * ray.inverseDirection[axis];
        double far = (box._max[axis] - ray.origin[axis]) * ray.inverseDirection[axis];
        if (near > far)
            std::swap(near, far);
        // note: a NaN (0 · inf, ray in the slab's plane) must not reject the box
        if (near > t0)
            t0 = near;
        if (far < t1)
            t1 = far;
        if (t0 > t1)
            return false;
    }
    tEnter = t0;
    return true;
}

bool TriangleBvh::hitsTriangle(const Ray& ray, const WorldTriangle& triangle, double tMax, double& t) const
{
    const osg::Vec3d e1 = triangle.b - triangle.a;
    const osg::Vec3d e2 = triangle.c - triangle.a;
    const osg::Vec3d p = ray.direction ^ e2;
    const double det = e1 * p;
    // det > 0: counter-clockwise as seen from the ray's origin side
    if (det == 0.0 || (det > 0.0 && triangle.cullsCounterClockwise) || (det < 0.0 && triangle.cullsClockwise))
        return false;
    const double inverseDet = 1.0 / det;
    const osg::Vec3d s = ray.origin - triangle.a;
    const double u = (s * p) * inverseDet;
    if (u < 0.0 || u > 1.0)
        return false;
    const osg::Vec3d q = s ^ e1;
    const double v = (ray.direction * q) * inverseDet;
    if (v < 0.0 || u + v > 1.0)
        return false;
    t = (e2 * q) * inverseDet;
    return t >= 0.0 && t < tMax;
}

bool TriangleBvh::nearest(const Ray& ray, double tMax, double& t, std::uint32_t& object) const
{
    bool hit = false;
    walk(
        ray, tMax,
        [&](const Node& node, std::uint32_t* stack, int& top)
        {
            double tLeft = 0.0, tRight = 0.0;
            const bool left = hitsBox(ray, _nodes[node.first].bounds, tMax, tLeft);
            const bool right = hitsBox(ray, _nodes[node.first + 1].bounds, tMax, tRight);
            // push the farther first so the nearer is searched first and shrinks tMax
            if (left && right)
            {
                stack[top++] = tLeft <= tRight ? node.first + 1 : node.first;
                stack[top++] = tLeft <= tRight ? node.first : node.first + 1;
            }
            else if (left)
                stack[top++] = node.first;
            else if (right)
                stack[top++] = node.first + 1;
        },
        [&](const WorldTriangle& triangle, double tHit)
        {
            tMax = tHit;
            t = tHit;
            object = triangle.object;
            hit = true;
        });
    return hit;
}
} // namespace osgVis::oracle
