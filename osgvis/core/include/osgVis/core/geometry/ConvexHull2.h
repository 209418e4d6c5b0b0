// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The convex hull of points of a plane by Andrew's monotone chain, for any point type with
/// members x and y and an orientation test of matching precision (the CDT's integer grid points,
/// the occlusion tree's image-plane doubles).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace osgVis::core
{
/// Replaces `points` by their convex hull, counter-clockwise, repeated and collinear points
/// dropped; fewer than three distinct points stay, sorted by x, then y. turn(o, a, b) is positive
/// when o → a → b turns left. `hull` is scratch.
template <class P, class Turn> void convexHullInPlace(std::vector<P>& points, std::vector<P>& hull, Turn&& turn)
{
    std::sort(points.begin(), points.end(),
              [](const P& a, const P& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(
        std::unique(points.begin(), points.end(), [](const P& a, const P& b) { return a.x == b.x && a.y == b.y; }),
        points.end());
    if (points.size() < 3)
        return;
    hull.resize(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    points.swap(hull);
}
} // namespace osgVis::core
