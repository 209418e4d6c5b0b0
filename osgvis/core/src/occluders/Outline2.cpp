// SPDX-License-Identifier: MIT
#include "Outline2.h"

#include <algorithm>
#include <numeric>

namespace osgVis::core
{
std::vector<std::size_t> convexHullIndices(const Outline2& points)
{
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(),
              [&](std::size_t i, std::size_t j)
              {
                  const Point2 &a = points[i], &b = points[j];
                  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && i < j)));
              });
    if (order.size() < 3)
        return order;
    // Monotone chain.
    std::vector<std::size_t> hull(2 * order.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < order.size(); ++i)
    {
        while (k >= 2 && cross2(points[hull[k - 2]], points[hull[k - 1]], points[order[i]]) <= 0.0)
            --k;
        hull[k++] = order[i];
    }
    for (std::size_t i = order.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && cross2(points[hull[k - 2]], points[hull[k - 1]], points[order[i]]) <= 0.0)
            --k;
        hull[k++] = order[i];
    }
    hull.resize(k - 1);
    return hull;
}

std::vector<std::size_t> convexUnionIndices(const Outline2& a, const Outline2& b, std::size_t maxCorners)
{
    Point2 loA(1e300), hiA(-1e300), loB(1e300), hiB(-1e300);
    for (const Point2& p : a)
    {
        loA = glm::min(loA, p);
        hiA = glm::max(hiA, p);
    }
    for (const Point2& p : b)
    {
        loB = glm::min(loB, p);
        hiB = glm::max(hiB, p);
    }
    if (loA.x > hiB.x || loB.x > hiA.x || loA.y > hiB.y || loB.y > hiA.y)
        return {};
    Outline2 points = a;
    points.insert(points.end(), b.begin(), b.end());
    std::vector<std::size_t> hull = convexHullIndices(points);
    if (hull.size() < 3 || hull.size() > maxCorners)
        return {};
    Outline2 outline;
    for (std::size_t i : hull)
        outline.push_back(points[i]);
    const double shared = signedArea(convexIntersection(a, b));
    const double covered = signedArea(a) + signedArea(b) - std::max(shared, 0.0);
    // note: only rounding may separate the two; any real gap or notch adds hull area
    if (signedArea(outline) > covered * (1.0 + 1e-9))
        return {};
    return hull;
}
} // namespace osgVis::core
