// SPDX-License-Identifier: MIT
#pragma once
// Internal to the mask rasterizer: its inner loop exists twice, SSE2 (4 pixels per step) and
// portable scalar code doing the same float operations lane by lane. Both are reachable here so a
// test can check that they agree bit for bit; rasterizeOccluderGroup() takes the SSE2 one where
// the compiler targets it.
#include <osgVis/core/mask/MaskRasterizer.h>

#include <cstddef>

namespace osgVis::core
{
enum class MaskRasterPath
{
    Scalar,
    Simd // falls back to Scalar where SSE2 is not available
};

bool maskRasterHasSimd();

std::size_t rasterizeOccluderGroupWith(MaskRasterPath path, OcclusionMask& mask, const ScreenPolygon* polygons,
                                       std::size_t count, double shrink, MaskRasterScratch& scratch);
} // namespace osgVis::core
