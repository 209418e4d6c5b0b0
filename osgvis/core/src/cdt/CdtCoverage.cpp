// SPDX-License-Identifier: MIT
// Coverage of the CDT record (Luka, "Visibility culling with a constrained Delaunay
// triangulation", §2.2.2 marking covered triangles, §2.2.3 testing a projected bound). A triangle
// is covered by an occluder only when an exact integer test shows it lies inside that occluder's
// polygon dilated by the rounding bound (the Minkowski sum with [-1/2, 1/2]^2), so a covered
// triangle never leaves the dilated occluder whatever the rounding did. Covers are found by a
// flood from the occluder's centroid and carried over to the triangles that replace a split or
// flipped one (back references, §2.2.1). Queries flood the triangles a polygon shares area with.
#include "CdtMesh.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core::cdt
{
namespace
{
bool zeroLength(GridPoint a, GridPoint b)
{
    return a == b;
}

/// True when the open segment (a, b) meets the interior of the convex counter-clockwise polygon
/// (separating axes: its edges' normals and the segment's normal; weak separation, exact).
bool segmentMeetsInterior(GridPoint a, GridPoint b, const GridPoint* q, std::size_t n)
{
    for (std::size_t j = 0; j < n; ++j)
    {
        const GridPoint u = q[j], w = q[(j + 1) % n];
        if (zeroLength(u, w))
            continue;
        if (orient(u, w, a) <= 0 && orient(u, w, b) <= 0)
            return false;
    }
    bool pos = false, neg = false;
    for (std::size_t j = 0; j < n; ++j)
    {
        const std::int64_t s = orient(a, b, q[j]);
        pos = pos || s > 0;
        neg = neg || s < 0;
    }
    return pos && neg;
}

/// Convex, counter-clockwise (collinear and repeated vertices allowed), with positive area.
bool convexPositive(const GridPoint* p, std::size_t n, std::size_t& i0)
{
    bool area = false;
    i0 = 0;
    for (std::size_t j = 0; j < n; ++j)
    {
        const std::int64_t s = orient(p[j], p[(j + 1) % n], p[(j + 2) % n]);
        if (s < 0)
            return false;
    }
    for (std::size_t j = 1; j + 1 < n && !area; ++j)
        if (orient(p[0], p[j], p[j + 1]) > 0)
            area = true, i0 = j;
    return area;
}
} // namespace

bool CoverageTriangulation::Impl::containedIn(std::int32_t t, const Occluder& o) const
{
    const Triangle& tr = tris[t];
    const GridPoint p[3] = {points[tr.v[0]], points[tr.v[1]], points[tr.v[2]]};
    // note: integer points; x >= minX - 1/2 is x >= minX. The box first: it rejects most.
    for (int k = 0; k < 3; ++k)
        if (p[k].x < o.minX || p[k].x > o.maxX || p[k].y < o.minY || p[k].y > o.maxY)
            return false;
    const OccluderEdge* e = occluderEdges.data() + o.first;
    for (std::uint32_t j = 0; j < o.count; ++j)
    {
        // 2·orient(a, b, p) >= -(|dx| + |dy|): the same exact integer test as the half-plane of the
        // Minkowski sum.
        const OccluderEdge& g = e[j];
        for (int k = 0; k < 3; ++k)
            if (2 * (g.dx * (p[k].y - g.ay) - g.dy * (p[k].x - g.ax)) < -g.slack)
                return false;
    }
    return true;
}

void CoverageTriangulation::Impl::applyCover(std::int32_t t, std::int32_t occluder)
{
    const Occluder& o = occluders[occluder];
    Triangle& tr = tris[t];
    if (o.kind == CoverKind::DepthFree && tr.depthFreeOccluder < 0)
        tr.depthFreeOccluder = occluder;
    if (o.nearness.valid)
    {
        double least = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k)
            least = std::min(least, o.nearness.at(points[tr.v[k]].x, points[tr.v[k]].y));
        if (!std::isnan(least) && least > tr.depthBound)
        {
            tr.depthBound = least;
            tr.depthOccluder = occluder;
        }
    }
}

void CoverageTriangulation::Impl::recover(std::int32_t t, const std::int32_t* cand, int count)
{
    Triangle& tr = tris[t];
    tr.depthFreeOccluder = -1;
    tr.depthOccluder = -1;
    tr.depthBound = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < count; ++i)
    {
        if (cand[i] < 0 || std::find(cand, cand + i, cand[i]) != cand + i)
            continue;
        if (containedIn(t, occluders[cand[i]]))
            applyCover(t, cand[i]);
    }
}

