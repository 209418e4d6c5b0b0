// SPDX-License-Identifier: MIT
#include "OrbitWalk.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace osgVis::apps
{
core::Walk makeOrbitWalk(const core::Aabb& bounds, const OrbitWalkOptions& options)
{
    if (bounds.empty() || !std::isfinite(bounds.min.x + bounds.min.y + bounds.min.z + bounds.max.x +
                                         bounds.max.y + bounds.max.z))
        throw std::invalid_argument("makeOrbitWalk: the scene has no finite bounds");
    if (options.views == 0)
        throw std::invalid_argument("makeOrbitWalk: at least one view is needed");

    const core::Vec3 center = bounds.center();
    // note: a flat or point-like scene still needs a positive radius for the depth range.
    const double radius = std::max(0.5 * glm::length(bounds.extent()), 1e-3);
    const double distance = options.distanceFactor * radius;
    const double elevation = glm::radians(options.elevationDegrees);

    core::Walk walk;
    walk.width = options.width;
    walk.height = options.height;
    walk.projection.kind = core::WalkProjection::Kind::Perspective;
    walk.projection.fovY = options.fovYDegrees;
    // The whole sphere lies between distance - radius and distance + radius from every eye; keep a
    // margin on both sides and a near plane well inside the eye-to-sphere gap.
    walk.projection.zFar = distance + 1.5 * radius;
    walk.projection.zNear = std::max(walk.projection.zFar * 1e-4, 0.25 * (distance - radius));

    walk.keys.reserve(options.views);
    for (unsigned i = 0; i < options.views; ++i)
    {
        const double t = double(i) / double(options.views);
        const double azimuth = 2.0 * 3.14159265358979323846 * t;
        core::WalkKey key;
        key.time = t * options.secondsPerTurn;
        key.eye = center + distance * core::Vec3(std::cos(elevation) * std::cos(azimuth),
                                                 std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
        key.center = center;
        key.up = core::Vec3(0.0, 0.0, 1.0);
        walk.keys.push_back(key);
    }
    return walk;
}
} // namespace osgVis::apps
