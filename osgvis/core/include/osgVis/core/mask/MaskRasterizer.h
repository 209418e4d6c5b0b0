// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Conservative software rasterization of occluders into an OcclusionMask: only pixels that a group
/// of connected occluder polygons covers entirely count, and each such pixel receives the largest
/// depth the group has anywhere over the pixel's area (not at its centre: walls seen at grazing
/// angles would leak). Runs on any thread, no GL.
///
/// A *group* is a set of polygons (already projected to mask coordinates) that are connected by
/// shared edges and face the same way on screen, so that a shared edge lies inside the group's
/// union. Pixel p, grown by `shrink` pixels on every side (P), counts as covered when
///   - P touches at least one polygon of the group, and
///   - for every polygon Q of the group that P touches, P lies inside each *outline* edge of Q
///     (edges not marked shared).
/// Then P lies inside the union (a point of P outside it would sit beyond an outline edge of a
/// polygon P touches). Growing P by `shrink` is the same as shrinking the group's union by that
/// many pixels, which the conservative `mask` mode uses for temporal coherence.
#include <osgVis/core/mask/OcclusionMask.h>

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::core
{
/// Depth of a planar polygon over the screen. Perspective: 1/depth is affine in mask coordinates,
/// 1/depth = a·x + b·y + c; orthographic: depth = a·x + b·y + c. The largest depth over an
/// axis-aligned square is at one of its corners in both cases; a square where 1/depth reaches
/// zero or below (the plane meets the horizon there) has depth +infinity.
struct DepthPlane
{
    double a = 0.0, b = 0.0, c = 0.0;
    bool inverse = true; ///< true: the affine function is 1/depth (perspective)
    double maxOverSquare(double x0, double y0, double x1, double y1) const;
};

struct ScreenPolygon
{
    std::vector<glm::dvec2> vertices; ///< mask coordinates, convex, either winding
    std::vector<bool> sharedEdge;     ///< per edge i (vertices[i] → vertices[i+1]): lies inside the group's union
    DepthPlane depth;
};

/// Reusable buffers (one per thread), so rasterizing allocates nothing once warmed up. Copying one
/// gives fresh buffers (their contents never carry over between calls).
struct MaskRasterScratch
{
    std::vector<float> depth;         ///< the reference rasterizer's
    std::vector<std::uint8_t> state;  ///< the reference rasterizer's
    struct Tiles;                     ///< the tile rasterizer's polygon setups
    std::unique_ptr<Tiles> tiles;

    MaskRasterScratch();
    ~MaskRasterScratch();
    MaskRasterScratch(const MaskRasterScratch&);
    MaskRasterScratch& operator=(const MaskRasterScratch&);
    MaskRasterScratch(MaskRasterScratch&&) noexcept;
    MaskRasterScratch& operator=(MaskRasterScratch&&) noexcept;
};

/// Rasterizes one group into `mask` (keeping the nearer depth where pixels are already covered).
/// Degenerate polygons (fewer than 3 vertices, zero area, non-finite coordinates) veto every pixel
/// they touch: they are never trusted. Returns the number of pixels the group covered, except in
/// 8 × 8 tiles skipped because the mask there is already covered no farther than anything the group
/// could write (OcclusionMask::tileBound; the mask is the same as if they had been counted).
/// Works in tiles with AVX2 or SSE2 kernels (docs/mask.md, "The tile rasterizer"); covers exactly
/// the pixels the pixel-by-pixel reference covers, with depths never nearer than the reference's.
std::size_t rasterizeOccluderGroup(OcclusionMask& mask, const ScreenPolygon* polygons, std::size_t count,
                                   double shrink, MaskRasterScratch& scratch);
} // namespace osgVis::core
