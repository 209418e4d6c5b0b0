// SPDX-License-Identifier: MIT
#pragma once
// Random convex polygons on the grid for the CDT record's tests (integer convex hulls).
#include <osgVis/core/cdt/CoverageTriangulation.h>
#include <osgVis/core/geometry/ConvexHull2.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace osgVis::test::cdt
{
using osgVis::core::cdt::GridPoint;

inline std::int64_t cross(GridPoint o, GridPoint a, GridPoint b)
{
    return (std::int64_t(a.x) - o.x) * (std::int64_t(b.y) - o.y) -
           (std::int64_t(a.y) - o.y) * (std::int64_t(b.x) - o.x);
}

/// Counter-clockwise convex hull (the library's monotone chain), repeated and collinear points dropped.
inline std::vector<GridPoint> hull(std::vector<GridPoint> p)
{
    std::vector<GridPoint> scratch;
    osgVis::core::convexHullInPlace(p, scratch, cross);
    return p;
}

/// A random convex polygon around (cx, cy) of about `size` grid units; `thin` squeezes it to a sliver.
inline std::vector<GridPoint> randomConvex(std::mt19937_64& rng, std::int64_t cx, std::int64_t cy, std::int64_t size,
                                           int points, bool thin)
{
    std::uniform_int_distribution<std::int64_t> d(-size, size);
    std::uniform_int_distribution<std::int64_t> dt(-std::max<std::int64_t>(1, size / 200),
                                                   std::max<std::int64_t>(1, size / 200));
    for (;;)
    {
        std::vector<GridPoint> p;
        for (int i = 0; i < points; ++i)
        {
            std::int64_t x = d(rng), y = thin ? dt(rng) : d(rng);
            if (thin)
                std::tie(x, y) = std::pair{x + y, x - y}; // a diagonal sliver
            p.push_back({std::int32_t(cx + x), std::int32_t(cy + y)});
        }
        auto h = hull(p);
        if (h.size() >= 3)
            return h;
    }
}
} // namespace osgVis::test::cdt