bool CoverageTriangulation::Impl::coverOccluder(std::int32_t occluder, std::int64_t X3, std::int64_t Y3)
{
    const std::int32_t t0 = locateScaled(X3, Y3);
    if (t0 < 0)
        return false;
    const Occluder& o = occluders[occluder];
    const std::uint32_t stamp = ++floodStamp;
    stack.clear();
    stack.push_back(t0);
    tris[t0].mark = stamp;
    bool any = false;
    while (!stack.empty())
    {
        const std::int32_t t = stack.back();
        stack.pop_back();
        if (!containedIn(t, o))
            continue;
        applyCover(t, occluder);
        any = true;
        for (int i = 0; i < 3; ++i)
        {
            const std::int32_t n = tris[t].n[i];
            if (n >= 0 && tris[n].mark != stamp)
            {
                tris[n].mark = stamp;
                stack.push_back(n);
            }
        }
    }
    return any;
}

CoverageTriangulation::CoverageTriangulation() : _impl(std::make_unique<Impl>())
{
    reset(0, 0, 1, 1);
}
CoverageTriangulation::~CoverageTriangulation() = default;

void CoverageTriangulation::reset(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1)
{
    Impl& m = *_impl;
    const auto clampGrid = [](std::int64_t v)
    { return std::int32_t(std::clamp<std::int64_t>(v, -GridLimit, GridLimit)); };
    m.x0 = clampGrid(std::min(x0, x1));
    m.x1 = clampGrid(std::max(x0, x1));
    m.y0 = clampGrid(std::min(y0, y1));
    m.y1 = clampGrid(std::max(y0, y1));
    if (m.x1 == m.x0)
        m.x0 > -GridLimit ? --m.x0 : ++m.x1;
    if (m.y1 == m.y0)
        m.y0 > -GridLimit ? --m.y0 : ++m.y1;
    m.resetMesh(m.x0, m.y0, m.x1, m.y1);
    m.originals.clear();
    m.occluders.clear();
    m.occluderPoints.clear();
    m.occluderEdges.clear();
    m.budgetUsed = 0;
    m.roundingFallbacks = 0;
    m.randomState = 1;
    m.stats = {};
    m.stats.vertices = 4;
    m.stats.triangles = 2;
}

void CoverageTriangulation::setConstraintBudget(std::uint32_t edges)
{
    _impl->budget = edges;
}

bool CoverageTriangulation::insertOccluder(const GridPoint* ccw, std::size_t count, CoverKind kind,
                                           const AffineNearness& nearness)
{
    Impl& m = *_impl;
    std::size_t i0 = 0;
    if (!m.acceptsOccluder(ccw, count) || !m.clipToRectangle(ccw, count, i0))
    {
        ++m.stats.occludersRefused;
        return false;
    }
    const std::vector<GridPoint>& poly = m.clipB;
    const std::int32_t occluder = m.addOccluder(ccw, count, kind, nearness);
    const std::int32_t firstVertex = m.insertOutline(poly);
    const std::int64_t X3 = std::int64_t(poly[0].x) + poly[i0].x + poly[i0 + 1].x;
    const std::int64_t Y3 = std::int64_t(poly[0].y) + poly[i0].y + poly[i0 + 1].y;
    // note: even an incomplete outline covers soundly: covers are certified triangle by triangle.
    if (firstVertex >= 0)
        m.hint = m.pointTriangle[firstVertex]; // the walk to the centroid starts at a corner
    m.coverOccluder(occluder, X3, Y3);
    ++m.stats.occludersInserted;
    m.stats.triangles = std::uint32_t(m.tris.size());
    return true;
}

bool CoverageTriangulation::Impl::acceptsOccluder(const GridPoint* ccw, std::size_t count) const
{
    std::size_t i0 = 0;
    bool ok = ccw && count >= 3 && count < (std::size_t(1) << 20);
    for (std::size_t i = 0; ok && i < count; ++i)
        ok = std::abs(std::int64_t(ccw[i].x)) <= GridLimit && std::abs(std::int64_t(ccw[i].y)) <= GridLimit;
    ok = ok && convexPositive(ccw, count, i0);
    if (ok && budget && budgetUsed + count > budget)
        ok = false;
    return ok;
}

