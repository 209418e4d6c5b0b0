// SPDX-License-Identifier: MIT
#pragma once
// Sets of axis-aligned rectangles in one plane (u, v coordinates of an AxialRect): the area of their
// union and the exact difference "a rectangle minus a union of rectangles" as few disjoint rectangles.
#include <osgVis/core/geometry/AxialRect.h>

#include <vector>

namespace osgVis::core
{
// Area of the union of `rects` (their axis and coordinate are ignored). O(n log n) sweep.
double unionArea(const std::vector<AxialRect>& rects);

// `region` minus the union of `holes`, as disjoint rectangles with region's axis and coordinate, in
// (vMin, uMin) order. Edges closer than `tolerance` count as one, so nothing thinner than
// `tolerance` is returned and a hole that covers a grid cell up to `tolerance` covers it; every
// uncovered slit at least `tolerance` wide is kept.
std::vector<AxialRect> subtractRects(const AxialRect& region, const std::vector<AxialRect>& holes, double tolerance);
} // namespace osgVis::core
