// SPDX-License-Identifier: MIT
// Line stabbing of axial portal sequences after Teller & Séquin, "Visibility Preprocessing for
// Interactive Walkthroughs" (SIGGRAPH '91) and Teller's thesis (1992): a line crosses an oriented
// convex polygon iff its Plücker side operator with every edge has one sign, which is linear in
// the line's Plücker coordinates; in 2-D the same test is exact. Every test here relaxes in the
// safe direction only: a configuration some line realises is never rejected.
#include <osgVis/core/cellportal/PortalStabbing.h>

#include <osgVis/core/geometry/SmallLp.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
// Added to every acceptance threshold (in units of the normalised frame, where the input spans
// about 1): absorbs the rounding of the LP and of the plane construction.
constexpr double NumericSlack = 1e-9;

// The caller's tolerance plus what rounding may cost at this size and distance from the origin,
// so that a tolerance of zero still accepts lines that exactly touch an edge.
double withRounding(double tolerance, double size, double magnitude)
{
    const double base = tolerance > 0.0 ? tolerance : 0.0;
    return base + NumericSlack * size + 1e-12 * magnitude;
}

double largestAbs(const Vec3& v)
{
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// Half-space n·x + d >= 0 with |n| = 1.
struct HalfSpace
{
    Vec3 n;
    double d;
};

// False only when the LP's optimum is certainly below `threshold`: judged by the dual bound,
// which rounding in the simplex cannot make too low. Anything but a clean optimum is "maybe".
bool lpMayReach(SmallLp& lp, double threshold)
{
    return lp.maximize() != SmallLp::Status::Optimal || lp.upperBound() >= threshold;
}

double travelSign(const OrientedPortal& p)
{
    return p.positive ? 1.0 : -1.0;
}

// Corner k of the portal, counter-clockwise seen along its travel direction.
Vec3 travelCorner(const OrientedPortal& p, int k)
{
    return p.positive ? p.rect.corner(k) : p.rect.corner(3 - k);
}

// Range of the rectangle's points along `axis`.
void rangeAlong(const AxialRect& r, int axis, double& lo, double& hi)
{
    if (axis == r.axis)
        lo = hi = r.coordinate;
    else if (axis == AxialRect::uAxis(r.axis))
    {
        lo = r.uMin;
        hi = r.uMax;
    }
    else
    {
        lo = r.vMin;
        hi = r.vMax;
    }
}

bool finiteRect(const AxialRect& r)
{
    return std::isfinite(r.coordinate) && std::isfinite(r.uMin) && std::isfinite(r.uMax) && std::isfinite(r.vMin) &&
           std::isfinite(r.vMax);
}

// Inverted ranges within the tolerance become zero-width ones (a line may still touch them).
OrientedPortal repaired(const OrientedPortal& p)
{
    OrientedPortal q = p;
    if (q.rect.uMax < q.rect.uMin)
        q.rect.uMin = q.rect.uMax = 0.5 * (q.rect.uMin + q.rect.uMax);
    if (q.rect.vMax < q.rect.vMin)
        q.rect.vMin = q.rect.vMax = 0.5 * (q.rect.vMin + q.rect.vMax);
    return q;
}

// A frame in which all portal corners lie in the unit ball: tolerances and LP coefficients are
// then of order one whatever the scene's size and position.
struct Frame
{
    Vec3 center{0.0};
    double scale = 1.0;
    Vec3 to(const Vec3& p) const { return (p - center) / scale; }
};

bool frameOf(const OrientedPortal* portals, std::size_t count, Frame& frame)
{
    Aabb bounds;
    for (std::size_t i = 0; i < count; ++i)
        bounds.expand(portals[i].rect.bounds());
    frame.center = bounds.center();
    double radius = 0.0;
    for (std::size_t i = 0; i < count; ++i)
        for (int k = 0; k < 4; ++k)
            radius = std::max(radius, glm::length(portals[i].rect.corner(k) - frame.center));
    frame.scale = radius;
    return radius > 1e-300 && std::isfinite(radius);
}

// Any line crossing portal i and later portal j in their directions has its crossing of j on the
// far side of i's plane and its crossing of i on the near side of j's plane (the direction has
// a non-negative component along each travel normal). Exact and cheap: catches sequences that
// turn back, which the Plücker test (blind to order) does not.
bool orderPossible(const OrientedPortal* portals, std::size_t count, double tolerance)
{
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = i + 1; j < count; ++j)
        {
            const OrientedPortal& a = portals[i];
            const OrientedPortal& b = portals[j];
            double lo = 0.0, hi = 0.0;
            rangeAlong(b.rect, a.rect.axis, lo, hi);
            const double farthestBeyondA = a.positive ? hi - a.rect.coordinate : a.rect.coordinate - lo;
            if (farthestBeyondA < -tolerance)
                return false;
            rangeAlong(a.rect, b.rect.axis, lo, hi);
            const double farthestBeforeB = b.positive ? b.rect.coordinate - lo : hi - b.rect.coordinate;
            if (farthestBeforeB < -tolerance)
                return false;
        }
    return true;
}

