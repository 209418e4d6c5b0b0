// SPDX-License-Identifier: MIT
// Luka, "Visibility culling with a constrained Delaunay triangulation", §2.2.2-§2.2.3: occluders
// and tested bounds projected into the screen-plane triangulation. The margins that keep this
// conservative (erosion of unshared occluder edges, dilation of queried outlines, shared edges
// ending on grid points of one common integer segment) are derived in docs/cdt.md.
#include "ScreenGrid.h"

#include <osgVis/core/geometry/ConvexHull2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace osgVis::core
{
namespace
{
using glm::dvec2;

constexpr std::uint32_t NotKept = ~std::uint32_t(0);

double cross(const dvec2& o, const dvec2& a, const dvec2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

std::int64_t cross(const cdt::GridPoint& o, const cdt::GridPoint& a, const cdt::GridPoint& b)
{
    return (std::int64_t(a.x) - o.x) * (std::int64_t(b.y) - o.y) - (std::int64_t(a.y) - o.y) * (std::int64_t(b.x) - o.x);
}

/// A polygon vertex with the label of the edge that starts at it: the index of the original edge
/// it is a piece of when that edge is kept unshrunk, NotKept otherwise.
struct Labelled
{
    dvec2 p;
    std::uint32_t edge;
};

/// Keeps the part of `poly` where n·(x - o) >= offset; the edge it cuts along is NotKept.
void clipHalfPlane(std::vector<Labelled>& poly, const dvec2& o, const dvec2& n, double offset)
{
    std::vector<Labelled> out;
    out.reserve(poly.size() + 1);
    const std::size_t count = poly.size();
    for (std::size_t i = 0; i < count; ++i)
    {
        const Labelled& a = poly[i];
        const Labelled& b = poly[(i + 1) % count];
        const double da = glm::dot(n, a.p - o) - offset, db = glm::dot(n, b.p - o) - offset;
        if (da >= 0.0)
            out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0))
        {
            const double t = da / (da - db);
            // Entering the kept side the piece continues a's edge; leaving it, the cut follows.
            out.push_back({a.p + (b.p - a.p) * t, da >= 0.0 ? NotKept : a.edge});
        }
    }
    poly.swap(out);
}

cdt::GridPoint roundPoint(const dvec2& p)
{
    return {std::int32_t(std::llround(p.x)), std::int32_t(std::llround(p.y))};
}
} // namespace

bool ScreenGrid::set(const View& view, double tolerancePixels)
{
    const std::uint32_t largest = std::max(view.viewportWidth, view.viewportHeight);
    if (view.viewportWidth == 0 || view.viewportHeight == 0)
        return false;
    // The guard band is the frame grown to twice its size: at most `largest` pixels either side of
    // the centre, kept within 2^27 grid units so the record's exact range has room to spare.
    double upp = 1.0;
    while (upp * 2.0 * largest <= double(1 << 27))
        upp *= 2.0;
    _unitsPerPixel = upp;
    _halfW = std::int32_t(upp * view.viewportWidth / 2.0);
    _halfH = std::int32_t(upp * view.viewportHeight / 2.0);
    _limit = 2 * std::max(_halfW, _halfH);
    _scaleX = _halfW;
    _scaleY = _halfH;
    _tolerance = std::max(tolerancePixels, 0.0) * upp + 2.0; // 2: the record's rounding, with room
    _lattice = std::max(1.0, upp / 64.0);
    _worldToClip = view.projectionMatrix * view.viewMatrix;
    _orthographic = view.orthographic;
    // One step of the depth buffer: its range in w (NDC depth's 2, or at most 1/near) over 2^bits.
    const double step = std::ldexp(1.0, -int(std::min<std::uint32_t>(view.depthBits, 64)));
    if (_orthographic)
    {
        _depthMargin = 16.0 * 2.0 * step;
        _orthographicDepthScale = std::abs(view.projectionMatrix[2][2]);
    }
    else
    {
        const double n = nearDistance(view);
        if (!(n > 0.0) || !std::isfinite(n))
            return false;
        _depthMargin = 16.0 * step / n;
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(_worldToClip[c][r]))
                return false;
    return true;
}

double ScreenGrid::depthSeparation(double distance) const
{
    if (_orthographic) // parallel rays: the gap along the ray is the gap in depth
        return _depthMargin / std::max(_orthographicDepthScale, 1e-300);
    // Points at s and s + g along a ray at angle θ to the axis differ in w by g / (s (s + g) cos θ):
    // at least the margin m once g ≥ m s² cos θ / (1 - m s cos θ), which is largest on the axis.
    const double reach = _depthMargin * distance;
    return reach < 1.0 ? _depthMargin * distance * distance / (1.0 - reach) : std::numeric_limits<double>::infinity();
}

