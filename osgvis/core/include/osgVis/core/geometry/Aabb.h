// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Axis-aligned bounding box. An empty box has min > max and contains nothing.
#include <osgVis/core/geometry/Math.h>

#include <limits>

namespace osgVis::core
{
struct Aabb
{
    Vec3 min{std::numeric_limits<double>::max()};
    Vec3 max{std::numeric_limits<double>::lowest()};

    Aabb() = default;
    Aabb(const Vec3& lo, const Vec3& hi) : min(lo), max(hi) {}

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    Vec3 center() const { return (min + max) * 0.5; }
    Vec3 extent() const { return max - min; }
    void expand(const Vec3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Aabb& b)
    {
        if (b.empty())
            return;
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool contains(const Vec3& p) const
    {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
    }
    bool intersects(const Aabb& b) const
    {
        return !(b.min.x > max.x || b.max.x < min.x || b.min.y > max.y || b.max.y < min.y || b.min.z > max.z ||
                 b.max.z < min.z);
    }
    /// Distance from p to the nearest point of the box (0 inside it).
    double distance(const Vec3& p) const { return glm::length(p - glm::clamp(p, min, max)); }
    /// Corner i: bit 0 selects x max, bit 1 y max, bit 2 z max.
    Vec3 corner(int i) const { return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z}; }
    /// True when all six coordinates are finite (NaN or infinite input bounds are rejected upstream).
    bool finite() const;
};
} // namespace osgVis::core
