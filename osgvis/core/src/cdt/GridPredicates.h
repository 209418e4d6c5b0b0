// SPDX-License-Identifier: MIT
#pragma once
// Exact predicates on the integer grid of the CDT record (Luka, "Visibility culling with a
// constrained Delaunay triangulation", §2.2.1: the record must be robust). Shewchuk's adaptive
// predicates ("Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
// Predicates", 1997) are not needed here: every coordinate is an integer with |c| <= 2^28, so
// differences take 30 bits, orientation 61 bits (int64) and in-circle about 4·30 + 4 = 124 bits
// (__int128). The bit budget is in docs/cdt.md.
#include <osgVis/core/cdt/CoverageTriangulation.h>

#include <cstdint>

namespace osgVis::core::cdt
{
using Wide = __int128;

inline bool operator==(GridPoint a, GridPoint b)
{
    return a.x == b.x && a.y == b.y;
}
inline bool operator!=(GridPoint a, GridPoint b)
{
    return !(a == b);
}

/// Twice the signed area of (a, b, c): > 0 counter-clockwise. Exact: |result| < 2^61.
inline std::int64_t orient(GridPoint a, GridPoint b, GridPoint c)
{
    const std::int64_t abx = std::int64_t(b.x) - a.x, aby = std::int64_t(b.y) - a.y;
    const std::int64_t acx = std::int64_t(c.x) - a.x, acy = std::int64_t(c.y) - a.y;
    return abx * acy - aby * acx;
}

inline int sign(std::int64_t v)
{
    return (v > 0) - (v < 0);
}

/// > 0 when d lies strictly inside the circle through the counter-clockwise a, b, c. Exact.
inline int inCircle(GridPoint a, GridPoint b, GridPoint c, GridPoint d)
{
    const std::int64_t adx = std::int64_t(a.x) - d.x, ady = std::int64_t(a.y) - d.y;
    const std::int64_t bdx = std::int64_t(b.x) - d.x, bdy = std::int64_t(b.y) - d.y;
    const std::int64_t cdx = std::int64_t(c.x) - d.x, cdy = std::int64_t(c.y) - d.y;
    const Wide alift = Wide(adx) * adx + Wide(ady) * ady;
    const Wide blift = Wide(bdx) * bdx + Wide(bdy) * bdy;
    const Wide clift = Wide(cdx) * cdx + Wide(cdy) * cdy;
    const Wide det = alift * (Wide(bdx) * cdy - Wide(bdy) * cdx) - blift * (Wide(adx) * cdy - Wide(ady) * cdx) +
                     clift * (Wide(adx) * bdy - Wide(ady) * bdx);
    return (det > 0) - (det < 0);
}

/// Rounds num/den (den != 0) to the nearest integer, halves away from zero. Exact.
inline std::int64_t roundDiv(Wide num, Wide den)
{
    if (den < 0)
    {
        num = -num;
        den = -den;
    }
    const Wide twice = 2 * num;
    return num >= 0 ? std::int64_t((twice + den) / (2 * den)) : -std::int64_t((-twice + den) / (2 * den));
}

/// The intersection of the lines through (a, b) and (c, d), rounded to the nearest grid point;
/// `proper` says whether it lies on both closed segments. False when the lines are parallel.
inline bool roundedCrossing(GridPoint a, GridPoint b, GridPoint c, GridPoint d, GridPoint& out, bool& proper)
{
    const std::int64_t rx = std::int64_t(b.x) - a.x, ry = std::int64_t(b.y) - a.y;
    const std::int64_t sx = std::int64_t(d.x) - c.x, sy = std::int64_t(d.y) - c.y;
    const std::int64_t den = rx * sy - ry * sx;
    if (den == 0)
        return false;
    const std::int64_t qx = std::int64_t(c.x) - a.x, qy = std::int64_t(c.y) - a.y;
    const std::int64_t tn = qx * sy - qy * sx; // t = tn / den along (a, b)
    const std::int64_t un = qx * ry - qy * rx; // u = un / den along (c, d)
    const bool tIn = den > 0 ? (tn >= 0 && tn <= den) : (tn <= 0 && tn >= den);
    const bool uIn = den > 0 ? (un >= 0 && un <= den) : (un <= 0 && un >= den);
    proper = tIn && uIn;
    out.x = std::int32_t(roundDiv(Wide(a.x) * den + Wide(tn) * rx, den));
    out.y = std::int32_t(roundDiv(Wide(a.y) * den + Wide(tn) * ry, den));
    return true;
}
} // namespace osgVis::core::cdt