int ScreenGrid::sideOf(const Vec3& a, const Vec3& b, const Vec3& p) const
{
    dvec2 screen[3];
    const Vec3* points[3] = {&a, &b, &p};
    for (int i = 0; i < 3; ++i)
    {
        const Vec4 clip = _worldToClip * Vec4(*points[i], 1.0);
        if (!(clip.w > 0.0) || !(clip.z > -clip.w))
            return 0;
        screen[i] = {clip.x / clip.w, clip.y / clip.w};
    }
    const double turn = cross(screen[0], screen[1], screen[2]);
    return turn > 0.0 ? 1 : (turn < 0.0 ? -1 : 0);
}

bool ScreenGrid::projectBox(const Aabb& box, std::vector<cdt::GridPoint>& outline, double& nearestW) const
{
    std::vector<dvec2> points;
    points.reserve(8);
    nearestW = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < 8; ++i)
    {
        const Vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z);
        const Vec4 clip = _worldToClip * Vec4(corner, 1.0);
        // A corner on or before the near plane: the box reaches the eye's side, never hidden.
        if (!(clip.w > 0.0) || !(clip.z > -clip.w))
            return false;
        points.emplace_back(clip.x / clip.w * _scaleX, clip.y / clip.w * _scaleY);
        nearestW = std::max(nearestW, _orthographic ? -clip.z : 1.0 / clip.w);
    }
    std::vector<dvec2> hull;
    convexHullInPlace(points, hull, [](const dvec2& o, const dvec2& a, const dvec2& b) { return cross(o, a, b); });
    if (points.size() < 3)
        return false;
    std::vector<Labelled> poly;
    for (const dvec2& p : points)
        poly.push_back({p, NotKept});
    const double fx = _halfW + _tolerance, fy = _halfH + _tolerance;
    clipHalfPlane(poly, {-fx, 0.0}, {1.0, 0.0}, 0.0);
    clipHalfPlane(poly, {fx, 0.0}, {-1.0, 0.0}, 0.0);
    clipHalfPlane(poly, {0.0, -fy}, {0.0, 1.0}, 0.0);
    clipHalfPlane(poly, {0.0, fy}, {0.0, -1.0}, 0.0);
    if (poly.size() < 3)
        return false;
    // Dilation by the square of half-width τ (+1 for rounding) contains the dilation by a disc.
    const double grow = _tolerance + 1.0;
    outline.clear();
    for (const Labelled& v : poly)
        for (int s = 0; s < 4; ++s)
            outline.push_back(roundPoint(v.p + dvec2((s & 1) ? grow : -grow, (s & 2) ? grow : -grow)));
    std::vector<cdt::GridPoint> outlineHull;
    convexHullInPlace(outline, outlineHull,
                      [](const cdt::GridPoint& o, const cdt::GridPoint& a, const cdt::GridPoint& b)
                      { return cross(o, a, b); });
    return outline.size() >= 3;
}