// Clip to the rectangle (Sutherland-Hodgman, crossings rounded: the cover is certified
// against the unclipped polygon, so the clipped outline only needs to be near it).
bool CoverageTriangulation::Impl::clipToRectangle(const GridPoint* ccw, std::size_t count, std::size_t& i0)
{
    std::vector<GridPoint>& a = clipA;
    std::vector<GridPoint>& b = clipB;
    a.assign(ccw, ccw + count);
    for (int side = 0; side < 4 && !a.empty(); ++side)
    {
        b.clear();
        const auto inside = [&](GridPoint p) {
            return side == 0 ? p.x >= x0 : side == 1 ? p.x <= x1 : side == 2 ? p.y >= y0 : p.y <= y1;
        };
        const auto cut = [&](GridPoint p, GridPoint q)
        {
            const bool vertical = side < 2;
            const std::int64_t k = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
            const std::int64_t pa = vertical ? p.x : p.y, qa = vertical ? q.x : q.y;
            const std::int64_t pb = vertical ? p.y : p.x, qb = vertical ? q.y : q.x;
            const std::int32_t other = std::int32_t(roundDiv(Wide(pb) * (qa - pa) + Wide(k - pa) * (qb - pb), qa - pa));
            return vertical ? GridPoint{std::int32_t(k), other} : GridPoint{other, std::int32_t(k)};
        };
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            const GridPoint p = a[i], q = a[(i + 1) % a.size()];
            if (inside(p))
                b.push_back(p);
            if (inside(p) != inside(q))
                b.push_back(cut(p, q));
        }
        a.swap(b);
    }
    b.clear();
    for (std::size_t i = 0; i < a.size(); ++i)
        if (b.empty() || a[i] != b.back())
            b.push_back(a[i]);
    while (b.size() > 1 && b.front() == b.back())
        b.pop_back();
    return b.size() >= 3 && convexPositive(b.data(), b.size(), i0);
}

std::int32_t CoverageTriangulation::Impl::addOccluder(const GridPoint* ccw, std::size_t count, CoverKind kind,
                                                      const AffineNearness& nearness)
{
    Occluder o;
    o.first = std::uint32_t(occluderPoints.size());
    o.count = std::uint32_t(count);
    o.kind = kind;
    o.nearness = nearness;
    o.minX = o.maxX = ccw[0].x;
    o.minY = o.maxY = ccw[0].y;
    for (std::size_t i = 0; i < count; ++i)
    {
        occluderPoints.push_back(ccw[i]);
        const GridPoint a = ccw[i], b = ccw[(i + 1) % count];
        const std::int64_t dx = std::int64_t(b.x) - a.x, dy = std::int64_t(b.y) - a.y;
        occluderEdges.push_back({a.x, a.y, dx, dy, std::abs(dx) + std::abs(dy)});
        o.minX = std::min<std::int64_t>(o.minX, ccw[i].x), o.maxX = std::max<std::int64_t>(o.maxX, ccw[i].x);
        o.minY = std::min<std::int64_t>(o.minY, ccw[i].y), o.maxY = std::max<std::int64_t>(o.maxY, ccw[i].y);
    }
    const std::int32_t occluder = std::int32_t(occluders.size());
    occluders.push_back(o);
    budgetUsed += std::uint32_t(count);
    return occluder;
}

// Vertices, then the edges as constraints (each remembers its original segment).
std::int32_t CoverageTriangulation::Impl::insertOutline(const std::vector<GridPoint>& poly)
{
    std::int32_t firstVertex = -1, previous = -1;
    bool complete = true;
    for (std::size_t i = 0; i <= poly.size() && complete; ++i)
    {
        const std::int32_t v = i < poly.size() ? insertPoint(poly[i]) : firstVertex;
        if (v < 0)
        {
            complete = false;
            break;
        }
        if (i == 0)
            firstVertex = v;
        else
        {
            const std::int32_t original = std::int32_t(originals.size());
            originals.push_back({poly[i - 1], poly[i % poly.size()]});
            complete = insertSegment(previous, v, original);
            ++stats.constraintEdges;
        }
        previous = v;
    }
    return firstVertex;
}

bool CoverageTriangulation::hidden(const GridPoint* q, std::size_t count, QueryMode mode, double nearestW) const
{
    const Impl& m = *_impl;
    ++m.stats.queries;
    std::size_t i0 = 0;
    if (!q || count < 3 || !convexPositive(q, count, i0))
        return false;
    for (std::size_t i = 0; i < count; ++i)
        if (q[i].x < m.x0 || q[i].x > m.x1 || q[i].y < m.y0 || q[i].y > m.y1)
            return false;
    const std::int64_t X3 = std::int64_t(q[0].x) + q[i0].x + q[i0 + 1].x;
    const std::int64_t Y3 = std::int64_t(q[0].y) + q[i0].y + q[i0 + 1].y;
    const std::int32_t t0 = m.locateScaled(X3, Y3);
    if (t0 < 0)
        return false;
    const std::uint32_t stamp = ++m.floodStamp;
    // note: marks live in the triangles; hidden() is const but not safe to call concurrently.
    std::vector<Triangle>& tris = const_cast<std::vector<Triangle>&>(m.tris);
    m.stack.clear();
    m.stack.push_back(t0);
    tris[t0].mark = stamp;
    while (!m.stack.empty())
    {
        const std::int32_t t = m.stack.back();
        m.stack.pop_back();
        ++m.stats.queryTrianglesVisited;
        const Triangle& tr = tris[t];
        const bool hides = (mode == QueryMode::DepthFree && tr.depthFreeOccluder >= 0) || tr.depthBound > nearestW;
        if (!hides)
            return false;
        for (int i = 0; i < 3; ++i)
        {
            const std::int32_t n = tr.n[i];
            if (n >= 0 && tris[n].mark == stamp)
                continue;
            if (!segmentMeetsInterior(m.points[tr.v[(i + 1) % 3]], m.points[tr.v[(i + 2) % 3]], q, count))
                continue;
            if (n < 0)
                return false;
            tris[n].mark = stamp;
            m.stack.push_back(n);
        }
    }
    return true;
}

