// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A rectangle lying in an axis-aligned plane (a cell face, a portal, an opaque axial face).
#include <osgVis/core/geometry/Aabb.h>

#include <algorithm>
#include <cstdint>

namespace osgVis::core
{
struct AxialRect
{
    std::uint8_t axis = 0;   ///< normal axis: 0 x, 1 y, 2 z
    double coordinate = 0.0; ///< position of the plane along `axis`
    /// Ranges along the two in-plane axes u = (axis+1)%3 and v = (axis+2)%3.
    double uMin = 0.0, uMax = 0.0, vMin = 0.0, vMax = 0.0;

    static int uAxis(int axis) { return (axis + 1) % 3; }
    static int vAxis(int axis) { return (axis + 2) % 3; }
    double area() const { return (uMax - uMin) * (vMax - vMin); }
    bool empty() const { return !(uMax > uMin) || !(vMax > vMin); }
    /// Corner i (0..3) counter-clockwise around +axis: (uMin,vMin), (uMax,vMin), (uMax,vMax), (uMin,vMax).
    Vec3 corner(int i) const
    {
        Vec3 p{0.0};
        p[axis] = coordinate;
        p[uAxis(axis)] = (i == 1 || i == 2) ? uMax : uMin;
        p[vAxis(axis)] = (i >= 2) ? vMax : vMin;
        return p;
    }
    Aabb bounds() const { return {corner(0), corner(2)}; }
    /// This rectangle with its u and v ranges cut to those of `box` (empty() when they miss).
    AxialRect clippedTo(const Aabb& box) const
    {
        AxialRect r = *this;
        const int u = uAxis(axis), v = vAxis(axis);
        r.uMin = std::max(uMin, box.min[u]);
        r.uMax = std::min(uMax, box.max[u]);
        r.vMin = std::max(vMin, box.min[v]);
        r.vMax = std::min(vMax, box.max[v]);
        return r;
    }
    /// This rectangle with its u and v ranges cut to those of `region` (of the same axis).
    AxialRect clippedTo(const AxialRect& region) const
    {
        AxialRect r = *this;
        r.uMin = std::max(uMin, region.uMin);
        r.uMax = std::min(uMax, region.uMax);
        r.vMin = std::max(vMin, region.vMin);
        r.vMax = std::min(vMax, region.vMax);
        return r;
    }
};
} // namespace osgVis::core