namespace
{
/// A clip-space vertex with the label of the edge that starts at it (as in Labelled).
struct ClipVertex
{
    Vec4 c;
    std::uint32_t edge;
};

// Clip space, clipped to the near plane and the guard band (|x|, |y| <= 2w). An edge keeps its
// label only while both its ends survive: a clipped edge ends where its twin's may not.
bool clipToGuardBand(const Mat4& worldToClip, const std::vector<Vec3>& vertices, const std::vector<bool>* keepEdge,
                     std::vector<ClipVertex>& poly)
{
    const std::size_t count = vertices.size();
    poly.reserve(count + 5);
    for (std::size_t i = 0; i < count; ++i)
        poly.push_back({worldToClip * Vec4(vertices[i], 1.0),
                        keepEdge && i < keepEdge->size() && (*keepEdge)[i] ? std::uint32_t(i) : NotKept});
    const Vec4 planes[5] = {{0, 0, 1, 1}, {-1, 0, 0, 2}, {1, 0, 0, 2}, {0, -1, 0, 2}, {0, 1, 0, 2}};
    for (const Vec4& plane : planes)
    {
        std::vector<ClipVertex> next;
        next.reserve(poly.size() + 1);
        for (std::size_t i = 0; i < poly.size(); ++i)
        {
            const ClipVertex& a = poly[i];
            const ClipVertex& b = poly[(i + 1) % poly.size()];
            const double da = glm::dot(plane, a.c), db = glm::dot(plane, b.c);
            if (da >= 0.0)
                next.push_back({a.c, db >= 0.0 ? a.edge : NotKept});
            if ((da >= 0.0) != (db >= 0.0))
                next.push_back({a.c + (b.c - a.c) * (da / (da - db)), NotKept});
        }
        poly.swap(next);
        if (poly.size() < 3)
            return false;
    }
    return true;
}

void reverseOrientation(std::vector<Labelled>& screen, std::vector<double>& nearness)
{
    // Reverse; the edge starting at vertex j of the reversed list is the old edge ending there.
    std::vector<Labelled> reversed(screen.size());
    std::vector<double> w(screen.size());
    for (std::size_t j = 0; j < screen.size(); ++j)
    {
        const std::size_t from = screen.size() - 1 - j;
        const std::size_t to = (from + screen.size() - 1) % screen.size();
        reversed[j] = {screen[from].p, screen[to].edge};
        w[j] = nearness[from];
    }
    screen.swap(reversed);
    nearness.swap(w);
}

/// The clipped polygon in grid units, counter-clockwise, and each vertex's nearness. False when a
/// vertex is not in front of the eye or the area is one square grid unit or less.
bool projectCounterClockwise(const std::vector<ClipVertex>& poly, double scaleX, double scaleY, bool orthographic,
                             std::vector<Labelled>& screen, std::vector<double>& nearness)
{
    for (const ClipVertex& v : poly)
    {
        if (!(v.c.w > 0.0))
            return false;
        screen.push_back({{v.c.x / v.c.w * scaleX, v.c.y / v.c.w * scaleY}, v.edge});
        nearness.push_back(orthographic ? -v.c.z : 1.0 / v.c.w);
    }
    double area = 0.0;
    for (std::size_t i = 0; i < screen.size(); ++i)
        area += cross({0.0, 0.0}, screen[i].p, screen[(i + 1) % screen.size()].p);
    if (!(std::abs(area) > 1.0))
        return false;
    if (area < 0.0)
        reverseOrientation(screen, nearness);
    return true;
}

// Nearness is affine over the screen for a planar polygon: fit it on the largest triangle.
cdt::AffineNearness fitNearness(const std::vector<Labelled>& screen, const std::vector<double>& nearness)
{
    std::size_t bi = 0, bj = 1, bk = 2;
    double best = 0.0;
    const std::size_t n = screen.size();
    for (std::size_t j = 1; j + 1 < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k)
        {
            const double a = std::abs(cross(screen[0].p, screen[j].p, screen[k].p));
            if (a > best)
                best = a, bj = j, bk = k;
        }
    const dvec2 p0 = screen[bi].p, p1 = screen[bj].p, p2 = screen[bk].p;
    const double det = cross(p0, p1, p2);
    if (!(std::abs(det) > 0.0))
        return {};
    const double w0 = nearness[bi], w1 = nearness[bj], w2 = nearness[bk];
    const double a = ((w1 - w0) * (p2.y - p0.y) - (w2 - w0) * (p1.y - p0.y)) / det;
    const double b = ((w2 - w0) * (p1.x - p0.x) - (w1 - w0) * (p2.x - p0.x)) / det;
    return {a, b, w0 - a * p0.x - b * p0.y, std::isfinite(a) && std::isfinite(b)};
}

// Erode every edge that is not kept by τ: clip by the half-planes τ inside them.
bool erodeUnkeptEdges(std::vector<Labelled>& screen, double tolerance)
{
    const std::vector<Labelled> original = screen;
    for (std::size_t i = 0; i < original.size(); ++i)
    {
        if (original[i].edge != NotKept)
            continue;
        const dvec2 a = original[i].p, b = original[(i + 1) % original.size()].p;
        const dvec2 d = b - a;
        const double len = glm::length(d);
        if (!(len > 0.0))
            continue;
        clipHalfPlane(screen, a, dvec2(-d.y, d.x) / len, tolerance);
        if (screen.size() < 3)
            return false;
    }
    return true;
}

/// The grid's mapping of world points to the lattice.
struct Lattice
{
    const Mat4& worldToClip;
    double scaleX, scaleY, step;

