// SPDX-License-Identifier: MIT
#pragma once
// Internal to the mask rasterizers, so that the tests can reach every path:
//   - the reference rasterizer (pixel by pixel, MaskReferenceRasterizer.cpp), whose inner loop
//     exists as SSE2 (4 pixels per step) and portable scalar code doing the same float operations;
//   - the tile rasterizer (MaskRasterizer.cpp) with its AVX2 or SSE2 tile kernels
//     (MaskTileKernels.h), which must agree bit for bit.
// rasterizeOccluderGroup() is the tile rasterizer with the best kernel the CPU runs.
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

std::size_t rasterizeOccluderGroupReference(MaskRasterPath path, OcclusionMask& mask, const ScreenPolygon* polygons,
                                            std::size_t count, double shrink, MaskRasterScratch& scratch);

enum class MaskTileKernel
{
    Sse2,
    Avx2 // only where the CPU has it (maskTileKernelAvailable)
};

bool maskTileKernelAvailable(MaskTileKernel kernel);

std::size_t rasterizeOccluderGroupTiled(MaskTileKernel kernel, OcclusionMask& mask, const ScreenPolygon* polygons,
                                        std::size_t count, double shrink, MaskRasterScratch& scratch);
} // namespace osgVis::core
