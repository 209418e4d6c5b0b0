// SPDX-License-Identifier: MIT
#include <osgVis/core/geometry/Plane.h>

#include <cmath>

namespace osgVis::core
{
bool Plane::normalize()
{
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length))
        return false;
    normal /= length;
    d /= length;
    return true;
}
} // namespace osgVis::core
