// SPDX-License-Identifier: MIT
#pragma once
// The triangulation behind CoverageTriangulation (Luka, "Visibility culling with a constrained
// Delaunay triangulation", §2.2.1-§2.2.3): triangles with neighbour links, constraint marks that
// remember their original segment, and per-triangle covers certified by an exact containment test.
// Vertex insertion with Lawson's flips (Lawson 1977; Sloan, "A fast algorithm for generating
// constrained Delaunay triangulations", 1993), constraint insertion by Sloan's flipping
// (CdtConstraints.cpp), coverage and queries (CdtCoverage.cpp).
#include "GridPredicates.h"

#include <osgVis/core/cdt/CoverageTriangulation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace osgVis::core::cdt
{
/// An original input segment (an occluder edge as given): every constraint piece points at one.
struct OriginalSegment
{
    GridPoint a, b;
};

/// The L-infinity distance of p from the segment (exact enough for measuring: doubles).
inline double linfDistance(GridPoint p, const OriginalSegment& s)
{
    const double fx = double(p.x) - s.a.x, fy = double(p.y) - s.a.y;
    const double dx = double(s.b.x) - s.a.x, dy = double(s.b.y) - s.a.y;
    double best = std::numeric_limits<double>::infinity();
    const double candidates[6] = {0.0, 1.0, fx / dx, fy / dy, (fx - fy) / (dx - dy), (fx + fy) / (dx + dy)};
    for (double t : candidates)
    {
        if (!std::isfinite(t))
            continue;
        t = std::clamp(t, 0.0, 1.0);
        best = std::min(best, std::max(std::abs(fx - t * dx), std::abs(fy - t * dy)));
    }
    return best;
}

struct Triangle
{
    std::int32_t v[3];              ///< counter-clockwise
    std::int32_t n[3];              ///< neighbour across the edge opposite v[i]; -1: the rectangle's border
    std::int32_t c[3];              ///< original segment of the constraint opposite v[i]; -1: no constraint
    std::int32_t depthFreeOccluder; ///< a DepthFree occluder whose dilation contains the triangle; -1 none
    std::int32_t depthOccluder;     ///< the occluder giving depthBound; -1 none
    double depthBound;
    std::uint32_t mark; ///< flood stamp
};

struct Occluder
{
    std::uint32_t first = 0, count = 0; ///< in Impl::occluderPoints (the unclipped input)
    std::int64_t minX = 0, minY = 0, maxX = 0, maxY = 0;
    CoverKind kind = CoverKind::DepthFree;
    AffineNearness nearness;
};

/// An occluder edge a→b as containedIn() needs it: a, b - a and the slack |dx| + |dy| of its
/// half-plane moved out by [-1/2, 1/2]^2 (all exact integers, computed once per occluder).
struct OccluderEdge
{
    std::int64_t ax, ay, dx, dy, slack;
};

struct EdgeRef
{
    std::int32_t t = -1, side = -1;
};

struct Piece
{
    std::int32_t p, q, original;
};

/// Where the walk of a piece p→q starts: the triangle around p whose angle holds the direction to
/// q, or a vertex exactly on the ray from p towards q (-1: none).
struct PieceStart
{
    std::int32_t triangle = -1, vertexOnRay = -1;
};

struct CoverageTriangulation::Impl
{
    std::vector<GridPoint> points;
    std::vector<std::int32_t> pointTriangle; ///< a triangle incident to each vertex
    std::vector<Triangle> tris;
    std::vector<OriginalSegment> originals;
    std::vector<Occluder> occluders;
    std::vector<GridPoint> occluderPoints;
    std::vector<OccluderEdge> occluderEdges; ///< parallel to occluderPoints: the edge from each point
    std::int32_t x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    std::uint32_t budget = 0;
    std::uint32_t budgetUsed = 0;
    mutable std::int32_t hint = 0;
    mutable std::uint32_t randomState = 1;
    mutable std::uint32_t floodStamp = 0;
    /// A recent vertex in each cell of a 64 x 64 bucket grid over the rectangle: walks start there.
    static constexpr int Buckets = 64;
    std::int32_t bucketVertex[Buckets * Buckets];
    int bucketOf(std::int64_t X3, std::int64_t Y3) const
    {
        const std::int64_t bx = (X3 - 3 * std::int64_t(x0)) * Buckets / (3 * (std::int64_t(x1) - x0) + 1);
        const std::int64_t by = (Y3 - 3 * std::int64_t(y0)) * Buckets / (3 * (std::int64_t(y1) - y0) + 1);
        return int(std::clamp<std::int64_t>(by, 0, Buckets - 1) * Buckets +
                   std::clamp<std::int64_t>(bx, 0, Buckets - 1));
    }
    mutable CoverageStatistics stats;

    // Reused buffers (no allocation once they reached their size).
    std::vector<std::pair<std::int32_t, std::int32_t>> legalizeQueue;
    std::vector<std::pair<std::int32_t, std::int32_t>> crossed;
    std::vector<std::pair<std::int32_t, std::int32_t>> newEdges;
    std::vector<Piece> pieces;
    std::vector<GridPoint> clipA, clipB;
    mutable std::vector<std::int32_t> stack;
    std::uint32_t roundingFallbacks = 0;

    // CdtMesh.cpp
    void resetMesh(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by);
    EdgeRef findEdge(std::int32_t u, std::int32_t w) const;
    /// Finds the triangle containing 3·p = (X, Y) (scaled so centroids are exact); -1 outside.
    std::int32_t locateScaled(std::int64_t X, std::int64_t Y) const;
    /// Inserts the grid point (or returns the vertex already there); -1 outside the rectangle.
    std::int32_t insertPoint(GridPoint p);
    void rotate(std::int32_t t, int k);
    void flip(std::int32_t t, int side);
    void legalize();
    void setNeighbour(std::int32_t t, std::int32_t oldN, std::int32_t newN);
    // note: inline (here, not in CdtMesh.cpp) because every file of the record calls them in its hot loops.
    int indexOf(std::int32_t t, std::int32_t v) const
    {
        const Triangle& tr = tris[t];
        return tr.v[0] == v ? 0 : tr.v[1] == v ? 1 : tr.v[2] == v ? 2 : -1;
    }

    // CdtConstraints.cpp
    /// Inserts the pieces of originals[original] from vertex p to vertex q. False when it gave up.
    bool insertSegment(std::int32_t p, std::int32_t q, std::int32_t original);
    PieceStart startOfPiece(std::int32_t p, std::int32_t q) const;
    /// Walks the piece from triangle `start` through the edges it crosses until it meets q, a
    /// vertex on it or a constraint: inserts it (by flips) or splits it. False when it gave up.
    bool walkPiece(const Piece& piece, std::int32_t start);
    /// The constraint r–l (of originals[other]) crosses the piece: splits both at one new vertex.
    bool splitAtConstraint(const Piece& piece, std::int32_t r, std::int32_t l, std::int32_t other);
    /// Where the piece and the constraint r–l meet: the rounded crossing of their originals.
    GridPoint constraintCrossing(const Piece& piece, std::int32_t r, std::int32_t l, std::int32_t other);
    bool insertPieceByFlips(std::int32_t p, std::int32_t q, std::int32_t original);
    void markConstraint(EdgeRef e, std::int32_t original, bool on);
    std::int32_t farVertex(std::int32_t t, std::int32_t u, std::int32_t w) const
    {
        for (int i = 0; i < 3; ++i)
            if (tris[t].v[i] != u && tris[t].v[i] != w)
                return tris[t].v[i];
        return -1;
    }

    // CdtCoverage.cpp
    bool containedIn(std::int32_t t, const Occluder& o) const;
    void applyCover(std::int32_t t, std::int32_t occluder);
    /// Clears t's cover and recomputes it from the candidate occluders (covers of the triangles t replaced).
    void recover(std::int32_t t, const std::int32_t* cand, int count);
    bool coverOccluder(std::int32_t occluder, std::int64_t X3, std::int64_t Y3);
    /// Within the grid's range, convex with positive area, and within the constraint budget.
    bool acceptsOccluder(const GridPoint* ccw, std::size_t count) const;
    /// Leaves the occluder clipped to the rectangle in clipB, and i0 such that clipB[0], clipB[i0]
    /// and clipB[i0 + 1] span positive area. False when no convex polygon of positive area is left.
    bool clipToRectangle(const GridPoint* ccw, std::size_t count, std::size_t& i0);
    /// Records the unclipped occluder for the containment test; returns its index.
    std::int32_t addOccluder(const GridPoint* ccw, std::size_t count, CoverKind kind, const AffineNearness& nearness);
    /// Inserts the clipped outline; returns its first vertex (-1 when none could be inserted).
    std::int32_t insertOutline(const std::vector<GridPoint>& poly);
};
} // namespace osgVis::core::cdt
