// SPDX-License-Identifier: MIT
#pragma once
// The one length below which cell subdivision treats two coordinates as equal: a little above what
// single-precision triangle storage moves a vertex, far below any real gap (a 1 cm slit survives).
#include <osgVis/core/geometry/Aabb.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
inline double subdivisionTolerance(const Aabb& box)
{
    if (box.empty())
        return 1e-9;
    const double diagonal = glm::length(box.extent());
    const Vec3 magnitude = glm::max(glm::abs(box.min), glm::abs(box.max));
    const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    // 2.4e-7 ≈ two float ulps relative to the largest coordinate.
    return 1e-7 * diagonal + 2.4e-7 * largest + 1e-9;
}
} // namespace osgVis::core
