// SPDX-License-Identifier: MIT
// Marsden & Guibas, "The multifocal z-buffer" — §3.2 (the occlusion criterion along a bundle of
// rays), §4.1 (one value per pixel: the largest least-h of an occluder covering the bundle),
// §4.2 (coverage maps on umbra boundaries), §5.3 (the umbra as the intersection of the central
// projections from V's corners). Why each step is conservative: docs/multifocal.md.
#include "MultifocalZBuffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
namespace
{
constexpr double NoValue = -std::numeric_limits<double>::infinity();

enum class SquareCover
{
    Outside, // the square misses the region
    Partial,
    Whole,
};

// How the region bounded by `edges` covers a pixel's square.
SquareCover squareCover(const ConvexArea2& square, const std::vector<HalfPlane2>& edges)
{
    bool whole = true;
    for (const HalfPlane2& h : edges)
    {
        // The corner farthest out decides "inside", the one farthest in decides "outside".
        const double x = h.normal.x >= 0.0 ? square[1].x : square[0].x;
        const double y = h.normal.y >= 0.0 ? square[2].y : square[0].y;
        const double xIn = h.normal.x >= 0.0 ? square[0].x : square[1].x;
        const double yIn = h.normal.y >= 0.0 ? square[0].y : square[2].y;
        if (h.excess(Vec2(x, y)) > 0.0)
            whole = false;
        if (h.excess(Vec2(xIn, yIn)) >= 0.0)
            return SquareCover::Outside;
    }
    return whole ? SquareCover::Whole : SquareCover::Partial;
}
} // namespace

void MultifocalZBuffer::reset(const CorrespondencePlane& plane, const Aabb& volume, double margin,
                              double depthGapPerDistance2)
{
    _depthGapPerDistance2 = depthGapPerDistance2;
    _plane = plane;
    _corners = boxCorners(volume);
    _volumeMinH = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 8; ++k)
    {
        _cornerH[k] = plane.h(_corners[k]);
        _volumeMinH = std::min(_volumeMinH, _cornerH[k]);
    }
    _margin = margin;
    // Umbrae shrink by this before use, far above the rounding of a projection (a few ulps of the
    // window's coordinates), so rounding can only make them smaller.
    const Vec2 span = plane.windowMax() - plane.origin;
    const double scale = std::max({std::abs(plane.origin.x), std::abs(plane.origin.y), span.x, span.y, 1e-300});
    _erosion = 1e-9 * scale;
    const std::size_t n = std::size_t(plane.width) * std::size_t(plane.height);
    _full.assign(n, NoValue);
    _value.assign(n, NoValue);
    _dirty.assign(n, 0);
    _fragments.resize(n);
    for (auto& f : _fragments)
        f.clear();
    _statistics = {};
}

double MultifocalZBuffer::lowestHitH(const ConvexArea2& region, const Plane& polygonPlane, double polygonMinH) const
{
    // Every ray from V through `region` meets the occluder (the region lies in its umbra). Where the
    // rays from corner c through the region's vertices q meet the occluder's plane, h = h(c)(1 - s)
    // (h(q) = 0 on P); the hits of all rays lie in the hull of these points, and h is affine on the
    // plane, so its least value over them bounds the least h of every hit from below.
    double lowest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 8; ++k)
    {
        const Vec3& c = _corners[k];
        const double atCorner = polygonPlane.distance(c);
        for (const Vec2& q2 : region)
        {
            const Vec3 q = _plane.lift(q2);
            const double along = glm::dot(polygonPlane.normal, q - c);
            const double s = -atCorner / along;
            if (!(s > 0.0) || !std::isfinite(s))
                return polygonMinH; // cannot bound it this way: the occluder's own least h holds
            lowest = std::min(lowest, _cornerH[k] * (1.0 - s));
        }
    }
    return std::max(lowest, polygonMinH);
}

bool MultifocalZBuffer::castUmbra(const std::vector<Vec3>& polygon)
{
    // The umbra: points q of P such that every ray from V through q meets the polygon. A ray from
    // corner c through q meets it iff q lies in its projection from c; the rays from V's interior
    // follow by convexity (docs/multifocal.md, "Umbra"), so the umbra is the intersection of the
    // eight projections.
    for (int k = 0; k < 8; ++k)
    {
        ConvexArea2& projection = _projections[k];
        projection.clear();
        for (const Vec3& p : polygon)
            projection.push_back(_plane.project(_corners[k], p));
        makeCounterClockwise(projection);
        if (projection.empty())
        {
            ++_statistics.emptyUmbrae;
            return false;
        }
    }
    _umbra = _projections[0];
    for (int k = 1; k < 8 && !_umbra.empty(); ++k)
    {
        halfPlanesOf(_projections[k], 0.0, _edges);
        clipInsideAll(_umbra, _edges, _clip);
    }
    if (!hasArea(_umbra))
    {
        ++_statistics.emptyUmbrae;
        return false;
    }
    halfPlanesOf(_umbra, _erosion, _edges);
    return true;
}

MultifocalZBuffer::PixelRange MultifocalZBuffer::umbraPixels() const
{
    Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const Vec2& q : _umbra)
    {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    PixelRange range;
    range.i0 = std::max(0, int(std::floor((lo.x - _plane.origin.x) / _plane.pixel)));
    range.j0 = std::max(0, int(std::floor((lo.y - _plane.origin.y) / _plane.pixel)));
    range.i1 = std::min(_plane.width - 1, int(std::floor((hi.x - _plane.origin.x) / _plane.pixel)));
    range.j1 = std::min(_plane.height - 1, int(std::floor((hi.y - _plane.origin.y) / _plane.pixel)));
    return range;
}

