// SPDX-License-Identifier: MIT
// 2-D convex clipping for the multifocal z-buffer (Marsden & Guibas, §4.2 coverage maps): umbrae
// are intersections of convex projections, coverage maps subtract umbrae from a pixel's square.
#include <osgVis/core/geometry/ConvexArea2.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
double cross2(const Vec2& o, const Vec2& a, const Vec2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double signedArea(const ConvexArea2& area)
{
    double twice = 0.0;
    for (std::size_t i = 0, n = area.size(); i < n; ++i)
    {
        const Vec2& a = area[i];
        const Vec2& b = area[(i + 1) % n];
        twice += a.x * b.y - a.y * b.x;
    }
    return 0.5 * twice;
}

ConvexArea2 convexIntersection(ConvexArea2 subject, const ConvexArea2& clip)
{
    ConvexArea2 next;
    for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e)
    {
        const Vec2& a = clip[e];
        const Vec2& b = clip[(e + 1) % clip.size()];
        next.clear();
        for (std::size_t i = 0; i < subject.size(); ++i)
        {
            const Vec2& p = subject[i];
            const Vec2& q = subject[(i + 1) % subject.size()];
            const double sp = cross2(a, b, p), sq = cross2(a, b, q);
            if (sp >= 0.0)
                next.push_back(p);
            if ((sp >= 0.0) != (sq >= 0.0))
                next.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        subject.swap(next);
    }
    return subject;
}

bool hasArea(const ConvexArea2& area)
{
    return area.size() >= 3 && signedArea(area) > 0.0;
}

void makeCounterClockwise(ConvexArea2& area)
{
    const double a = area.size() >= 3 ? signedArea(area) : 0.0;
    if (!(a != 0.0) || !std::isfinite(a))
        area.clear();
    else if (a < 0.0)
        std::reverse(area.begin(), area.end());
}

void halfPlanesOf(const ConvexArea2& area, double erosion, std::vector<HalfPlane2>& out)
{
    out.clear();
    for (std::size_t i = 0, n = area.size(); i < n; ++i)
    {
        const Vec2& a = area[i];
        const Vec2& b = area[(i + 1) % n];
        const Vec2 edge = b - a;
        const double length = std::sqrt(edge.x * edge.x + edge.y * edge.y);
        if (!(length > 0.0))
            continue;
        // Counter-clockwise: the inside is to the left, so the outward normal is (dy, -dx).
        HalfPlane2 h;
        h.normal = Vec2(edge.y, -edge.x) / length;
        h.offset = h.normal.x * a.x + h.normal.y * a.y - erosion;
        out.push_back(h);
    }
}

namespace
{
// Sutherland–Hodgman against one line; `sign` = +1 keeps excess <= 0, -1 keeps excess >= 0.
void clip(const ConvexArea2& in, const HalfPlane2& h, double sign, ConvexArea2& out)
{
    out.clear();
    const std::size_t n = in.size();
    if (n == 0)
        return;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec2& a = in[i];
        const Vec2& b = in[(i + 1) % n];
        const double ea = sign * h.excess(a);
        const double eb = sign * h.excess(b);
        if (ea <= 0.0)
            out.push_back(a);
        if ((ea < 0.0 && eb > 0.0) || (ea > 0.0 && eb < 0.0))
        {
            const double t = ea / (ea - eb);
            out.push_back(a + (b - a) * t);
        }
    }
    if (out.size() < 3)
        out.clear();
}
} // namespace

void clipInside(const ConvexArea2& in, const HalfPlane2& h, ConvexArea2& out)
{
    clip(in, h, 1.0, out);
}

void clipOutside(const ConvexArea2& in, const HalfPlane2& h, ConvexArea2& out)
{
    clip(in, h, -1.0, out);
}

void clipInsideAll(ConvexArea2& area, const std::vector<HalfPlane2>& halfPlanes, ConvexArea2& scratch)
{
    for (const HalfPlane2& h : halfPlanes)
    {
        clipInside(area, h, scratch);
        area.swap(scratch);
        if (area.empty())
            return;
    }
}

bool subtractConvex(std::vector<ConvexArea2>& pieces, const std::vector<HalfPlane2>& region, std::size_t maxPieces)
{
    std::vector<ConvexArea2> remaining;
    ConvexArea2 inside, next, outside;
    for (const ConvexArea2& piece : pieces)
    {
        inside = piece;
        for (const HalfPlane2& h : region)
        {
            clipOutside(inside, h, outside);
            if (hasArea(outside))
            {
                if (remaining.size() >= maxPieces)
                    return false;
                remaining.push_back(outside);
            }
            clipInside(inside, h, next);
            inside.swap(next);
            if (!hasArea(inside))
                break;
        }
        // What is left in `inside` lies in the region: it is covered and goes.
    }
    pieces.swap(remaining);
    return true;
}
} // namespace osgVis::core