std::vector<CoverageTriangulation::TriangleView> CoverageTriangulation::triangles() const
{
    std::vector<TriangleView> out;
    out.reserve(_impl->tris.size());
    for (const Triangle& t : _impl->tris)
        out.push_back({_impl->points[t.v[0]], _impl->points[t.v[1]], _impl->points[t.v[2]], t.depthFreeOccluder >= 0,
                       t.depthBound});
    return out;
}

std::vector<std::pair<GridPoint, GridPoint>> CoverageTriangulation::constraintEdges() const
{
    std::vector<std::pair<GridPoint, GridPoint>> out;
    const Impl& m = *_impl;
    for (std::size_t t = 0; t < m.tris.size(); ++t)
        for (int i = 0; i < 3; ++i)
            if (m.tris[t].c[i] >= 0 && (m.tris[t].n[i] < 0 || m.tris[t].n[i] > std::int32_t(t)))
                out.push_back({m.points[m.tris[t].v[(i + 1) % 3]], m.points[m.tris[t].v[(i + 2) % 3]]});
    return out;
}

std::string CoverageTriangulation::validate() const
{
    const Impl& m = *_impl;
    const auto where = [](std::size_t t, const char* what) { return "triangle " + std::to_string(t) + ": " + what; };
    for (std::size_t t = 0; t < m.tris.size(); ++t)
    {
        const Triangle& tr = m.tris[t];
        if (orient(m.points[tr.v[0]], m.points[tr.v[1]], m.points[tr.v[2]]) <= 0)
            return where(t, "not counter-clockwise");
        for (int i = 0; i < 3; ++i)
        {
            const std::int32_t u = tr.v[(i + 1) % 3], w = tr.v[(i + 2) % 3];
            const std::int32_t n = tr.n[i];
            if (n < 0)
            {
                const GridPoint a = m.points[u], b = m.points[w];
                const bool border =
                    (a.x == b.x && (a.x == m.x0 || a.x == m.x1)) || (a.y == b.y && (a.y == m.y0 || a.y == m.y1));
                if (!border)
                    return where(t, "open edge inside the rectangle");
                continue;
            }
            const Triangle& o = m.tris[n];
            const int j = m.indexOf(n, m.farVertex(n, u, w));
            if (m.indexOf(n, u) < 0 || m.indexOf(n, w) < 0 || o.n[j] != std::int32_t(t))
                return where(t, "neighbour links disagree");
            if ((o.c[j] >= 0) != (tr.c[i] >= 0))
                return where(t, "constraint marked on one side only");
            if (tr.c[i] < 0 && inCircle(m.points[tr.v[0]], m.points[tr.v[1]], m.points[tr.v[2]], m.points[o.v[j]]) > 0)
                return where(t, "not constrained Delaunay");
        }
        if (tr.depthFreeOccluder >= 0 && !m.containedIn(std::int32_t(t), m.occluders[tr.depthFreeOccluder]))
            return where(t, "cover not certified");
        if (tr.depthOccluder >= 0 && !m.containedIn(std::int32_t(t), m.occluders[tr.depthOccluder]))
            return where(t, "depth cover not certified");
    }
    return {};
}

double CoverageTriangulation::constraintDeviation() const
{
    const Impl& m = *_impl;
    const auto distance = linfDistance;
    double worst = 0.0;
    for (const Triangle& t : m.tris)
        for (int i = 0; i < 3; ++i)
            if (t.c[i] >= 0)
            {
                const OriginalSegment& s = m.originals[t.c[i]];
                worst =
                    std::max({worst, distance(m.points[t.v[(i + 1) % 3]], s), distance(m.points[t.v[(i + 2) % 3]], s)});
            }
    return worst;
}

const CoverageStatistics& CoverageTriangulation::statistics() const
{
    _impl->stats.roundingFallbacks = _impl->roundingFallbacks;
    _impl->stats.triangles = std::uint32_t(_impl->tris.size());
    _impl->stats.vertices = std::uint32_t(_impl->points.size());
    return _impl->stats;
}
} // namespace osgVis::core::cdt
