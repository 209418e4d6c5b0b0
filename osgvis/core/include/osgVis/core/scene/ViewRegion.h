// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A region of viewpoints: every eye inside an axial box, looking in any direction, with a
/// perspective projection whose near plane lies within given bounds. A module's answer for a
/// region (VisibilityModule::cullRegion) holds for every view the region holds, so a renderer can
/// compute it ahead of time, off its cull thread, and use it for as long as the eye stays inside.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/scene/View.h>

namespace osgVis::core
{
struct ViewRegion
{
    Aabb eyes;                 ///< every eye position the answer holds for
    double minNearDistance = 0.0; ///< nearest near plane of a view it holds for (depth precision)
    double maxNearReach = 0.0;    ///< farthest near-plane corner from the eye (clipped geometry)
    std::uint32_t depthBits = 24; ///< fewest depth-buffer bits of a view it holds for (depth precision)

    /// The box's centre and half extents (the eye volume occlusion tests take).
    Vec3 center() const { return eyes.center(); }
    Vec3 halfExtent() const { return eyes.extent() * 0.5; }

    /// True when `view` is one the region's answer holds for: a perspective view whose eye lies in
    /// `eyes`, whose near plane is neither nearer than minNearDistance nor reaches farther than
    /// maxNearReach, and whose depth buffer has at least depthBits.
    bool holds(const View& view) const
    {
        if (view.orthographic || eyes.empty() || !eyes.contains(view.eye))
            return false;
        return nearDistance(view) >= minNearDistance && nearPlaneReach(view) <= maxNearReach &&
               view.depthBits >= depthBits;
    }
};
} // namespace osgVis::core
