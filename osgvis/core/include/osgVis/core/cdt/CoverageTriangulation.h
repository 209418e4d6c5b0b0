// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The occlusion record of Luka's CDT method ("Visibility culling with a constrained Delaunay
/// triangulation", §2.2.1-§2.2.3): a constrained Delaunay triangulation of the screen plane whose
/// constraint edges are the outlines of the occluders drawn so far, each triangle knowing whether it
/// is covered and by what. No resolution: occluders fuse at object precision, with no sub-pixel
/// gap and no shrinking.
///
/// Robust by construction (docs/cdt.md); never hides what is not covered: a triangle counts as
/// covered by an occluder only when an exact test shows it inside that occluder dilated by half a
/// grid unit (the Minkowski sum with [-1/2, 1/2]^2), so every hidden() answer lies in the union of
/// the dilated occluders whatever rounding did.
/// - Every vertex is a point of a fixed integer grid, |x|, |y| <= GridLimit. Orientation is exact in
///   64-bit integers, in-circle in 128-bit integers (differences need 30 bits, the in-circle
///   determinant about 4·30 + 4 bits).
/// - Constraint crossings are computed from the two *original* input segments (never from pieces
///   already split and rounded), then rounded to the grid; the pieces of a constraint may therefore
///   leave the exact segment by at most half a grid diagonal (the bound docs/cdt.md states and the
///   tests measure).
/// - Callers erode occluders and dilate queried outlines by more than that bound (inputs are already
///   in grid coordinates here), so rounding only makes answers more conservative.
///
/// Depth: every occluder may carry an affine "nearness" w(x, y) = a·x + b·y + c over the grid
/// (for a perspective view w = 1/z_eye of the occluder's plane, which is affine on screen; for an
/// orthographic one any affine function increasing towards the eye). A triangle keeps, over the
/// occluders covering it, the largest of their least w over the triangle (taken at its three
/// vertices, since w is affine): a box whose greatest w (its nearest point) is below that lies
/// behind an occluder at every point of the triangle.
///
/// Allocation: reset() keeps every buffer, so a frame's triangulation allocates nothing once the
/// buffers reached their steady size.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::core::cdt
{
/// Grid coordinates are limited to ±GridLimit so that every predicate is exact (docs/cdt.md).
constexpr std::int64_t GridLimit = std::int64_t(1) << 28;

struct GridPoint
{
    std::int32_t x = 0, y = 0;
};

/// w(x, y) = a·x + b·y + c over grid coordinates; `valid` false: the occluder gives no depth bound.
struct AffineNearness
{
    double a = 0.0, b = 0.0, c = 0.0;
    bool valid = false;
    double at(double x, double y) const { return a * x + b * y + c; }
};

/// How an occluder may be used (Luka §2.3.1).
enum class CoverKind : std::uint8_t
{
    /// It lies in a cell before every cell that is still to be tested and overlaps none of them:
    /// whatever it covers on screen is hidden, whatever the depth.
    DepthFree,
    /// It may overlap what is still to be tested (held by an inner node): it hides a box only where
    /// its depth bound lies in front of the box.
    DepthOnly,
};

/// How a query may use the record.
enum class QueryMode : std::uint8_t
{
    DepthFree, ///< covered by a DepthFree occluder, or (with a nearness) behind a depth bound
    DepthOnly, ///< only depth bounds count (a box that depth-free occluders may not hide)
};

struct CoverageStatistics
{
    std::uint32_t vertices = 0, triangles = 0;
    std::uint32_t occludersInserted = 0, occludersRefused = 0; ///< refused: budget or degenerate input
    std::uint32_t constraintEdges = 0, crossings = 0, flips = 0;
    std::uint32_t queries = 0, queryTrianglesVisited = 0;
    /// Crossings whose original segments did not meet (their pieces did, after rounding): rounded
    /// from the pieces' crossing instead (docs/cdt.md).
    std::uint32_t roundingFallbacks = 0;
};

class CoverageTriangulation
{
public:
    CoverageTriangulation();
    ~CoverageTriangulation();
    CoverageTriangulation(const CoverageTriangulation&) = delete;
    CoverageTriangulation& operator=(const CoverageTriangulation&) = delete;

    /// Starts a frame: the triangulation of the rectangle [x0, x1] × [y0, y1] (grid coordinates),
    /// nothing covered. Queries and occluders outside it are clipped to it (a query reaching
    /// beyond it is not hidden there). Buffers are kept.
    void reset(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1);

    /// At most this many constraint edges a frame (0: no cap); an occluder that would pass it is
    /// refused whole (counted) and nothing of it is inserted.
    void setConstraintBudget(std::uint32_t edges);

    /// Inserts a convex polygon (counter-clockwise, at least 3 vertices, grid coordinates, already
    /// eroded by the caller) as covered. Returns false when it was refused (budget, fewer than 3
    /// distinct vertices, zero area): a refused occluder only covers less.
    bool insertOccluder(const GridPoint* ccw, std::size_t count, CoverKind kind, const AffineNearness& nearness);

    /// True when the convex polygon (counter-clockwise, grid coordinates, already dilated by the
    /// caller) lies wholly in covered triangles that hide it: each triangle it overlaps (shares
    /// area with) must be DepthFree-covered (QueryMode::DepthFree only), or have a depth bound
    /// whose w exceeds `nearestW` (the largest w of the queried thing; +inf: no depth test passes).
    /// Found by a flood over the triangles it overlaps, so a hole inside it is found too.
    bool hidden(const GridPoint* ccw, std::size_t count, QueryMode mode,
                double nearestW = std::numeric_limits<double>::infinity()) const;

    /// For the debug map and the tests.
    struct TriangleView
    {
        GridPoint a, b, c;
        bool depthFreeCovered = false;
        double depthBound = -std::numeric_limits<double>::infinity(); ///< largest least-w of its covers
    };
    std::vector<TriangleView> triangles() const;
    /// Constraint edges currently in the triangulation (pieces of occluder outlines).
    std::vector<std::pair<GridPoint, GridPoint>> constraintEdges() const;
    /// Checks the triangulation's invariants (orientation, adjacency, constrained Delaunay
    /// property); for the tests. Returns an empty string or what is wrong.
    std::string validate() const;

    /// The largest L-infinity distance of a constraint piece from the original segment it
    /// remembers (grid units; for the tests and docs/cdt.md).
    double constraintDeviation() const;

    const CoverageStatistics& statistics() const;

private:
    struct Impl;
    std::unique_ptr<Impl> _impl;
};
} // namespace osgVis::core::cdt
