// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Planar convex polygon (counter-clockwise seen from the side its normal points to), with
/// Sutherland–Hodgman clipping against a plane.
#include <osgVis/core/geometry/Plane.h>

#include <vector>

namespace osgVis::core
{
class ConvexPolygon
{
public:
    ConvexPolygon() = default;
    explicit ConvexPolygon(std::vector<Vec3> vertices) : _vertices(std::move(vertices)) {}

    const std::vector<Vec3>& vertices() const { return _vertices; }
    std::size_t size() const { return _vertices.size(); }
    bool empty() const { return _vertices.empty(); }

    /// Newell normal: length = 2 × area; zero for degenerate polygons.
    Vec3 newellNormal() const;
    double area() const;
    Vec3 centroid() const;
    /// Supporting plane with unit normal; false when the polygon is degenerate.
    bool plane(Plane& out) const;

    /// Keeps the part with distance >= 0. Returns an empty polygon if nothing remains.
    ConvexPolygon clipped(const Plane& plane) const;

    /// Rejects what must never be trusted as an occluder: fewer than 3 distinct vertices, area
    /// below `minArea`, non-finite coordinates, vertices off the plane by more than `planarTolerance`
    /// (relative to the polygon size), or a non-convex outline.
    bool isValidOccluder(double minArea = 1e-9, double planarTolerance = 1e-6) const;

private:
    std::vector<Vec3> _vertices;
};
} // namespace osgVis::core
