// SPDX-License-Identifier: MIT
#pragma once
// Internal to the mask rasterizers: one occluder polygon turned into signed edge functions and a
// depth function over grown pixel squares, shared by the per-pixel reference rasterizer and the
// tile rasterizer so that both decide a pixel with the same double-precision formula.
//
// Edge e: f_e(p) = n_e·p + offset_e is the signed distance (px) of point p inside the edge line.
// The pixel square grown by the shrink and centred at p reaches reach_e = (|n.x| + |n.y|)·h along
// n_e (h = 0.5 + shrink): the grown square lies inside the edge when f_e(p) ≥ reach_e (its corner
// that minimises f_e is inside) and touches the edge's half-plane when f_e(p) ≥ -reach_e (its
// corner that maximises f_e is). The polygon touches the square when every edge does and the
// polygon's bounding box meets it (separating axes of a convex polygon and a square).
#include <osgVis/core/mask/MaskRasterizer.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace osgVis::core::maskraster
{
// Polygons with more edges are vetoed (never trusted) rather than tracked in a heap array.
constexpr std::size_t MaxEdges = 64;
// Float edge values this close (px) to a threshold are re-decided in double.
constexpr float Ambiguity = 1e-4f;
// Relative size below which areas, cross products and edge lengths count as zero.
constexpr double RelativeTolerance = 1e-12;
constexpr float InfiniteDepth = std::numeric_limits<float>::infinity();

struct PixelRange
{
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

enum class Shape
{
    Convex,
    Degenerate, // vetoes its grown bounding box
    NonFinite   // what it touches is unknown: the whole group is untrusted
};

struct PolygonSetup
{
    PixelRange pixels; // its grown bounding box, clipped to the mask
    std::size_t edgeCount = 0;
    std::array<double, MaxEdges> nx, ny, offset, reach;
    std::array<bool, MaxEdges> outline;
    std::array<float, MaxEdges> slope, slopeY, reachF,
        insideLimit; // float nx, ny, reach; insideLimit: -inf for shared edges
    // Largest depth over the grown square centred at p, in the affine form v = da·x + db·y + dc:
    // the smallest 1/depth (perspective) or the largest depth (orthographic) over its corners.
    double da = 0.0, db = 0.0, dc = 0.0;
    float depthSlope = 0.0f, depthSlopeY = 0.0f, depthAbsMargin = 0.0f;
    bool inverse = true;
    // The plane itself (no corner spread), for depth bounds over larger rectangles.
    DepthPlane plane;
};

// False when a group draws nothing (no polygons, an empty mask, a non-finite shrink); else clamps the
// shrink at 0 (a negative shrink would grow the union: never conservative).
bool prepareGroup(std::size_t count, const OcclusionMask& mask, double& shrink);

// Grows `region` to hold `pixels` (an empty range leaves it).
void unite(PixelRange& region, const PixelRange& pixels);

// Fills `setup` (pixels even for degenerate polygons, so that they veto what they touch).
Shape setupPolygon(const ScreenPolygon& polygon, double shrink, const OcclusionMask& mask, PolygonSetup& setup);

// The double-precision decision for pixel (x, y) of a convex polygon inside its pixel range: does
// the grown square touch it, and does it reach beyond an outline edge?
void decidePixel(const PolygonSetup& setup, int x, int y, bool& touched, bool& outside);
} // namespace osgVis::core::maskraster
