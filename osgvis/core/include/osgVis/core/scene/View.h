// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// One viewpoint as a renderer hands it to the visibility core.
#include <osgVis/core/geometry/Frustum.h>

#include <cstdint>

namespace osgVis::core
{
struct View
{
    Vec3 eye{0.0};
    Mat4 viewMatrix{1.0};       ///< world → eye (GL convention, looking down -z)
    Mat4 projectionMatrix{1.0}; ///< eye → clip
    Frustum frustum;            ///< derived from projection * view by makeView
    double time = 0.0;          ///< walk time in seconds (never the wall clock)
    std::uint32_t viewportWidth = 1280, viewportHeight = 1024;
    bool orthographic = false;
    /// Bits of the depth buffer the view draws into: depth-tie margins (cdt, multifocal) take the
    /// resolution from it (docs/cdt.md, docs/multifocal.md); the OSG adapter sets it from the context.
    std::uint32_t depthBits = 24;
};

/// Fills eye, frustum and orthographic from the two matrices.
View makeView(const Mat4& viewMatrix, const Mat4& projectionMatrix, double time = 0.0,
              std::uint32_t viewportWidth = 1280, std::uint32_t viewportHeight = 1024);

/// Distance from the eye to the near plane along the view direction (perspective views; 0 when the
/// projection gives none).
double nearDistance(const View& view);
/// Largest distance from the eye to a corner of the near-plane rectangle: geometry closer than this
/// may be clipped away and so be seen through.
double nearPlaneReach(const View& view);
} // namespace osgVis::core
