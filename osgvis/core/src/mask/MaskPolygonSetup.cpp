// SPDX-License-Identifier: MIT
// Setup of one occluder polygon for the mask rasterizers (MaskPolygonSetup.h): convexity and
// degeneracy checks, signed edge functions with the grown square's reach along each normal, and
// the affine form of the largest depth over a grown square (the corner the gradient picks).
#include "MaskPolygonSetup.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace maskraster
{
namespace
{
// Pixels p of [0, size) whose square grown by `shrink`, [p - s, p + 1 + s], meets [lo, hi]; a hair
// wider than exact so that rounding never loses a touching pixel.
bool grownSpan(double lo, double hi, double shrink, std::uint32_t size, int& first, int& last)
{
    const double slack = RelativeTolerance * (1.0 + std::abs(lo) + std::abs(hi) + shrink);
    const double a = std::max(std::ceil(lo - 1.0 - shrink - slack), 0.0);
    const double b = std::min(std::floor(hi + shrink + slack), double(size) - 1.0);
    if (!(a <= b))
        return false;
    first = int(a);
    last = int(b);
    return true;
}

// The vertices' bounding box (mask coordinates).
struct VertexBounds
{
    double minX, minY, maxX, maxY;
};

// False when a vertex is not finite.
bool findVertexBounds(const std::vector<glm::dvec2>& v, VertexBounds& bounds)
{
    double minX = std::numeric_limits<double>::infinity(), minY = minX, maxX = -minX, maxY = -minX;
    for (const glm::dvec2& p : v)
    {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return false;
        minX = std::min(minX, p.x);
        maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y);
        maxY = std::max(maxY, p.y);
    }
    bounds = VertexBounds{minX, minY, maxX, maxY};
    return true;
}

// Twice the signed area (its sign gives the winding), by the fan from the first vertex.
double signedTwiceArea(const std::vector<glm::dvec2>& v)
{
    double twiceArea = 0.0;
    for (std::size_t i = 1; i + 1 < v.size(); ++i)
    {
        const glm::dvec2 a = v[i] - v[0], b = v[i + 1] - v[0];
        twiceArea += a.x * b.y - a.y * b.x;
    }
    return twiceArea;
}

// Fills the edge functions of the polygon's edges that are not too short to bound anything, and
// their unit directions; returns how many there are. `h` is half the grown square's side.
std::size_t setupEdges(const ScreenPolygon& polygon, double orientation, double size, double h, PolygonSetup& setup,
                       std::array<glm::dvec2, MaxEdges>& direction)
{
    const std::vector<glm::dvec2>& v = polygon.vertices;
    const std::size_t n = v.size();
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const glm::dvec2 d = v[(i + 1) % n] - v[i];
        const double length = std::sqrt(d.x * d.x + d.y * d.y);
        if (!(length > RelativeTolerance * size))
            continue; // a repeated vertex bounds nothing
        const double nx = -orientation * d.y / length, ny = orientation * d.x / length;
        direction[count] = d / length;
        setup.nx[count] = nx;
        setup.ny[count] = ny;
        setup.offset[count] = -(nx * v[i].x + ny * v[i].y);
        setup.reach[count] = (std::abs(nx) + std::abs(ny)) * h;
        setup.outline[count] = !(i < polygon.sharedEdge.size() && polygon.sharedEdge[i]);
        setup.slope[count] = float(nx);
        setup.slopeY[count] = float(ny);
        setup.reachF[count] = float(setup.reach[count]);
        setup.insideLimit[count] = setup.outline[count] ? setup.reachF[count] : -InfiniteDepth;
        ++count;
    }
    return count;
}

// True when the edges' unit directions turn one way only and sweep round once (setupPolygon).
bool turnsConvexly(const std::array<glm::dvec2, MaxEdges>& direction, std::size_t count, double orientation)
{
    int xSignChanges = 0, ySignChanges = 0;
    double lastX = 0.0, lastY = 0.0;
    for (std::size_t i = 0; i < 2 * count; ++i) // twice round, counting the changes of the second lap
    {
        const glm::dvec2 a = direction[i % count], b = direction[(i + 1) % count];
        const double turn = a.x * b.y - a.y * b.x;
        if (turn * orientation < -RelativeTolerance ||
            (std::abs(turn) <= RelativeTolerance && a.x * b.x + a.y * b.y < 0.0))
            return false;
        const bool counted = i >= count;
        if (std::abs(a.x) > 1e-9)
        {
            xSignChanges += counted && lastX * a.x < 0.0;
            lastX = a.x;
        }
        if (std::abs(a.y) > 1e-9)
        {
            ySignChanges += counted && lastY * a.y < 0.0;
            lastY = a.y;
        }
    }
    return xSignChanges <= 2 && ySignChanges <= 2;
}