// Sign each direction component must have: bit 0 "may be positive", bit 1 "may be negative".
void directionSigns(const OrientedPortal* portals, std::size_t count, int dropped, unsigned allowed[3])
{
    allowed[0] = allowed[1] = allowed[2] = 3u;
    for (std::size_t i = 0; i < count; ++i)
        if (portals[i].rect.axis != dropped)
            allowed[portals[i].rect.axis] &= portals[i].positive ? 1u : 2u;
}

// Bounds of the direction variables 0..dims-1 by the signs `allowed` leaves them, the dominant
// component fixed to +1 (sign 0) or -1 (sign 1).
void setDirectionBounds(SmallLp& lp, const unsigned* allowed, int dims, int dominant, int sign)
{
    for (int a = 0; a < dims; ++a)
    {
        double lo = (allowed[a] & 2u) ? -1.0 : 0.0;
        double hi = (allowed[a] & 1u) ? 1.0 : 0.0;
        if (a == dominant)
            lo = hi = (sign == 0) ? 1.0 : -1.0;
        lp.setBounds(a, lo, hi);
    }
}

// Plücker relaxation. Variables: direction d (0..2), moment m (3..5), slack t (6). For an edge
// through a with unit direction e, side(L, E) = d·(a×e) + e·m; a real line crossing the portal at
// point p has side = d_axis·(in-plane distance of p from the edge line) >= 0. The direction is
// normalised by its largest component (fixed to ±1, the others in [-1, 1]), one LP per choice,
// so that t measures a distance: a line missing an edge by δ has side >= -δ.
bool pluckerFeasible(const OrientedPortal* portals, std::size_t count, const Frame& frame, double tol)
{
    thread_local SmallLp lp;
    unsigned allowed[3];
    directionSigns(portals, count, -1, allowed);
    const double momentBound = std::sqrt(3.0) * (1.0 + tol) + NumericSlack;
    for (int dominant = 0; dominant < 3; ++dominant)
        for (int sign = 0; sign < 2; ++sign)
        {
            if (!(allowed[dominant] & (sign == 0 ? 1u : 2u)))
                continue;
            lp.reset(7);
            setDirectionBounds(lp, allowed, 3, dominant, sign);
            for (int a = 0; a < 3; ++a)
                lp.setBounds(3 + a, -momentBound, momentBound);
            lp.setBounds(6, -16.0, 0.0); // |side| <= |d||a×e| + |m| < 8 in this frame
            lp.setObjective(6, 1.0);
            for (std::size_t i = 0; i < count; ++i)
                for (int k = 0; k < 4; ++k)
                {
                    const Vec3 a = frame.to(travelCorner(portals[i], k));
                    const Vec3 edge = frame.to(travelCorner(portals[i], (k + 1) % 4)) - a;
                    const double length = glm::length(edge);
                    if (!(length > 1e-12))
                        continue;
                    const Vec3 e = edge / length;
                    const Vec3 moment = glm::cross(a, e);
                    // t - side(L, E) <= 0
                    const double row[7] = {-moment.x, -moment.y, -moment.z, -e.x, -e.y, -e.z, 1.0};
                    lp.addLessEqual(row, 0.0);
                }
            if (lpMayReach(lp, -1.5 * tol - NumericSlack))
                return true;
        }
    return false;
}

// One oriented segment of the projection that drops an axis: "left" and "right" endpoints seen
// along the travel direction, in the plane's coordinates (X = axis+1, Y = axis+2 of the dropped one).
struct Segment
{
    double left[2];
    double right[2];
    int normalAxis; // 0 X, 1 Y
    double coordinate;
    double wMin, wMax; // extent along the other plane axis
};

