// SPDX-License-Identifier: MIT
#include <osgVis/core/occluders/CoplanarUnion.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace osgVis::core
{
namespace
{
using Point = glm::dvec2;
using Outline = std::vector<Point>; // convex, counter-clockwise

constexpr std::size_t MaxCorners = 32;
constexpr std::size_t MaxGroup = 4096; // a plane holding more polygons is left alone (cost)

double cross(const Point& o, const Point& a, const Point& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double area(const Outline& p)
{
    double twice = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Point& a = p[i];
        const Point& b = p[(i + 1) % p.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

// Part of convex `subject` inside convex `clip` (both counter-clockwise).
Outline intersection(Outline subject, const Outline& clip)
{
    Outline next;
    for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e)
    {
        const Point& a = clip[e];
        const Point& b = clip[(e + 1) % clip.size()];
        next.clear();
        for (std::size_t i = 0; i < subject.size(); ++i)
        {
            const Point& p = subject[i];
            const Point& q = subject[(i + 1) % subject.size()];
            const double sp = cross(a, b, p), sq = cross(a, b, q);
            if (sp >= 0.0)
                next.push_back(p);
            if ((sp >= 0.0) != (sq >= 0.0))
                next.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        subject.swap(next);
    }
    return subject;
}

// Convex hull (monotone chain), counter-clockwise, collinear points dropped.
Outline hull(Outline points)
{
    std::sort(points.begin(), points.end(),
              [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (points.size() < 3)
        return points;
    Outline h(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        while (k >= 2 && cross(h[k - 2], h[k - 1], points[i]) <= 0.0)
            --k;
        h[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && cross(h[k - 2], h[k - 1], points[i]) <= 0.0)
            --k;
        h[k++] = points[i];
    }
    h.resize(k - 1);
    return h;
}

struct Bounds2
{
    Point lo{1e300}, hi{-1e300};
};

Bounds2 bounds(const Outline& p)
{
    Bounds2 b;
    for (const Point& v : p)
    {
        b.lo = glm::min(b.lo, v);
        b.hi = glm::max(b.hi, v);
    }
    return b;
}

// The union of a and b when it is exactly their convex hull: they overlap or abut and leave no
// notch or gap. Empty otherwise.
Outline convexUnion(const Outline& a, const Outline& b)
{
    const Bounds2 ba = bounds(a), bb = bounds(b);
    if (ba.lo.x > bb.hi.x || bb.lo.x > ba.hi.x || ba.lo.y > bb.hi.y || bb.lo.y > ba.hi.y)
        return {};
    Outline points = a;
    points.insert(points.end(), b.begin(), b.end());
    Outline h = hull(points);
    if (h.size() < 3 || h.size() > MaxCorners)
        return {};
    const double areaA = area(a), areaB = area(b);
    const double shared = area(intersection(a, b));
    const double covered = areaA + areaB - std::max(shared, 0.0);
    // note: only rounding may separate the two; any real gap or notch adds hull area
    if (area(h) > covered * (1.0 + 1e-9))
        return {};
    return h;
}

struct Group
{
    Plane plane;
    bool oneSided = false;
    std::vector<std::uint32_t> members;
};
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

        struct Piece
        {
            Outline outline;
            std::size_t parts = 1;
        };
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
            if (onPlane && area(piece.outline) > 0.0)
                pieces.push_back(std::move(piece));
        }

        for (bool merged = true; merged;)
        {
            merged = false;
            for (std::size_t i = 0; i < pieces.size(); ++i)
                for (std::size_t j = i + 1; j < pieces.size(); ++j)
                {
                    Outline joined = convexUnion(pieces[i].outline, pieces[j].outline);
                    if (joined.empty())
                        continue;
                    pieces[i].outline = std::move(joined);
                    pieces[i].parts += pieces[j].parts;
                    pieces.erase(pieces.begin() + std::ptrdiff_t(j));
                    --j;
                    merged = true;
                }
        }

        for (const Piece& piece : pieces)
        {
            if (piece.parts < 2)
                continue;
            OccluderPolygon polygon;
            polygon.plane = group.plane;
            polygon.oneSided = group.oneSided;
            for (const Point& p : piece.outline)
                polygon.vertices.push_back(origin + p.x * u + p.y * v);
            polygon.area = area(piece.outline);
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
