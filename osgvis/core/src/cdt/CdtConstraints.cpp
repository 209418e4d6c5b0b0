// SPDX-License-Identifier: MIT
// Constraint insertion of the CDT record (Luka, "Visibility culling with a constrained Delaunay
// triangulation", §2.2.2: occluder outlines become constraint edges). A piece p→q is walked
// through the triangulation; when it meets a vertex on it, it is split there; when it crosses a
// constraint edge, the crossing is computed from the two *original* segments (never from pieces
// already split and rounded), rounded to the grid, inserted as a vertex, and both constraints are
// re-routed through it. A piece that crosses no constraint and no vertex is made an edge by
// Sloan's flipping ("A fast algorithm for generating constrained Delaunay triangulations", 1993,
// §4), then the Delaunay property is restored by Lawson's flips around it.
#include "CdtMesh.h"

namespace osgVis::core::cdt
{
namespace
{
std::int64_t dot(GridPoint p, GridPoint a, GridPoint q)
{
    return (std::int64_t(a.x) - p.x) * (std::int64_t(q.x) - p.x) +
           (std::int64_t(a.y) - p.y) * (std::int64_t(q.y) - p.y);
}
constexpr std::size_t MaxPiecesPerSegment = 4096;
} // namespace

void CoverageTriangulation::Impl::markConstraint(EdgeRef e, std::int32_t original, bool on)
{
    Triangle& tr = tris[e.t];
    const std::int32_t u = tr.v[(e.side + 1) % 3], w = tr.v[(e.side + 2) % 3];
    const std::int32_t value = on ? (tr.c[e.side] >= 0 ? tr.c[e.side] : original) : -1;
    tr.c[e.side] = value;
    const std::int32_t t2 = tr.n[e.side];
    if (t2 >= 0)
    {
        const std::int32_t far = farVertex(t2, u, w);
        tris[t2].c[indexOf(t2, far)] = value;
    }
}

bool CoverageTriangulation::Impl::insertSegment(std::int32_t p0, std::int32_t q0, std::int32_t original)
{
    pieces.clear();
    pieces.push_back({p0, q0, original});
    std::size_t processed = 0;
    while (!pieces.empty())
    {
        if (++processed > MaxPiecesPerSegment)
            return false;
        const Piece piece = pieces.back();
        pieces.pop_back();
        const std::int32_t p = piece.p, q = piece.q;
        if (p == q)
            continue;
        if (const EdgeRef e = findEdge(p, q); e.t >= 0)
        {
            markConstraint(e, piece.original, true);
            continue;
        }
        const PieceStart start = startOfPiece(p, q);
        if (start.vertexOnRay >= 0)
        {
            // note: a vertex exactly on p→q lies within the band of the original, like p and q.
            pieces.push_back({start.vertexOnRay, q, piece.original});
            pieces.push_back({p, start.vertexOnRay, piece.original});
            continue;
        }
        if (start.triangle < 0)
            return false;
        if (!walkPiece(piece, start.triangle))
            return false;
        legalize();
    }
    return true;
}

PieceStart CoverageTriangulation::Impl::startOfPiece(std::int32_t p, std::int32_t q) const
{
    const GridPoint P = points[p], Q = points[q];
    // The triangle around p whose angle holds the direction to q (or a vertex on the ray).
    std::int32_t start = -1, vertexOnRay = -1;
    for (int dir = 0; dir < 2 && start < 0 && vertexOnRay < 0; ++dir)
    {
        std::int32_t t = pointTriangle[p];
        for (std::size_t guard = 0; t >= 0 && guard <= tris.size(); ++guard)
        {
            const int i = indexOf(t, p);
            const std::int32_t a = tris[t].v[(i + 1) % 3], b = tris[t].v[(i + 2) % 3];
            const std::int64_t oa = orient(P, points[a], Q), ob = orient(P, points[b], Q);
            if (oa == 0 && dot(P, points[a], Q) > 0)
            {
                vertexOnRay = a;
                break;
            }
            if (ob == 0 && dot(P, points[b], Q) > 0)
            {
                vertexOnRay = b;
                break;
            }
            if (oa > 0 && ob < 0)
            {
                start = t;
                break;
            }
            t = dir == 0 ? tris[t].n[(i + 1) % 3] : tris[t].n[(i + 2) % 3];
            if (t == pointTriangle[p])
                break;
        }
    }
    return {start, vertexOnRay};
}

bool CoverageTriangulation::Impl::walkPiece(const Piece& piece, std::int32_t start)
{
    const std::int32_t p = piece.p, q = piece.q;
    const GridPoint P = points[p], Q = points[q];
    crossed.clear();
    std::int32_t t = start;
    int exitSide = indexOf(t, p);
    std::int32_t r = tris[t].v[(exitSide + 1) % 3], l = tris[t].v[(exitSide + 2) % 3];
    while (true)
    {
        if (tris[t].c[exitSide] >= 0)
            return splitAtConstraint(piece, r, l, tris[t].c[exitSide]);
        const std::int32_t tn = tris[t].n[exitSide];
        if (tn < 0)
            return false;
        crossed.push_back({r, l});
        const std::int32_t o = farVertex(tn, r, l);
        if (o == q)
            return insertPieceByFlips(p, q, piece.original);
        const std::int64_t so = orient(P, Q, points[o]);
        if (so == 0)
        {
            pieces.push_back({o, q, piece.original});
            return insertPieceByFlips(p, o, piece.original);
        }
        if (so > 0)
            l = o;
        else
            r = o;
        t = tn;
        exitSide = indexOf(t, farVertex(t, r, l));
    }
}

bool CoverageTriangulation::Impl::splitAtConstraint(const Piece& piece, std::int32_t r, std::int32_t l,
                                                    std::int32_t other)
{
    // A constraint r–l crosses p→q: both meet at the rounded crossing of their originals.
    const GridPoint c = constraintCrossing(piece, r, l, other);
    ++stats.crossings;
    const std::int32_t cv = insertPoint(c);
    if (cv < 0)
        return false;
    if (cv != r && cv != l)
    {
        if (const EdgeRef old = findEdge(r, l); old.t >= 0)
        {
            markConstraint(old, -1, false);
            legalizeQueue.push_back({r, l});
            pieces.push_back({r, cv, other});
            pieces.push_back({cv, l, other});
        }
    }
    pieces.push_back({cv, piece.q, piece.original});
    pieces.push_back({piece.p, cv, piece.original});
    return true;
}

GridPoint CoverageTriangulation::Impl::constraintCrossing(const Piece& piece, std::int32_t r, std::int32_t l,
                                                          std::int32_t other)
{
    const std::int32_t p = piece.p, q = piece.q;
    const OriginalSegment& s = originals[piece.original];
    const OriginalSegment& e = originals[other];
    GridPoint c;
    bool proper = false;
    if (!roundedCrossing(s.a, s.b, e.a, e.b, c, proper) || !proper)
    {
        // The originals do not meet (their pieces do, after rounding): take, of the
        // rounded crossing of the pieces and the four end points, the one nearest to
        // both originals (docs/cdt.md: no proven bound here, measured instead).
        ++roundingFallbacks;
        roundedCrossing(points[p], points[q], points[r], points[l], c, proper);
        const auto worse = [&](GridPoint g) { return std::max(linfDistance(g, s), linfDistance(g, e)); };
        double best = worse(c);
        for (const std::int32_t v : {r, l, p, q})
            if (const double d = worse(points[v]); d < best)
                best = d, c = points[v];
    }
    return c;
}

bool CoverageTriangulation::Impl::insertPieceByFlips(std::int32_t p, std::int32_t q, std::int32_t original)
{
    const GridPoint P = points[p], Q = points[q];
    newEdges.clear();
    const std::size_t limit = 64 + 64 * crossed.size() * crossed.size();
    for (std::size_t head = 0; head < crossed.size(); ++head)
    {
        if (head > limit)
            return false;
        const auto [u, w] = crossed[head];
        const EdgeRef e = findEdge(u, w);
        if (e.t < 0 || tris[e.t].n[e.side] < 0)
            return false;
        const std::int32_t o1 = tris[e.t].v[e.side], o2 = farVertex(tris[e.t].n[e.side], u, w);
        const int su = sign(orient(points[o1], points[o2], points[u]));
        const int sw = sign(orient(points[o1], points[o2], points[w]));
        if (su * sw >= 0)
        {
            crossed.push_back({u, w}); // not strictly convex yet: later
            continue;
        }
        flip(e.t, e.side);
        const int s1 = sign(orient(P, Q, points[o1])), s2 = sign(orient(P, Q, points[o2]));
        if (s1 * s2 < 0)
            crossed.push_back({o1, o2});
        else
            newEdges.push_back({o1, o2});
    }
    const EdgeRef e = findEdge(p, q);
    if (e.t < 0)
        return false;
    markConstraint(e, original, true);
    for (const auto& edge : newEdges)
        legalizeQueue.push_back(edge);
    legalize();
    return true;
}
} // namespace osgVis::core::cdt
