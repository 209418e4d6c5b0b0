// SPDX-License-Identifier: MIT
#pragma once

#include <osg/BoundingBox>
#include <osg/Vec3d>

#include <cstdint>
#include <vector>

namespace osgVis::oracle
{
struct WorldTriangle
{
    osg::Vec3d a, b, c;
    std::uint32_t object = 0;
    bool cullsCounterClockwise = false; // by winding as seen from the eye
    bool cullsClockwise = false;
};

// A segment origin + t·direction, t in [0, 1]: from the near plane to the far plane.
struct Ray
{
    osg::Vec3d origin;
    osg::Vec3d direction;
    osg::Vec3d inverseDirection;
};

// Bounding volume hierarchy over world triangles (median split on the widest centroid axis), for
// the oracle's ray casting. Hits: Möller–Trumbore, edges inclusive, edge-on triangles never hit.
class TriangleBvh
{
public:
    explicit TriangleBvh(std::vector<WorldTriangle> triangles);

    std::size_t size() const { return _triangles.size(); }

    // Nearest hit with t < tMax; false when none.
    bool nearest(const Ray& ray, double tMax, double& t, std::uint32_t& object) const;

    // Calls onHit(object) for every triangle hit with t < tMax, in no particular order.
    template <class OnHit> void forEachHit(const Ray& ray, double tMax, OnHit&& onHit) const;

private:
    struct Node
    {
        osg::BoundingBoxd bounds;
        std::uint32_t first = 0; // leaf: first triangle; inner: left child (right child = left + 1)
        std::uint32_t count = 0; // leaf: triangle count; inner: 0
    };

    void build(std::uint32_t index, std::uint32_t first, std::uint32_t count, std::vector<osg::Vec3d>& centroids);
    // Depth-first over the nodes whose box the ray enters before `tMax` (read at each test, so
    // onHit may lower it): an inner node's children go on the stack by pushChildren(node, stack,
    // top), and onHit(triangle, t) is called for each triangle of a leaf hit with t < tMax.
    template <class PushChildren, class OnHit>
    void walk(const Ray& ray, const double& tMax, PushChildren&& pushChildren, OnHit&& onHit) const;
    bool hitsBox(const Ray& ray, const osg::BoundingBoxd& box, double tMax, double& tEnter) const;
    bool hitsTriangle(const Ray& ray, const WorldTriangle& triangle, double tMax, double& t) const;

    std::vector<WorldTriangle> _triangles;
    std::vector<Node> _nodes;
};

template <class PushChildren, class OnHit>
void TriangleBvh::walk(const Ray& ray, const double& tMax, PushChildren&& pushChildren, OnHit&& onHit) const
{
    if (_nodes.empty())
        return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
        const Node& node = _nodes[stack[--top]];
        double tEnter;
        if (!hitsBox(ray, node.bounds, tMax, tEnter))
            continue;
        if (node.count == 0)
        {
            pushChildren(node, stack, top);
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        {
            double t;
            if (hitsTriangle(ray, _triangles[i], tMax, t))
                onHit(_triangles[i], t);
        }
    }
}

template <class OnHit> void TriangleBvh::forEachHit(const Ray& ray, double tMax, OnHit&& onHit) const
{
    walk(
        ray, tMax,
        [](const Node& node, std::uint32_t* stack, int& top)
        {
            stack[top++] = node.first;
            stack[top++] = node.first + 1;
        },
        [&](const WorldTriangle& triangle, double) { onHit(triangle.object); });
}
} // namespace osgVis::oracle
