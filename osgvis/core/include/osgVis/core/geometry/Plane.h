// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Oriented plane n·p + d = 0; positive distance is the "inside" (kept) half-space.
#include <osgVis/core/geometry/Math.h>

namespace osgVis::core
{
struct Plane
{
    Vec3 normal{0.0, 0.0, 1.0};
    double d = 0.0;

    Plane() = default;
    Plane(const Vec3& n, double offset) : normal(n), d(offset) {}
    /// Plane through p with normal n (not necessarily unit).
    static Plane fromPointNormal(const Vec3& p, const Vec3& n) { return {n, -glm::dot(n, p)}; }

    double distance(const Vec3& p) const { return glm::dot(normal, p) + d; }
    /// Scales to a unit normal; returns false (and leaves the plane unchanged) for a zero normal.
    bool normalize();
};
} // namespace osgVis::core
