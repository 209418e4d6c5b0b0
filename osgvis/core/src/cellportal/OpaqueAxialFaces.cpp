// SPDX-License-Identifier: MIT
// Opaque axial faces for cell subdivision: the object-space occluder polygons (same eligibility,
// welding and coplanar merging), keeping only two-sided ones that are exactly axis-aligned
// rectangles. One-sided polygons hide from one side only, so a cell boundary behind them is open.
#include <osgVis/core/cellportal/CellSubdivision.h>
#include <osgVis/core/occluders/OccluderBuilder.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
// The axial rectangle `polygon` is, or false. Every vertex must lie on one axial plane and on the
// outline of its bounding rectangle, and every corner of that rectangle must be a vertex: a convex
// polygon meeting both is exactly the rectangle (extra vertices are collinear ones on its edges).
bool asAxialRect(const OccluderPolygon& polygon, AxialRect& out)
{
    const std::vector<Vec3>& vertices = polygon.vertices;
    if (vertices.size() < 4)
        return false;
    const Vec3 n = glm::abs(polygon.plane.normal);
    const int axis = (n.x >= n.y && n.x >= n.z) ? 0 : (n.y >= n.z ? 1 : 2);
    const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);

    Aabb box;
    for (const Vec3& p : vertices)
        box.expand(p);
    const double size = glm::length(box.extent());
    const Vec3 magnitude = glm::max(glm::abs(box.min), glm::abs(box.max));
    // Tight: the polygon builder's plane tolerance, plus two float ulps of the stored vertices.
    const double tolerance = 1e-6 * size + 2.4e-7 * std::max({magnitude.x, magnitude.y, magnitude.z});
    if (box.max[axis] - box.min[axis] > tolerance)
        return false;
    if (!(box.max[u] - box.min[u] > tolerance) || !(box.max[v] - box.min[v] > tolerance))
        return false;

    auto near = [tolerance](double a, double b) { return std::abs(a - b) <= tolerance; };
    bool corners[4] = {false, false, false, false};
    for (const Vec3& p : vertices)
    {
        const bool atUMin = near(p[u], box.min[u]), atUMax = near(p[u], box.max[u]);
        const bool atVMin = near(p[v], box.min[v]), atVMax = near(p[v], box.max[v]);
        if (!atUMin && !atUMax && !atVMin && !atVMax)
            return false; // off the outline: the polygon is not the rectangle
        corners[0] |= atUMin && atVMin;
        corners[1] |= atUMax && atVMin;
        corners[2] |= atUMax && atVMax;
        corners[3] |= atUMin && atVMax;
    }
    if (!(corners[0] && corners[1] && corners[2] && corners[3]))
        return false;

    double coordinate = 0.0;
    for (const Vec3& p : vertices)
        coordinate += p[axis];
    out.axis = std::uint8_t(axis);
    out.coordinate = coordinate / double(vertices.size());
    out.uMin = box.min[u];
    out.uMax = box.max[u];
    out.vMin = box.min[v];
    out.vMax = box.max[v];
    return true;
}
} // namespace

std::vector<OpaqueFace> findOpaqueAxialFaces(const Scene& scene)
{
    std::vector<OpaqueFace> faces;
    for (const OccluderPolygon& polygon : buildOccluderPolygons(scene))
    {
        AxialRect rect;
        if (!polygon.oneSided && asAxialRect(polygon, rect))
            faces.push_back({rect, polygon.owner});
    }
    return faces;
}
} // namespace osgVis::core