// The depth part of the setup: the largest depth over a grown square (half side `h`) in affine form,
// and the margin for its evaluation's rounding.
void setupDepth(const DepthPlane& plane, const VertexBounds& bounds, double shrink, double h, const OcclusionMask& mask,
                PolygonSetup& setup)
{
    setup.inverse = plane.inverse;
    setup.da = plane.a;
    setup.db = plane.b;
    const double cornerSpread = (std::abs(plane.a) + std::abs(plane.b)) * h;
    setup.dc = plane.inverse ? plane.c - cornerSpread : plane.c + cornerSpread;
    setup.depthSlope = float(plane.a);
    setup.depthSlopeY = float(plane.b);
    setup.plane = plane;
    // Covers the double evaluation's own rounding (terms up to the largest coordinates reached).
    const double reachX = std::max(std::abs(bounds.minX), std::abs(bounds.maxX)) + 1.0 + shrink;
    const double reachY = std::max(std::abs(bounds.minY), std::abs(bounds.maxY)) + 1.0 + shrink;
    const double extent = std::max(reachX, double(mask.width())) * std::abs(plane.a) +
                          std::max(reachY, double(mask.height())) * std::abs(plane.b) + std::abs(plane.c) +
                          cornerSpread;
    setup.depthAbsMargin = float(extent * 1e-12);
}
} // namespace

bool prepareGroup(std::size_t count, const OcclusionMask& mask, double& shrink)
{
    if (count == 0 || mask.width() == 0 || mask.height() == 0 || !std::isfinite(shrink))
        return false;
    shrink = std::max(shrink, 0.0);
    return true;
}

void unite(PixelRange& region, const PixelRange& pixels)
{
    if (pixels.empty())
        return;
    region = PixelRange{std::min(region.x0, pixels.x0), std::min(region.y0, pixels.y0), std::max(region.x1, pixels.x1),
                        std::max(region.y1, pixels.y1)};
}

Shape setupPolygon(const ScreenPolygon& polygon, double shrink, const OcclusionMask& mask, PolygonSetup& setup)
{
    const std::vector<glm::dvec2>& v = polygon.vertices;
    VertexBounds bounds;
    if (!findVertexBounds(v, bounds))
        return Shape::NonFinite;
    setup.pixels = PixelRange{};
    if (v.empty())
        return Shape::Degenerate; // touches nothing
    PixelRange& r = setup.pixels;
    if (!grownSpan(bounds.minX, bounds.maxX, shrink, mask.width(), r.x0, r.x1) ||
        !grownSpan(bounds.minY, bounds.maxY, shrink, mask.height(), r.y0, r.y1))
        r = PixelRange{};

    const DepthPlane& plane = polygon.depth;
    const std::size_t n = v.size();
    if (n < 3 || n > MaxEdges || !std::isfinite(plane.a) || !std::isfinite(plane.b) || !std::isfinite(plane.c))
        return Shape::Degenerate;
    const double size = std::max(bounds.maxX - bounds.minX, bounds.maxY - bounds.minY);
    const double twiceArea = signedTwiceArea(v);
    if (!(std::abs(twiceArea) > RelativeTolerance * size * size))
        return Shape::Degenerate;
    const double orientation = twiceArea > 0.0 ? 1.0 : -1.0;

    // Convex = every turn the same way (collinear allowed, reversals not) and the direction sweeps
    // round once (its x and y components change sign at most twice each), which rules out stars.
    const double h = 0.5 + shrink;
    std::array<glm::dvec2, MaxEdges> direction;
    const std::size_t count = setupEdges(polygon, orientation, size, h, setup, direction);
    if (count < 3 || !turnsConvexly(direction, count, orientation))
        return Shape::Degenerate;
    setup.edgeCount = count;

    setupDepth(plane, bounds, shrink, h, mask, setup);
    return Shape::Convex;
}

void decidePixel(const PolygonSetup& s, int x, int y, bool& touched, bool& outside)
{
    const double cx = x + 0.5, cy = y + 0.5;
    touched = true;
    outside = false;
    for (std::size_t e = 0; e < s.edgeCount; ++e)
    {
        const double f = s.nx[e] * cx + s.ny[e] * cy + s.offset[e];
        touched = touched && f >= -s.reach[e];
        outside = outside || (s.outline[e] && f < s.reach[e]);
    }
}
} // namespace maskraster

double DepthPlane::maxOverSquare(double x0, double y0, double x1, double y1) const
{
    const double corners[4] = {a * x0 + b * y0 + c, a * x1 + b * y0 + c, a * x0 + b * y1 + c, a * x1 + b * y1 + c};
    const double infinity = std::numeric_limits<double>::infinity();
    if (inverse)
    {
        const double smallest = *std::min_element(corners, corners + 4);
        return smallest > 0.0 ? 1.0 / smallest : infinity; // NaN: +inf too
    }
    const double largest = *std::max_element(corners, corners + 4);
    return std::isnan(largest) ? infinity : largest;
}

} // namespace osgVis::core
