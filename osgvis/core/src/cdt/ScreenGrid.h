// SPDX-License-Identifier: MIT
#pragma once
// How the CDT method sees a view: world → clip space → the record's integer grid (docs/cdt.md,
// "From the view to the grid"). The grid has a power of two units per pixel, so a pixel edge falls
// on grid lines, and spans the frame grown to twice its size (the guard band occluders are clipped
// to), within the record's exact range.
//
// Margins, in grid units: `tolerance` (τ) covers what the GPU's rasterizer may do differently from
// exact geometry (sub-pixel vertex snapping, 1/256 px in GL implementations, and the float
// transform): occluder edges that are not exactly shared with a drawn neighbour are eroded by τ,
// and every queried outline is dilated by τ. `lattice` is the coarser grid the endpoints of shared
// edges are rounded to, so that the integer segment between them has grid points to stop on.
#include <osgVis/core/cdt/CoverageTriangulation.h>
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/scene/View.h>

#include <algorithm>
#include <vector>

namespace osgVis::core
{
struct GridPolygon
{
    std::vector<cdt::GridPoint> points; ///< counter-clockwise
    cdt::AffineNearness nearness;
};

class ScreenGrid
{
public:
    /// False for views it cannot serve (degenerate viewport or matrices).
    bool set(const View& view, double tolerancePixels);

    std::int32_t limit() const { return _limit; }           ///< the record's rectangle is ±limit
    std::int32_t frameHalfWidth() const { return _halfW; }  ///< the frame is ±halfW × ±halfH
    std::int32_t frameHalfHeight() const { return _halfH; }
    double tolerance() const { return _tolerance; }
    double unitsPerPixel() const { return _unitsPerPixel; }
    /// Queried w must exceed a depth bound by this much to count as behind: 16 steps of the view's
    /// depth buffer (View::depthBits), uniform in w (1/z for a perspective view, NDC depth for an
    /// orthographic one).
    double depthMargin() const { return _depthMargin; }
    /// How far behind a point at most `distance` from the eye another point of the same ray must
    /// lie for their w to differ by depthMargin(), whatever the ray's angle to the view axis
    /// (docs/cdt.md, "Depth-free only clear of the cell's faces"); infinite where no gap does.
    double depthSeparation(double distance) const;

    /// The box's outline on the grid (convex, dilated by τ, clipped to the frame grown by τ) and the
    /// largest nearness of its points. False when the box reaches the near plane (its projection
    /// is unbounded: never hidden) or lies wholly outside the frame.
    bool projectBox(const Aabb& box, std::vector<cdt::GridPoint>& outline, double& nearestW) const;

    /// An occluder polygon (world space, convex) on the grid: clipped to the near plane and the
    /// guard band, made counter-clockwise, each edge i (vertices[i] → vertices[i+1]) eroded by τ
    /// unless `keepEdge[i]` (an edge exactly shared with a drawn neighbour; nullptr: none kept).
    /// False when nothing usable is left.
    bool projectOccluder(const std::vector<Vec3>& vertices, const std::vector<bool>* keepEdge, GridPolygon& out) const;

    /// Which side of the screen line through a and b the point p projects to (+1 left, -1 right),
    /// 0 when one of them lies behind the near plane or on the line.
    int sideOf(const Vec3& a, const Vec3& b, const Vec3& p) const;

private:
    Mat4 _worldToClip{1.0};
    bool _orthographic = false;
    double _scaleX = 1.0, _scaleY = 1.0; ///< grid units per NDC unit
    double _unitsPerPixel = 1.0, _tolerance = 0.0, _lattice = 1.0, _depthMargin = 0.0;
    double _orthographicDepthScale = 1.0; // |d NDC depth / d eye z| of an orthographic view
    std::int32_t _limit = 0, _halfW = 0, _halfH = 0;
};
} // namespace osgVis::core