    // The lattice segments of kept edges, from the unclipped vertices (the twin computes the same).
    cdt::GridPoint point(const Vec3& world) const
    {
        const Vec4 c = worldToClip * Vec4(world, 1.0);
        const dvec2 p(c.x / c.w * scaleX, c.y / c.w * scaleY);
        return cdt::GridPoint{std::int32_t(std::llround(p.x / step) * std::int64_t(step)),
                              std::int32_t(std::llround(p.y / step) * std::int64_t(step))};
    }
};

// Round: a vertex on a kept edge moves along that edge's integer segment, inwards, to a grid
// point of it; every other vertex to the nearest grid point (τ leaves room for that).
cdt::GridPoint placeVertex(const std::vector<Labelled>& screen, std::size_t index, const std::vector<Vec3>& vertices,
                           const Lattice& lattice, bool& ok)
{
    const std::size_t count = vertices.size();
    const std::size_t n = screen.size();
    const Labelled& v = screen[index];
    const Labelled& before = screen[(index + n - 1) % n];
    if (v.edge == NotKept && before.edge == NotKept)
        return roundPoint(v.p);
    if (v.edge != NotKept && before.edge != NotKept)
    {
        // Between two kept edges: their common original vertex, the same in every polygon.
        const std::uint32_t e1 = before.edge, e2 = v.edge;
        const std::uint32_t common = (e1 == e2 || e1 == (e2 + 1) % count) ? e1 : (e1 + 1) % count;
        return lattice.point(vertices[common]);
    }
    // On one kept edge: its end is the other end of this piece of it.
    const bool starts = v.edge != NotKept;
    const std::uint32_t edge = starts ? v.edge : before.edge;
    const dvec2 other = starts ? screen[(index + 1) % n].p : before.p;
    const cdt::GridPoint a = lattice.point(vertices[edge]);
    const cdt::GridPoint b = lattice.point(vertices[(edge + 1) % count]);
    const std::int64_t dx = std::int64_t(b.x) - a.x, dy = std::int64_t(b.y) - a.y;
    const std::int64_t g = std::gcd(std::llabs(dx), std::llabs(dy));
    if (g == 0)
    {
        ok = false;
        return a;
    }
    const double length2 = double(dx) * double(dx) + double(dy) * double(dy);
    auto parameter = [&](const dvec2& p) {
        return std::clamp(((p.x - a.x) * double(dx) + (p.y - a.y) * double(dy)) / length2, 0.0, 1.0);
    };
    const double t = parameter(v.p);
    // Inwards: towards the piece's other end, so the piece only gets shorter.
    const std::int64_t step = parameter(other) > t ? std::int64_t(std::ceil(t * double(g)))
                                                   : std::int64_t(std::floor(t * double(g)));
    const std::int64_t s = std::clamp<std::int64_t>(step, 0, g);
    return {std::int32_t(a.x + dx / g * s), std::int32_t(a.y + dy / g * s)};
}

/// Drops the vertices where the outline runs straight on (or doubles back onto itself); false at
/// a turn the wrong way.
bool dropStraightVertices(std::vector<cdt::GridPoint>& points)
{
    for (std::size_t i = 0; points.size() >= 3 && i < points.size();)
    {
        const std::size_t n = points.size();
        const std::int64_t turn = cross(points[(i + n - 1) % n], points[i], points[(i + 1) % n]);
        if (turn < 0)
            return false;
        if (turn == 0)
            points.erase(points.begin() + std::ptrdiff_t(i));
        else
            ++i;
    }
    return true;
}
} // namespace

bool ScreenGrid::projectOccluder(const std::vector<Vec3>& vertices, const std::vector<bool>* keepEdge, GridPolygon& out) const
{
    if (vertices.size() < 3)
        return false;
    std::vector<ClipVertex> poly;
    if (!clipToGuardBand(_worldToClip, vertices, keepEdge, poly))
        return false;
    std::vector<Labelled> screen;
    std::vector<double> nearness;
    if (!projectCounterClockwise(poly, _scaleX, _scaleY, _orthographic, screen, nearness))
        return false;
    out.nearness = fitNearness(screen, nearness);
    if (!erodeUnkeptEdges(screen, _tolerance))
        return false;

    const Lattice lattice{_worldToClip, _scaleX, _scaleY, _lattice};
    bool ok = true;
    out.points.clear();
    for (std::size_t i = 0; i < screen.size(); ++i)
        out.points.push_back(placeVertex(screen, i, vertices, lattice, ok));
    // Strictly convex, counter-clockwise, and every kept edge still of positive length; otherwise
    // fall back to eroding everything (the hull of points that all lie τ - 1 inside is safe).
    // Straight-line vertices (kept where the neighbour across an edge changes) and points that
    // rounding made coincide or collinear go; a turn the wrong way means rounding broke convexity.
    if (ok && dropStraightVertices(out.points) && out.points.size() >= 3)
        return true;
    if (!keepEdge)
        return false;
    return projectOccluder(vertices, nullptr, out);
}
} // namespace osgVis::core