// Teller's 2-D case, exact: an oriented 2-D line (direction d, side(q) = d.x q.y - d.y q.x + k,
// positive on its left) crosses an oriented segment iff its left endpoint is on the line's left
// and its right endpoint on its right. A 3-D line parallel to the dropped axis projects to a
// point; it can only touch the portals if one point lies on every segment, checked separately.
bool projectionFeasible(const OrientedPortal* portals, std::size_t count, const Frame& frame, int dropped, double tol)
{
    thread_local std::vector<Segment> segments;
    segments.clear();
    const int xAxis = (dropped + 1) % 3;
    for (std::size_t i = 0; i < count; ++i)
    {
        const AxialRect& r = portals[i].rect;
        if (r.axis == dropped)
            continue;
        Segment s;
        s.normalAxis = (r.axis == xAxis) ? 0 : 1;
        const int wAxis = 3 - dropped - r.axis;
        double lo = 0.0, hi = 0.0;
        rangeAlong(r, wAxis, lo, hi);
        s.coordinate = (r.coordinate - frame.center[r.axis]) / frame.scale;
        s.wMin = (lo - frame.center[wAxis]) / frame.scale;
        s.wMax = (hi - frame.center[wAxis]) / frame.scale;
        // left = travel normal turned a quarter counter-clockwise: +Y for +X travel, -X for +Y travel.
        const double sign = travelSign(portals[i]);
        const bool leftIsMax = (s.normalAxis == 0) ? sign > 0 : sign < 0;
        const int n = s.normalAxis;
        const int w = 1 - n;
        s.left[n] = s.right[n] = s.coordinate;
        s.left[w] = leftIsMax ? s.wMax : s.wMin;
        s.right[w] = leftIsMax ? s.wMin : s.wMax;
        segments.push_back(s);
    }
    if (segments.size() < 2)
        return true;

    // A point common to all segments (within tolerance): a line along the dropped axis.
    double boxLo[2] = {-1e300, -1e300}, boxHi[2] = {1e300, 1e300};
    for (const Segment& s : segments)
    {
        const int n = s.normalAxis;
        boxLo[n] = std::max(boxLo[n], s.coordinate - tol);
        boxHi[n] = std::min(boxHi[n], s.coordinate + tol);
        boxLo[1 - n] = std::max(boxLo[1 - n], s.wMin - tol);
        boxHi[1 - n] = std::min(boxHi[1 - n], s.wMax + tol);
    }
    if (boxLo[0] <= boxHi[0] + NumericSlack && boxLo[1] <= boxHi[1] + NumericSlack)
        return true;

    unsigned allowed[2] = {3u, 3u};
    for (std::size_t i = 0; i < count; ++i)
        if (portals[i].rect.axis != dropped)
            allowed[portals[i].rect.axis == xAxis ? 0 : 1] &= portals[i].positive ? 1u : 2u;

    thread_local SmallLp lp;
    const double offsetBound = std::sqrt(2.0) * (1.0 + tol) + NumericSlack;
    for (int dominant = 0; dominant < 2; ++dominant)
        for (int sign = 0; sign < 2; ++sign)
        {
            if (!(allowed[dominant] & (sign == 0 ? 1u : 2u)))
                continue;
            lp.reset(4); // d.x, d.y, k, t
            setDirectionBounds(lp, allowed, 2, dominant, sign);
            lp.setBounds(2, -offsetBound, offsetBound);
            lp.setBounds(3, -8.0, 0.0); // |side| <= |d||q| + |k| < 3 in this frame
            lp.setObjective(3, 1.0);
            for (const Segment& s : segments)
            {
                // t - side(left) <= 0 and t + side(right) <= 0
                const double leftRow[4] = {-s.left[1], s.left[0], -1.0, 1.0};
                const double rightRow[4] = {s.right[1], -s.right[0], 1.0, 1.0};
                lp.addLessEqual(leftRow, 0.0);
                lp.addLessEqual(rightRow, 0.0);
            }
            // |d| <= sqrt(2): a line missing an endpoint by δ has side >= -sqrt(2) δ.
            if (lpMayReach(lp, -2.0 * tol - NumericSlack))
                return true;
        }
    return false;
}

