// SPDX-License-Identifier: MIT
#include <osgVis/core/occluders/CoplanarUnion.h>

#include "Outline2.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <map>
#include <tuple>

namespace osgVis::core
{
namespace
{
constexpr std::size_t MaxCorners = 32;
constexpr std::size_t MaxGroup = 4096; // a plane holding more polygons is left alone (cost)

struct Group
{
    Plane plane;
    bool oneSided = false;
    std::vector<std::uint32_t> members;
};

struct Piece
{
    Outline2 outline;
    std::vector<std::uint32_t> members; // indices of the polygons it unites
};

struct PlaneFrame
{
    Vec3 origin, u, v;
    Point2 map(const Vec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }
};

// Interval [lo, hi] along the line (p, unit d) of the outline's corners within `tolerance` of it.
bool intervalOnLine(const Outline2& outline, const Point2& p, const Point2& d, double tolerance, double& lo, double& hi)
{
    std::size_t on = 0;
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const Point2& x : outline)
    {
        const Point2 r = x - p;
        if (std::abs(r.x * d.y - r.y * d.x) > tolerance)
            continue;
        const double t = glm::dot(r, d);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
        ++on;
    }
    return on >= 2;
}

// Whether the union of a and b draws without a crack where they meet (docs/occluders.md, "Cracks").
// Overlapping with positive area: every point of either outline inside the union lies inside the
// other piece. Touching: they meet along one line, and there only exactly shared edges (same two end
// vertices, linked) may run, or the rasterizer may leave a T-junction's crack open.
bool meetWatertight(const Piece& a, const Piece& b, const std::vector<OccluderPolygon>& polygons,
                    const PlaneFrame& frame, double tolerance)
{
    const double overlap = signedArea(convexIntersection(a.outline, b.outline));
    if (overlap > 1e-3 * std::min(signedArea(a.outline), signedArea(b.outline)))
        return true;
    std::vector<std::pair<Point2, Point2>> shared;
    for (std::uint32_t m : a.members)
    {
        const OccluderPolygon& polygon = polygons[m];
        for (std::size_t k = 0; k < polygon.neighbours.size(); ++k)
            if (std::find(b.members.begin(), b.members.end(), polygon.neighbours[k]) != b.members.end())
                shared.emplace_back(frame.map(polygon.vertices[k]),
                                    frame.map(polygon.vertices[(k + 1) % polygon.vertices.size()]));
    }
    if (shared.empty())
        return false;
    const Point2 p = shared.front().first;
    const Point2 d = glm::normalize(shared.front().second - p);
    double loA, hiA, loB, hiB;
    if (!intervalOnLine(a.outline, p, d, tolerance, loA, hiA) || !intervalOnLine(b.outline, p, d, tolerance, loB, hiB))
        return false;
    const double lo = std::max(loA, loB), hi = std::min(hiA, hiB);
    std::vector<std::pair<double, double>> covered;
    for (const auto& [from, to] : shared)
    {
        const Point2 rf = from - p, rt = to - p;
        if (std::abs(rf.x * d.y - rf.y * d.x) > tolerance || std::abs(rt.x * d.y - rt.y * d.x) > tolerance)
            return false; // exact edges on two lines: the pieces overlap after all, or rounding lies
        const double s = glm::dot(rf, d), t = glm::dot(rt, d);
        covered.emplace_back(std::min(s, t), std::max(s, t));
    }
    std::sort(covered.begin(), covered.end());
    double reached = lo;
    for (const auto& [s, t] : covered)
    {
        if (s > reached + tolerance)
            return false; // a stretch of the contact that no shared edge covers
        reached = std::max(reached, t);
    }
    return reached >= hi - tolerance;
}
} // namespace

std::vector<OccluderPolygon> coplanarUnions(const std::vector<OccluderPolygon>& polygons, double sceneSize)
{
    // Polygons grouped by plane: quantized unit normal, offset and sidedness.
    const double offsetStep = 1e-6 * sceneSize;
    // note: within the module's depth margin (1e-6 of the scene), so a union never stands in front
    // of the surfaces it replaces by more than the margin allows for
    const double onPlaneTolerance = 1e-7 * sceneSize;
    std::map<std::tuple<long long, long long, long long, long long, bool>, Group> groups;
    for (std::uint32_t i = 0; i < polygons.size(); ++i)
    {
        const OccluderPolygon& p = polygons[i];
        const Vec3& n = p.plane.normal;
        const auto key = std::make_tuple(std::llround(n.x * 1e6), std::llround(n.y * 1e6), std::llround(n.z * 1e6),
                                         std::llround(p.plane.d / offsetStep), p.oneSided);
        Group& group = groups[key];
        if (group.members.empty())
        {
            group.plane = p.plane;
            group.oneSided = p.oneSided;
        }
        group.members.push_back(i);
    }

    std::vector<OccluderPolygon> unions;
    for (auto& [key, group] : groups)
    {
        if (group.members.size() < 2 || group.members.size() > MaxGroup)
            continue;
        const Vec3 n = group.plane.normal;
        const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        const Vec3 u = glm::normalize(glm::cross(helper, n));
        const Vec3 v = glm::cross(n, u); // (u, v, n) right-handed: counter-clockwise stays so
        const Vec3 origin = -group.plane.d * n;

        std::vector<Piece> pieces;
        for (std::uint32_t index : group.members)
        {
            Piece piece;
            bool onPlane = true;
            for (const Vec3& p : polygons[index].vertices)
            {
                onPlane = onPlane && std::abs(group.plane.distance(p)) <= onPlaneTolerance;
                piece.outline.push_back({glm::dot(p - origin, u), glm::dot(p - origin, v)});
            }
            piece.members.push_back(index);
            if (onPlane && signedArea(piece.outline) > 0.0)
                pieces.push_back(std::move(piece));
        }
        const PlaneFrame frame{origin, u, v};

        for (bool merged = true; merged;)
        {
            merged = false;
            for (std::size_t i = 0; i < pieces.size(); ++i)
                for (std::size_t j = i + 1; j < pieces.size(); ++j)
                {
                    const std::vector<std::size_t> hull =
                        convexUnionIndices(pieces[i].outline, pieces[j].outline, MaxCorners);
                    if (hull.empty() || !meetWatertight(pieces[i], pieces[j], polygons, frame, onPlaneTolerance))
                        continue;
                    Outline2 joined;
                    for (std::size_t k : hull)
                        joined.push_back(k < pieces[i].outline.size() ? pieces[i].outline[k]
                                                                      : pieces[j].outline[k - pieces[i].outline.size()]);
                    pieces[i].outline = std::move(joined);
                    pieces[i].members.insert(pieces[i].members.end(), pieces[j].members.begin(),
                                             pieces[j].members.end());
                    pieces.erase(pieces.begin() + std::ptrdiff_t(j));
                    --j;
                    merged = true;
                }
        }

        for (const Piece& piece : pieces)
        {
            if (piece.members.size() < 2)
                continue;
            OccluderPolygon polygon;
            polygon.plane = group.plane;
            polygon.oneSided = group.oneSided;
            for (const Point2& p : piece.outline)
                polygon.vertices.push_back(origin + p.x * u + p.y * v);
            polygon.area = signedArea(piece.outline);
            Vec3 sum(0.0);
            for (const Vec3& p : polygon.vertices)
                sum += p;
            polygon.centroid = sum / double(polygon.vertices.size());
            polygon.neighbours.assign(polygon.vertices.size(), NoNeighbour);
            unions.push_back(std::move(polygon));
        }
    }
    return unions;
}
} // namespace osgVis::core
