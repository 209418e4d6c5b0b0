// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A correspondence plane of the multifocal z-buffer (Marsden & Guibas, §4.1, §5.3): an axial
/// plane P beyond one face of the view volume V, a window of square pixels on it, and h(x), the
/// signed distance of x from P, positive towards V. Along every ray from a point of V, h is affine
/// and decreasing, on both sides of P (docs/multifocal.md, "One test for both sides").
#include <osgVis/core/geometry/ConvexArea2.h>

#include <osgVis/core/geometry/Aabb.h>

#include <array>
#include <cmath>

namespace osgVis::core
{
struct CorrespondencePlane
{
    int axis = 0;           ///< P is { x : x[axis] = position }
    int direction = 1;      ///< +1: P lies at larger coordinates than V, -1: smaller
    double position = 0.0;
    int u = 1, v = 2;       ///< the plane's own axes (the other two, ascending)
    Vec2 origin{0.0};       ///< the window's lower corner
    double pixel = 1.0;     ///< pixel edge length (square pixels)
    int width = 0, height = 0;

    double h(const Vec3& x) const { return direction * (position - x[axis]); }
    Vec2 onPlane(const Vec3& x) const { return Vec2(x[u], x[v]); }
    Vec3 lift(const Vec2& q) const
    {
        Vec3 x(0.0);
        x[axis] = position;
        x[u] = q.x;
        x[v] = q.y;
        return x;
    }
    /// Where the line from `from` through `x` meets P; needs h(from) > h(x).
    Vec2 project(const Vec3& from, const Vec3& x) const
    {
        const double hf = h(from);
        const double t = hf / (hf - h(x));
        return Vec2(from[u] + t * (x[u] - from[u]), from[v] + t * (x[v] - from[v]));
    }
    Vec2 windowMax() const { return origin + Vec2(width * pixel, height * pixel); }
    /// The square of pixel (i, j), counter-clockwise.
    ConvexArea2 square(int i, int j) const
    {
        const double x0 = origin.x + i * pixel, y0 = origin.y + j * pixel;
        return {Vec2(x0, y0), Vec2(x0 + pixel, y0), Vec2(x0 + pixel, y0 + pixel), Vec2(x0, y0 + pixel)};
    }
};

/// The eight corners of a box.
inline std::array<Vec3, 8> boxCorners(const Aabb& box)
{
    std::array<Vec3, 8> c;
    for (int k = 0; k < 8; ++k)
        c[k] = Vec3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z);
    return c;
}
} // namespace osgVis::core
