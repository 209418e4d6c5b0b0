// SPDX-License-Identifier: MIT
#pragma once
// Geometry of a planar boundary loop given as welded vertex ids (counter-clockwise around a
// normal): how it turns at each vertex, which vertices are only straight-line points, and whether
// the outline is convex. Shared by the coplanar merge and the final output of the occluder builder.
#include <osgVis/core/geometry/Math.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
enum class Turn
{
    Straight, // continues in the same direction within the tolerance
    Convex,   // turns left around the normal
    Reflex    // turns right, or doubles back on itself
};

// How far single-precision storage may have moved a coordinate of this size (a few units in the
// last place of a float): scene triangles arrive as floats, so finer differences mean nothing.
double storageSlack(const Vec3& p);

// Turn at `b` walking a → b → c. `tolerance` is the sine of the largest bend still taken as
// straight; a vertex within storageSlack of the line a–c is straight as well.
Turn turnAt(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal, double tolerance);

// Indices into `loop` of the vertices that stay when straight-line vertices are dropped; a vertex
// with keep[i] set always stays (keep may be empty). Straightness is judged against the last vertex
// kept, so a slow curve keeps enough vertices to follow it.
std::vector<std::size_t> cornerIndices(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions,
                                       const Vec3& normal, double tolerance, const std::vector<bool>& keep = {});

// Newell normal of the loop (length = 2 × area).
Vec3 loopNormal(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions);

// True when the loop is a convex polygon of 3..maxCorners corners: no vertex repeats, the corners
// all turn left, the outline winds once, and every vertex lies within planeTolerance × size of
// its plane (plus storageSlack).
bool isConvexLoop(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions, const Vec3& normal,
                  double turnTolerance, double planeTolerance, std::uint32_t maxCorners);
} // namespace osgVis::core
