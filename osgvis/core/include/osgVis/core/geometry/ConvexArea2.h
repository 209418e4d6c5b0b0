// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Convex regions of a plane in its own 2-D coordinates (double precision): area, clipping by
/// half-planes, intersection, and the difference of a set of convex pieces and one convex region.
/// The coplanar unions of occluders/ and the multifocal z-buffer's umbrae and coverage maps are
/// made of them.
#include <osgVis/core/geometry/Math.h>

#include <vector>

namespace osgVis::core
{
using Vec2 = glm::dvec2;
/// Convex, counter-clockwise, no repeated closing vertex.
using ConvexArea2 = std::vector<Vec2>;

/// (a − o) × (b − o): positive when o → a → b turns left.
double cross2(const Vec2& o, const Vec2& a, const Vec2& b);

/// { x : dot(normal, x) <= offset }.
struct HalfPlane2
{
    Vec2 normal{0.0};
    double offset = 0.0;
    double excess(const Vec2& p) const { return normal.x * p.x + normal.y * p.y - offset; }
};

double signedArea(const ConvexArea2& area);
/// Reverses a clockwise outline; empties one with fewer than 3 vertices or no area.
void makeCounterClockwise(ConvexArea2& area);
/// The half-planes whose intersection is `area` (counter-clockwise), one per edge, each moved
/// inwards by `erosion` (world units on the plane): the eroded region lies inside the exact one.
void halfPlanesOf(const ConvexArea2& area, double erosion, std::vector<HalfPlane2>& out);
/// `out` = the part of `in` inside `h` (out may not alias in).
void clipInside(const ConvexArea2& in, const HalfPlane2& h, ConvexArea2& out);
/// `out` = the part of `in` outside `h` (excess >= 0).
void clipOutside(const ConvexArea2& in, const HalfPlane2& h, ConvexArea2& out);
/// The part of convex `subject` inside convex `clip` (both counter-clockwise).
ConvexArea2 convexIntersection(ConvexArea2 subject, const ConvexArea2& clip);
/// area ∩= every half-plane, in turn (`scratch` is reused); stops once nothing is left.
void clipInsideAll(ConvexArea2& area, const std::vector<HalfPlane2>& halfPlanes, ConvexArea2& scratch);
/// True when `area` holds at least 3 vertices and positive area.
bool hasArea(const ConvexArea2& area);

/// pieces −= region (given by its half-planes): each piece is cut along the region's edges; the
/// parts outside stay, the part inside goes.
/// Returns false, leaving `pieces` as they were, when more than `maxPieces` would remain.
bool subtractConvex(std::vector<ConvexArea2>& pieces, const std::vector<HalfPlane2>& region, std::size_t maxPieces);
} // namespace osgVis::core
