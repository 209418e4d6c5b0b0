// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The multifocal z-buffer of one correspondence plane (Marsden & Guibas, §3.2, §4.1, §4.2): per
/// pixel p, the largest value z such that every ray from every point of V through p meets an
/// inserted occluder at h >= z. An occludee whose largest h is below the values of every pixel its
/// rays cross is hidden from all of V. Pixels that an umbra covers whole keep one value; pixels on
/// umbra boundaries keep coverage maps (the umbra pieces inside them with their values) and take
/// the least value over the sub-regions the pieces make. docs/multifocal.md derives each step.
#include "CorrespondencePlane.h"

#include <osgVis/core/geometry/Plane.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
struct ZBufferStatistics
{
    std::uint64_t inserted = 0;     ///< occluders whose umbra met the window
    std::uint64_t emptyUmbrae = 0;  ///< occluders too small (or too near P's edge) to cast one
    std::uint64_t fullPixels = 0;   ///< pixel updates by an umbra covering the whole pixel
    std::uint64_t fragments = 0;    ///< coverage-map pieces stored
    std::uint64_t droppedFragments = 0;
    std::uint64_t queries = 0, hiddenQueries = 0;
};

class MultifocalZBuffer
{
public:
    std::size_t maxFragmentsPerPixel = 8; ///< beyond it the lowest piece goes (covering less is safe)
    std::size_t maxCoverPieces = 48;      ///< a coverage map needing more pieces stops (safe)

    /// Clears the buffer for `plane` and the view volume `volume` (which must lie on P's positive
    /// side). `margin` (world units) is the slack every comparison keeps against rounding.
    /// `depthGapPerDistance2`: the depth buffer's resolution for the views served
    /// (core::depthGapPerDistance2; 0: none): a hidden point must lie that much, times its squared
    /// distance from V, behind its occluder in h, or the two may tie.
    void reset(const CorrespondencePlane& plane, const Aabb& volume, double margin, double depthGapPerDistance2 = 0.0);
    const CorrespondencePlane& plane() const { return _plane; }
    /// Least h over V: geometry is testable, and may occlude, only where h is below it minus margin.
    double volumeMinH() const { return _volumeMinH; }

    /// Inserts a convex planar occluder (world space, every vertex below volumeMinH() - margin).
    /// The caller has checked it may occlude (opaque, static, its plane clear of V, facing V).
    /// Returns true when its umbra covered part of the window.
    bool insert(const std::vector<Vec3>& polygon, const Plane& polygonPlane);

    /// True when every ray from V through the convex hull of `points` meets an inserted occluder
    /// before it reaches any of those points, with all crossings of P inside the window.
    bool hidden(const Vec3* points, std::size_t count);

    const ZBufferStatistics& statistics() const { return _statistics; }

private:
    struct Fragment
    {
        double z = 0.0;
        ConvexArea2 area;
    };
    double pixelValue(std::size_t index);
    double lowestHitH(const ConvexArea2& region, const Plane& polygonPlane, double polygonMinH) const;

    // The phases of insert().
    struct PixelRange
    {
        int i0 = 0, j0 = 0, i1 = -1, j1 = -1; // inclusive
    };
    // The polygon's umbra into _umbra and its eroded edges into _edges; false when it has no area.
    bool castUmbra(const std::vector<Vec3>& polygon);
    // The window's pixels that _umbra's bounding box meets (empty when i0 > i1 or j0 > j1).
    PixelRange umbraPixels() const;
    // Raises pixel (i, j)'s full value, or adds a coverage-map piece, by the umbra in _edges.
    void coverPixel(int i, int j, const Plane& polygonPlane, double polygonMinH);
    // Keeps _piece at value z in the pixel's coverage map, dropping its lowest piece when full.
    void storeFragment(std::size_t index, double z);

    CorrespondencePlane _plane;
    std::array<Vec3, 8> _corners{};
    std::array<double, 8> _cornerH{};
    double _volumeMinH = 0.0, _margin = 0.0, _erosion = 0.0;
    double _depthGapPerDistance2 = 0.0; // needed gap in h per squared distance from V (depth resolution)
    std::vector<double> _full;   ///< per pixel: best value of umbrae covering it whole
    std::vector<double> _value;  ///< per pixel: cached answer (full and coverage map)
    std::vector<std::uint8_t> _dirty;
    std::vector<std::vector<Fragment>> _fragments;
    ZBufferStatistics _statistics;
    // scratch
    std::array<ConvexArea2, 8> _projections;
    ConvexArea2 _umbra, _clip, _piece;
    std::vector<HalfPlane2> _edges, _fragmentEdges;
    std::vector<ConvexArea2> _pieces;
    std::vector<const Fragment*> _order;
};
} // namespace osgVis::core