// Is there a point of `box` (grown by tolerance) at distance >= -tolerance from every half-space?
// Half-spaces that every box point satisfies are left out, ones no box point satisfies answer
// at once; the rest go to one LP maximising the smallest distance, in a frame around the box.
bool boxMeetsHalfSpaces(const Aabb& box, const HalfSpace* halfSpaces, std::size_t count, double tolerance)
{
    if (box.empty())
        return false;
    if (!box.finite())
        return true;
    thread_local SmallLp lp;
    const Vec3 center = box.center();
    const Vec3 half = box.extent() * 0.5;
    const double scale =
        std::max({half.x, half.y, half.z, tolerance,
                  1e-12 * (1.0 + std::max({std::fabs(center.x), std::fabs(center.y), std::fabs(center.z)}))});
    const double tol = tolerance / scale;
    bool anyRow = false;
    double depth = 1.0;
    lp.reset(4);
    for (std::size_t i = 0; i < count; ++i)
    {
        const HalfSpace& h = halfSpaces[i];
        const double atCenter = glm::dot(h.n, center) + h.d;
        const double reach = std::fabs(h.n.x) * half.x + std::fabs(h.n.y) * half.y + std::fabs(h.n.z) * half.z;
        if (!std::isfinite(atCenter))
            continue; // unusable plane: dropping it is safe
        if (atCenter + reach < -tolerance)
            return false;
        if (atCenter - reach >= -tolerance)
            continue;
        // t - n·x' <= d'  in the box frame x = center + scale x'
        const double row[4] = {-h.n.x, -h.n.y, -h.n.z, 1.0};
        lp.addLessEqual(row, atCenter / scale);
        depth = std::max(depth, (reach - atCenter) / scale + 1.0);
        anyRow = true;
    }
    if (!anyRow)
        return true;
    for (int a = 0; a < 3; ++a)
        lp.setBounds(a, -half[a] / scale - tol, half[a] / scale + tol);
    lp.setBounds(3, -depth - tol, 0.0);
    lp.setObjective(3, 1.0);
    return lpMayReach(lp, -tol - NumericSlack);
}

bool unitHalfSpace(const Vec3& normal, double d, HalfSpace& out)
{
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length))
        return false;
    out = {normal / length, d / length};
    return true;
}

// The constraints on a point p of a sightline from `eye` through portals[0..count): beyond each
// portal's plane and inside the cone from the eye through the portal (planes through the eye and
// each edge). Returns false when the eye lies beyond a portal's plane (no sightline can cross it
// in its direction).
bool sightlineHalfSpaces(const Vec3& eye, const OrientedPortal* portals, std::size_t count,
                         const std::vector<Plane>& viewPlanes, double tolerance, std::vector<HalfSpace>& out)
{
    out.clear();
    for (const Plane& plane : viewPlanes)
    {
        HalfSpace h;
        if (unitHalfSpace(plane.normal, plane.d, h))
            out.push_back(h);
        else if (plane.d < -tolerance)
            return false; // a zero normal with negative offset keeps nothing
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        const OrientedPortal portal = repaired(portals[i]);
        const int axis = portal.rect.axis;
        const double sign = travelSign(portal);
        const double eyeBeyond = sign * (eye[axis] - portal.rect.coordinate);
        if (eyeBeyond > tolerance)
            return false;
        Vec3 normal{0.0};
        normal[axis] = sign;
        out.push_back({normal, -sign * portal.rect.coordinate});
        // note: an eye on (or within tolerance of) the portal's plane makes its cone degenerate;
        // leaving the cone out is the safe relaxation.
        if (eyeBeyond >= -tolerance)
            continue;
        for (int k = 0; k < 4; ++k)
        {
            const Vec3 a = travelCorner(portal, k);
            const Vec3 edge = travelCorner(portal, (k + 1) % 4) - a;
            // Inward for counter-clockwise corners seen along the travel direction, eye behind.
            HalfSpace h;
            const Vec3 n = glm::cross(a - eye, edge);
            if (glm::length(n) > 1e-14 * glm::length(a - eye) * glm::length(edge) &&
                unitHalfSpace(n, -glm::dot(n, eye), h))
                out.push_back(h);
        }
    }
    return true;
}
// Appends the separating planes of `first` and `second` (through an edge of one and a vertex of
// the other, with the two on opposite sides), oriented to keep `second`. A line meeting first and
// then second has a plane value that grows along it, so every point beyond second keeps >= 0.
void appendSeparatingPlanes(const AxialRect& first, const AxialRect& second, double scale, std::vector<HalfSpace>& out)
{
    const double eps = 1e-10 * scale;
    Vec3 corners[2][4];
    for (int c = 0; c < 4; ++c)
    {
        corners[0][c] = first.corner(c);
        corners[1][c] = second.corner(c);
    }
    for (int edgeOwner = 0; edgeOwner < 2; ++edgeOwner)
        for (int k = 0; k < 4; ++k)
        {
            const Vec3& a = corners[edgeOwner][k];
            const Vec3 edge = corners[edgeOwner][(k + 1) % 4] - a;
            const double edgeLength = glm::length(edge);
            if (!(edgeLength > eps))
                continue;
            for (int v = 0; v < 4; ++v)
            {
                const Vec3 n = glm::cross(edge, corners[1 - edgeOwner][v] - a);
                const double length = glm::length(n);
                if (!(length > 1e-12 * edgeLength * scale))
                    continue;
                const Vec3 unit = n / length;
                double minFirst = 1e300, maxFirst = -1e300, minSecond = 1e300, maxSecond = -1e300;
                for (int c = 0; c < 4; ++c)
                {
                    const double f = glm::dot(unit, corners[0][c] - a);
                    const double g = glm::dot(unit, corners[1][c] - a);
                    minFirst = std::min(minFirst, f);
                    maxFirst = std::max(maxFirst, f);
                    minSecond = std::min(minSecond, g);
                    maxSecond = std::max(maxSecond, g);
                }
                const bool allOnPlane = maxFirst <= eps && minFirst >= -eps && maxSecond <= eps && minSecond >= -eps;
                if (allOnPlane)
                    continue;
                if (maxFirst <= eps && minSecond >= -eps)
                    out.push_back({unit, -glm::dot(unit, a)});
                else if (minFirst >= -eps && maxSecond <= eps)
                    out.push_back({-unit, glm::dot(unit, a)});
            }
        }
}

