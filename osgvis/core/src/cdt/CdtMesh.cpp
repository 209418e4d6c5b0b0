// SPDX-License-Identifier: MIT
// The triangulation of the CDT record (Luka, "Visibility culling with a constrained Delaunay
// triangulation", §2.2.1-§2.2.2): point location by a remembering stochastic walk (Devillers,
// Pion, Teillaud, "Walking in a triangulation", 2002), vertex insertion by splitting the triangle
// or edge that holds the point, and Delaunay restoration by Lawson's edge flips (Lawson 1977, as
// in Sloan 1993 §3), never across a constraint edge.
#include "CdtMesh.h"

namespace osgVis::core::cdt
{
namespace
{
Wide orientScaled(GridPoint a, GridPoint b, std::int64_t X, std::int64_t Y)
{
    return Wide(std::int64_t(b.x) - a.x) * (Y - 3 * std::int64_t(a.y)) -
           Wide(std::int64_t(b.y) - a.y) * (X - 3 * std::int64_t(a.x));
}
} // namespace

void CoverageTriangulation::Impl::resetMesh(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by)
{
    points.clear();
    pointTriangle.clear();
    tris.clear();
    points.push_back({ax, ay});
    points.push_back({bx, ay});
    points.push_back({bx, by});
    points.push_back({ax, by});
    pointTriangle.assign(4, 0);
    pointTriangle[2] = 1;
    pointTriangle[3] = 1;
    const double none = -std::numeric_limits<double>::infinity();
    tris.push_back({{0, 1, 2}, {-1, 1, -1}, {-1, -1, -1}, -1, -1, none, 0});
    tris.push_back({{0, 2, 3}, {-1, -1, 0}, {-1, -1, -1}, -1, -1, none, 0});
    hint = 0;
    std::fill(bucketVertex, bucketVertex + Buckets * Buckets, -1);
}

EdgeRef CoverageTriangulation::Impl::findEdge(std::int32_t u, std::int32_t w) const
{
    // Rotate around u one way, then the other (the border stops a rotation).
    for (int dir = 0; dir < 2; ++dir)
    {
        std::int32_t t = pointTriangle[u];
        for (std::size_t guard = 0; t >= 0 && guard <= tris.size(); ++guard)
        {
            static constexpr int Next[3] = {1, 2, 0}, Prev[3] = {2, 0, 1};
            const int i = indexOf(t, u);
            if (i < 0)
                return {};
            const Triangle& tr = tris[t];
            if (tr.v[Next[i]] == w)
                return {t, Prev[i]};
            if (tr.v[Prev[i]] == w)
                return {t, Next[i]};
            t = tr.n[dir == 0 ? Next[i] : Prev[i]];
            if (t == pointTriangle[u])
                return {};
        }
    }
    return {};
}

std::int32_t CoverageTriangulation::Impl::locateScaled(std::int64_t X, std::int64_t Y) const
{
    if (const std::int32_t v = bucketVertex[bucketOf(X, Y)]; v >= 0 && v < std::int32_t(points.size()))
        hint = pointTriangle[v];
    std::int32_t t = (hint >= 0 && hint < std::int32_t(tris.size())) ? hint : 0;
    for (std::size_t step = 0; step < 4 * tris.size() + 64; ++step)
    {
        randomState = randomState * 1664525u + 1013904223u;
        const int start = int((randomState >> 16) % 3);
        const Triangle& tr = tris[t];
        int next = -1;
        static constexpr int Mod3[5] = {0, 1, 2, 0, 1};
        for (int k = 0; k < 3; ++k)
        {
            const int i = Mod3[start + k];
            if (orientScaled(points[tr.v[Mod3[i + 1]]], points[tr.v[Mod3[i + 2]]], X, Y) < 0)
            {
                next = i;
                break;
            }
        }
        if (next < 0)
            return hint = t;
        if (tr.n[next] < 0)
            return -1;
        t = tr.n[next];
    }
    for (std::int32_t s = 0; s < std::int32_t(tris.size()); ++s)
    {
        const Triangle& tr = tris[s];
        bool inside = true;
        for (int i = 0; i < 3 && inside; ++i)
            inside = orientScaled(points[tr.v[(i + 1) % 3]], points[tr.v[(i + 2) % 3]], X, Y) >= 0;
        if (inside)
            return hint = s;
    }
    return -1;
}

void CoverageTriangulation::Impl::rotate(std::int32_t t, int k)
{
    Triangle& tr = tris[t];
    const Triangle o = tr;
    for (int i = 0; i < 3; ++i)
    {
        tr.v[i] = o.v[(i + k) % 3];
        tr.n[i] = o.n[(i + k) % 3];
        tr.c[i] = o.c[(i + k) % 3];
    }
}

void CoverageTriangulation::Impl::setNeighbour(std::int32_t t, std::int32_t oldN, std::int32_t newN)
{
    if (t < 0)
        return;
    Triangle& tr = tris[t];
    for (int i = 0; i < 3; ++i)
        if (tr.n[i] == oldN)
        {
            tr.n[i] = newN;
            return;
        }
}

void CoverageTriangulation::Impl::flip(std::int32_t t, int side)
{
    // t = (o1, u, w), t2 = (o2, w, u)  ->  t = (o1, u, o2), t2 = (o2, w, o1).
    rotate(t, side);
    const std::int32_t t2 = tris[t].n[0];
    const std::int32_t u = tris[t].v[1], w = tris[t].v[2];
    rotate(t2, (indexOf(t2, w) + 2) % 3);
    Triangle& a = tris[t];
    Triangle& b = tris[t2];
    const std::int32_t o1 = a.v[0], o2 = b.v[0];
    const std::int32_t nA = a.n[1], cA = a.c[1], nB = a.n[2], cB = a.c[2];
    const std::int32_t nC = b.n[1], cC = b.c[1], nD = b.n[2], cD = b.c[2];
    a.v[0] = o1, a.v[1] = u, a.v[2] = o2;
    a.n[0] = nC, a.c[0] = cC, a.n[1] = t2, a.c[1] = -1, a.n[2] = nB, a.c[2] = cB;
    b.v[0] = o2, b.v[1] = w, b.v[2] = o1;
    b.n[0] = nA, b.c[0] = cA, b.n[1] = t, b.c[1] = -1, b.n[2] = nD, b.c[2] = cD;
    setNeighbour(nA, t, t2);
    setNeighbour(nC, t2, t);
    pointTriangle[u] = t, pointTriangle[o1] = t, pointTriangle[o2] = t, pointTriangle[w] = t2;
    // note: t and t2 shared a non-constraint edge, and any cover of either is certified again.
    const std::int32_t cand[4] = {a.depthFreeOccluder, a.depthOccluder, b.depthFreeOccluder, b.depthOccluder};
    recover(t, cand, 4);
    recover(t2, cand, 4);
    ++stats.flips;
}

void CoverageTriangulation::Impl::legalize()
{
    while (!legalizeQueue.empty())
    {
        const auto [u, w] = legalizeQueue.back();
        legalizeQueue.pop_back();
        const EdgeRef e = findEdge(u, w);
        if (e.t < 0)
            continue;
        const Triangle& tr = tris[e.t];
        const std::int32_t t2 = tr.n[e.side];
        if (t2 < 0 || tr.c[e.side] >= 0)
            continue;
        const std::int32_t far = farVertex(t2, u, w);
        if (inCircle(points[tr.v[0]], points[tr.v[1]], points[tr.v[2]], points[far]) <= 0)
            continue;
        const std::int32_t near = tr.v[e.side];
        flip(e.t, e.side);
        legalizeQueue.push_back({u, far});
        legalizeQueue.push_back({far, w});
        legalizeQueue.push_back({near, u});
        legalizeQueue.push_back({w, near});
    }
}

std::int32_t CoverageTriangulation::Impl::insertPoint(GridPoint p)
{
    if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1)
        return -1;
    const std::int32_t t = locateScaled(3 * std::int64_t(p.x), 3 * std::int64_t(p.y));
    if (t < 0)
        return -1;
    int onEdge = -1;
    for (int i = 0; i < 3; ++i)
    {
        if (points[tris[t].v[i]] == p)
            return tris[t].v[i];
        if (orient(points[tris[t].v[(i + 1) % 3]], points[tris[t].v[(i + 2) % 3]], p) == 0)
            onEdge = i;
    }
    const std::int32_t pv = std::int32_t(points.size());
    points.push_back(p);
    pointTriangle.push_back(t);
    const double none = -std::numeric_limits<double>::infinity();
    if (onEdge < 0)
    {
        const Triangle o = tris[t];
        const std::int32_t a = o.v[0], b = o.v[1], c = o.v[2];
        const std::int32_t tb = std::int32_t(tris.size()), tc = tb + 1;
        tris[t] = {{pv, b, c}, {o.n[0], tb, tc}, {o.c[0], -1, -1}, -1, -1, none, 0};
        tris.push_back({{pv, c, a}, {o.n[1], tc, t}, {o.c[1], -1, -1}, -1, -1, none, 0});
        tris.push_back({{pv, a, b}, {o.n[2], t, tb}, {o.c[2], -1, -1}, -1, -1, none, 0});
        setNeighbour(o.n[1], t, tb);
        setNeighbour(o.n[2], t, tc);
        pointTriangle[a] = tb, pointTriangle[b] = t, pointTriangle[c] = t;
        const std::int32_t cand[2] = {o.depthFreeOccluder, o.depthOccluder};
        recover(t, cand, 2), recover(tb, cand, 2), recover(tc, cand, 2);
        legalizeQueue.push_back({b, c}), legalizeQueue.push_back({c, a}), legalizeQueue.push_back({a, b});
    }
    else
    {
        rotate(t, onEdge);
        const Triangle o = tris[t];
        const std::int32_t a = o.v[0], b = o.v[1], c = o.v[2];
        const std::int32_t t2 = o.n[0];
        const std::int32_t t1 = std::int32_t(tris.size());
        const std::int32_t t3 = t2 >= 0 ? t1 + 1 : -1;
        tris[t] = {{a, b, pv}, {t3, t1, o.n[2]}, {o.c[0], -1, o.c[2]}, -1, -1, none, 0};
        tris.push_back({{a, pv, c}, {t2, o.n[1], t}, {o.c[0], o.c[1], -1}, -1, -1, none, 0});
        setNeighbour(o.n[1], t, t1);
        pointTriangle[a] = t, pointTriangle[b] = t, pointTriangle[c] = t1;
        const std::int32_t cand[2] = {o.depthFreeOccluder, o.depthOccluder};
        recover(t, cand, 2), recover(t1, cand, 2);
        legalizeQueue.push_back({b, a}), legalizeQueue.push_back({a, c});
        if (t2 >= 0)
        {
            rotate(t2, (indexOf(t2, c) + 2) % 3); // t2 = (d, c, b)
            const Triangle q = tris[t2];
            const std::int32_t d = q.v[0];
            tris[t2] = {{d, c, pv}, {t1, t3, q.n[2]}, {q.c[0], -1, q.c[2]}, -1, -1, none, 0};
            tris.push_back({{d, pv, b}, {t, q.n[1], t2}, {q.c[0], q.c[1], -1}, -1, -1, none, 0});
            setNeighbour(q.n[1], t2, t3);
            pointTriangle[d] = t2;
            const std::int32_t cand2[2] = {q.depthFreeOccluder, q.depthOccluder};
            recover(t2, cand2, 2), recover(t3, cand2, 2);
            legalizeQueue.push_back({d, c}), legalizeQueue.push_back({b, d});
        }
    }
    ++stats.vertices;
    bucketVertex[bucketOf(3 * std::int64_t(p.x), 3 * std::int64_t(p.y))] = pv;
    legalize();
    return pv;
}
} // namespace osgVis::core::cdt
