// SPDX-License-Identifier: MIT
#pragma once
// Convex outlines in a plane's own 2-D coordinates, as the coplanar unions build them: the convex
// hull, and whether two convex outlines together are exactly their hull (so their union is one
// convex polygon). Area and intersection are geometry/ConvexArea2's.
#include <osgVis/core/geometry/ConvexArea2.h>

#include <cstddef>
#include <vector>

namespace osgVis::core
{
using Point2 = Vec2;
using Outline2 = ConvexArea2; // counter-clockwise unless said otherwise

/// Indices of `points` on their convex hull, counter-clockwise; collinear points are dropped.
std::vector<std::size_t> convexHullIndices(const Outline2& points);
/// Indices into a followed by b (b's offset by a.size()) of the hull of a ∪ b when that hull is
/// exactly their union (they overlap or abut and leave no notch or gap) and has at most
/// `maxCorners` corners; empty otherwise.
std::vector<std::size_t> convexUnionIndices(const Outline2& a, const Outline2& b, std::size_t maxCorners);
} // namespace osgVis::core