// Teller's funnel test: the last portal must meet the funnel (separating planes and portal planes)
// of those before it, since a stabbing line crosses it beyond all of them. Only the last portal
// is tested: the bake extends sequences one portal at a time, so shorter prefixes were checked.
bool lastPortalMeetsFunnel(const OrientedPortal* portals, std::size_t count, double scale, double tolerance)
{
    thread_local std::vector<HalfSpace> halfSpaces;
    halfSpaces.clear();
    const std::size_t before = count - 1;
    for (std::size_t i = 0; i < before; ++i)
    {
        Vec3 normal{0.0};
        const double sign = travelSign(portals[i]);
        normal[portals[i].rect.axis] = sign;
        halfSpaces.push_back({normal, -sign * portals[i].rect.coordinate});
        for (std::size_t j = i + 1; j < before; ++j)
            appendSeparatingPlanes(portals[i].rect, portals[j].rect, scale, halfSpaces);
    }
    return boxMeetsHalfSpaces(portals[before].rect.bounds(), halfSpaces.data(), halfSpaces.size(), tolerance);
}

} // namespace

bool portalSequenceStabbable(const OrientedPortal* portals, std::size_t count, double tolerance)
{
    if (count <= 1)
        return true;
    Aabb extent;
    for (std::size_t i = 0; i < count; ++i)
    {
        if (!finiteRect(portals[i].rect))
            return true; // nothing certain about unusable input
        extent.expand(portals[i].rect.bounds());
    }
    tolerance =
        withRounding(tolerance, largestAbs(extent.extent()), std::max(largestAbs(extent.min), largestAbs(extent.max)));
    thread_local std::vector<OrientedPortal> fixed;
    fixed.clear();
    for (std::size_t i = 0; i < count; ++i)
    {
        const AxialRect& r = portals[i].rect;
        if (r.uMax < r.uMin - tolerance || r.vMax < r.vMin - tolerance)
            return false; // an empty portal lets no line through
        fixed.push_back(repaired(portals[i]));
    }
    if (!orderPossible(fixed.data(), count, tolerance))
        return false;
    Frame frame;
    if (!frameOf(fixed.data(), count, frame))
        return true;
    const double tol = tolerance / frame.scale;
    for (int dropped = 0; dropped < 3; ++dropped)
        if (!projectionFeasible(fixed.data(), count, frame, dropped, tol))
            return false;
    if (!pluckerFeasible(fixed.data(), count, frame, tol))
        return false;
    return count < 3 || lastPortalMeetsFunnel(fixed.data(), count, frame.scale, tolerance);
}

