// SPDX-License-Identifier: MIT
#include <osgVis/core/geometry/Aabb.h>

#include <cmath>

namespace osgVis::core
{
bool Aabb::finite() const
{
    for (int i = 0; i < 3; ++i)
    {
        if (!std::isfinite(min[i]) || !std::isfinite(max[i]))
            return false;
    }
    return true;
}
} // namespace osgVis::core