void MultifocalZBuffer::coverPixel(int i, int j, const Plane& polygonPlane, double polygonMinH)
{
    const ConvexArea2 square = _plane.square(i, j);
    const SquareCover cover = squareCover(square, _edges);
    if (cover == SquareCover::Outside)
        return;
    const std::size_t index = std::size_t(j) * std::size_t(_plane.width) + std::size_t(i);
    if (cover == SquareCover::Whole)
    {
        const double z = lowestHitH(square, polygonPlane, polygonMinH);
        if (z > _full[index])
        {
            _full[index] = z;
            _dirty[index] = 1;
            ++_statistics.fullPixels;
        }
        return;
    }
    _piece = square;
    clipInsideAll(_piece, _edges, _clip);
    if (!hasArea(_piece))
        return;
    const double z = lowestHitH(_piece, polygonPlane, polygonMinH);
    if (!(z > _full[index]) || maxFragmentsPerPixel == 0)
        return;
    storeFragment(index, z);
}

void MultifocalZBuffer::storeFragment(std::size_t index, double z)
{
    std::vector<Fragment>& fragments = _fragments[index];
    if (fragments.size() >= maxFragmentsPerPixel)
    {
        auto lowest = std::min_element(fragments.begin(), fragments.end(),
                                       [](const Fragment& a, const Fragment& b) { return a.z < b.z; });
        ++_statistics.droppedFragments;
        if (lowest->z >= z)
            return;
        *lowest = Fragment{z, _piece};
    }
    else
        fragments.push_back(Fragment{z, _piece});
    ++_statistics.fragments;
    _dirty[index] = 1;
}

bool MultifocalZBuffer::insert(const std::vector<Vec3>& polygon, const Plane& polygonPlane)
{
    if (polygon.size() < 3 || _plane.width <= 0 || _plane.height <= 0)
        return false;
    double minH = std::numeric_limits<double>::infinity(), maxH = -minH;
    for (const Vec3& p : polygon)
    {
        const double hp = _plane.h(p);
        minH = std::min(minH, hp);
        maxH = std::max(maxH, hp);
    }
    if (!(maxH < _volumeMinH - _margin))
        return false;

    if (!castUmbra(polygon))
        return false;
    const PixelRange range = umbraPixels();
    if (range.i0 > range.i1 || range.j0 > range.j1)
        return false;
    ++_statistics.inserted;

    for (int j = range.j0; j <= range.j1; ++j)
        for (int i = range.i0; i <= range.i1; ++i)
            coverPixel(i, j, polygonPlane, minH);
    return true;
}

double MultifocalZBuffer::pixelValue(std::size_t index)
{
    if (!_dirty[index])
        return _value[index];
    _dirty[index] = 0;
    double best = _full[index];
    // The coverage map (§4.2): the value is the largest z such that the pieces of value >= z cover
    // the whole pixel; found by taking pieces in falling z and subtracting them from the square.
    _order.clear();
    for (const Fragment& f : _fragments[index])
        if (f.z > best)
            _order.push_back(&f);
    if (!_order.empty())
    {
        std::sort(_order.begin(), _order.end(), [](const Fragment* a, const Fragment* b) { return a->z > b->z; });
        const int i = int(index % std::size_t(_plane.width)), j = int(index / std::size_t(_plane.width));
        _pieces.assign(1, _plane.square(i, j));
        for (const Fragment* f : _order)
        {
            halfPlanesOf(f->area, 0.0, _fragmentEdges);
            if (!subtractConvex(_pieces, _fragmentEdges, maxCoverPieces))
                break;
            if (_pieces.empty())
            {
                best = std::max(best, f->z);
                break;
            }
        }
    }
    _value[index] = best;
    return best;
}

bool MultifocalZBuffer::hidden(const Vec3* points, std::size_t count)
{
    ++_statistics.queries;
    if (count == 0 || _plane.width <= 0)
        return false;
    double maxH = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < count; ++i)
        maxH = std::max(maxH, _plane.h(points[i]));
    // Rays from V reach P only through points below V's least h; anything at or above it has rays
    // that never cross P, so this plane proves nothing about it.
    if (!(maxH < _volumeMinH - _margin))
        return false;
    // The rays from V to the points' hull cross P inside the hull of the projections of every
    // point from every corner (docs/multifocal.md, "Footprint").
    Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    double farthest2 = 0.0;
    for (int k = 0; k < 8; ++k)
        for (std::size_t i = 0; i < count; ++i)
        {
            const Vec2 q = _plane.project(_corners[k], points[i]);
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
            farthest2 = std::max(farthest2, glm::dot(points[i] - _corners[k], points[i] - _corners[k]));
        }
    const Vec2 windowMax = _plane.windowMax();
    const double slack = _erosion;
    if (!(lo.x > _plane.origin.x + slack && lo.y > _plane.origin.y + slack && hi.x < windowMax.x - slack &&
          hi.y < windowMax.y - slack))
        return false;
    // Pixels are closed squares: a footprint touching a pixel's edge counts that pixel too.
    const int i0 = std::max(0, int(std::floor((lo.x - slack - _plane.origin.x) / _plane.pixel)));
    const int j0 = std::max(0, int(std::floor((lo.y - slack - _plane.origin.y) / _plane.pixel)));
    const int i1 = std::min(_plane.width - 1, int(std::floor((hi.x + slack - _plane.origin.x) / _plane.pixel)));
    const int j1 = std::min(_plane.height - 1, int(std::floor((hi.y + slack - _plane.origin.y) / _plane.pixel)));
    const double needed = maxH + _margin + _depthGapPerDistance2 * farthest2;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            if (!(pixelValue(std::size_t(j) * std::size_t(_plane.width) + std::size_t(i)) > needed))
                return false;
    ++_statistics.hiddenQueries;
    return true;
}
} // namespace osgVis::core