PortalFunnel portalFunnel(const OrientedPortal* portals, std::size_t count)
{
    PortalFunnel funnel;
    if (count == 0)
        return funnel;
    Frame frame;
    frameOf(portals, count, frame);
    auto addUnique = [&](const Vec3& normal, double d)
    {
        for (const Plane& p : funnel.planes)
            if (std::fabs(p.normal.x - normal.x) < 1e-9 && std::fabs(p.normal.y - normal.y) < 1e-9 &&
                std::fabs(p.normal.z - normal.z) < 1e-9 && std::fabs(p.d - d) < 1e-9 * frame.scale)
                return;
        funnel.planes.emplace_back(normal, d);
    };
    // Beyond every portal's plane: the line's direction has a non-negative travel component.
    for (std::size_t i = 0; i < count; ++i)
    {
        Vec3 normal{0.0};
        const double sign = travelSign(portals[i]);
        normal[portals[i].rect.axis] = sign;
        addUnique(normal, -sign * portals[i].rect.coordinate);
    }
    thread_local std::vector<HalfSpace> separating;
    separating.clear();
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = i + 1; j < count; ++j)
            appendSeparatingPlanes(portals[i].rect, portals[j].rect, frame.scale, separating);
    for (const HalfSpace& h : separating)
        addUnique(h.n, h.d);
    return funnel;
}

bool boxMeetsFunnel(const Aabb& box, const PortalFunnel& funnel, double tolerance)
{
    if (box.empty())
        return false;
    tolerance = withRounding(tolerance, largestAbs(box.extent()), std::max(largestAbs(box.min), largestAbs(box.max)));
    thread_local std::vector<HalfSpace> halfSpaces;
    halfSpaces.clear();
    for (const Plane& plane : funnel.planes)
    {
        HalfSpace h;
        if (unitHalfSpace(plane.normal, plane.d, h))
            halfSpaces.push_back(h);
        else if (plane.d < -tolerance)
            return false;
    }
    return boxMeetsHalfSpaces(box, halfSpaces.data(), halfSpaces.size(), tolerance);
}

bool eyeSeesThroughPortals(const Vec3& eye, const OrientedPortal* portals, std::size_t count,
                           const std::vector<Plane>& viewPlanes, double tolerance)
{
    if (count == 0)
        return true;
    const OrientedPortal& last = portals[count - 1];
    if (!finiteRect(last.rect))
        return true;
    const Aabb lastBounds = last.rect.bounds();
    tolerance = withRounding(tolerance, largestAbs(lastBounds.extent()) + glm::length(lastBounds.center() - eye),
                             std::max(largestAbs(eye), largestAbs(lastBounds.center())));
    if (last.rect.uMax < last.rect.uMin - tolerance || last.rect.vMax < last.rect.vMin - tolerance)
        return false;
    if (travelSign(last) * (eye[last.rect.axis] - last.rect.coordinate) > tolerance)
        return false;
    const OrientedPortal lastFixed = repaired(last);
    // The point where the sightline crosses the last portal ranges over its rectangle.
    return eyeSeesBoxThroughPortals(eye, portals, count - 1, viewPlanes, lastFixed.rect.bounds(), tolerance);
}

bool eyeSeesBoxThroughPortals(const Vec3& eye, const OrientedPortal* portals, std::size_t count,
                              const std::vector<Plane>& viewPlanes, const Aabb& box, double tolerance)
{
    thread_local std::vector<HalfSpace> halfSpaces;
    if (box.empty())
        return false;
    tolerance = withRounding(tolerance, largestAbs(box.extent()) + glm::length(box.center() - eye),
                             std::max(largestAbs(eye), largestAbs(box.center())));
    for (std::size_t i = 0; i < count; ++i)
    {
        const AxialRect& r = portals[i].rect;
        if (!finiteRect(r))
            return true;
        if (r.uMax < r.uMin - tolerance || r.vMax < r.vMin - tolerance)
            return false;
    }
    if (!sightlineHalfSpaces(eye, portals, count, viewPlanes, tolerance, halfSpaces))
        return false;
    return boxMeetsHalfSpaces(box, halfSpaces.data(), halfSpaces.size(), tolerance);
}
} // namespace osgVis::core
