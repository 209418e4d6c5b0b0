// SPDX-License-Identifier: MIT
// Newell's normal (as in Sutherland, Sproull & Schumacker 1974) and Sutherland–Hodgman clipping
// (Sutherland & Hodgman, "Reentrant Polygon Clipping", 1974) against one plane.
#include <osgVis/core/geometry/ConvexPolygon.h>

#include <osgVis/core/geometry/Aabb.h>

#include <cmath>

namespace osgVis::core
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

double diameterOf(const std::vector<Vec3>& vertices)
{
    Aabb box;
    for (const Vec3& v : vertices)
        box.expand(v);
    return glm::length(box.extent());
}

// Drops consecutive (and wrap-around) vertices closer than `tolerance`.
std::vector<Vec3> distinctVertices(const std::vector<Vec3>& vertices, double tolerance)
{
    std::vector<Vec3> out;
    for (const Vec3& v : vertices)
    {
        if (out.empty() || glm::length(v - out.back()) > tolerance)
            out.push_back(v);
    }
    while (out.size() > 1 && glm::length(out.front() - out.back()) <= tolerance)
        out.pop_back();
    return out;
}
} // namespace

Vec3 ConvexPolygon::newellNormal() const
{
    // note: summed relative to the first vertex; the same vector as Newell's formula, but without
    // the cancellation that large world coordinates cause.
    Vec3 n(0.0);
    if (_vertices.size() < 3)
        return n;
    const Vec3& origin = _vertices.front();
    for (std::size_t i = 1; i + 1 < _vertices.size(); ++i)
        n += glm::cross(_vertices[i] - origin, _vertices[i + 1] - origin);
    return n;
}

double ConvexPolygon::area() const
{
    return 0.5 * glm::length(newellNormal());
}

Vec3 ConvexPolygon::centroid() const
{
    if (_vertices.empty())
        return Vec3(0.0);
    const Vec3 normal = newellNormal();
    const double normalLength2 = glm::dot(normal, normal);
    if (normalLength2 > 0.0)
    {
        // Area-weighted triangle-fan centroids; weights are signed areas along the normal.
        const Vec3& origin = _vertices.front();
        Vec3 sum(0.0);
        double weight = 0.0;
        for (std::size_t i = 1; i + 1 < _vertices.size(); ++i)
        {
            const double w = glm::dot(glm::cross(_vertices[i] - origin, _vertices[i + 1] - origin), normal);
            sum += w * (origin + _vertices[i] + _vertices[i + 1]) / 3.0;
            weight += w;
        }
        if (weight != 0.0)
            return sum / weight;
    }
    Vec3 mean(0.0);
    for (const Vec3& v : _vertices)
        mean += v;
    return mean / double(_vertices.size());
}

bool ConvexPolygon::plane(Plane& out) const
{
    const Vec3 n = newellNormal();
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length))
        return false;
    Vec3 mean(0.0);
    for (const Vec3& v : _vertices)
        mean += v;
    mean /= double(_vertices.size());
    out = Plane::fromPointNormal(mean, n / length);
    return true;
}

ConvexPolygon ConvexPolygon::clipped(const Plane& plane) const
{
    std::vector<Vec3> out;
    out.reserve(_vertices.size() + 1);
    const std::size_t n = _vertices.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& current = _vertices[i];
        const Vec3& next = _vertices[(i + 1) % n];
        const double dc = plane.distance(current);
        const double dn = plane.distance(next);
        if (dc >= 0.0)
            out.push_back(current);
        // note: strict crossing only; a vertex on the plane is emitted once, as itself.
        if ((dc > 0.0 && dn < 0.0) || (dc < 0.0 && dn > 0.0))
        {
            const double t = dc / (dc - dn);
            out.push_back(current + t * (next - current));
        }
    }
    if (out.size() < 3)
        return {};
    return ConvexPolygon(std::move(out));
}

bool ConvexPolygon::isValidOccluder(double minArea, double planarTolerance) const
{
    for (const Vec3& v : _vertices)
    {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            return false;
    }
    const double diameter = diameterOf(_vertices);
    if (!(diameter > 0.0))
        return false;
    const ConvexPolygon distinct(distinctVertices(_vertices, diameter * 1e-12));
    if (distinct.size() < 3)
        return false;

    const Vec3 normalSum = distinct.newellNormal();
    const double area = 0.5 * glm::length(normalSum);
    // Slivers: too thin relative to their size for the normal to mean anything.
    if (!(area >= minArea) || area < planarTolerance * diameter * diameter)
        return false;

    Plane supporting;
    if (!distinct.plane(supporting))
        return false;
    for (const Vec3& v : distinct.vertices())
    {
        if (std::abs(supporting.distance(v)) > planarTolerance * diameter)
            return false;
    }

    // Convex: every turn has the normal's orientation (straight runs allowed) and the outline
    // winds once (exterior angles sum to 2π), which rules out stars.
    const std::vector<Vec3>& p = distinct.vertices();
    const std::size_t n = p.size();
    const double turnTolerance = planarTolerance * diameter * diameter;
    double turning = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3 a = p[(i + 1) % n] - p[i];
        const Vec3 b = p[(i + 2) % n] - p[(i + 1) % n];
        const double turn = glm::dot(glm::cross(a, b), supporting.normal);
        if (turn < -turnTolerance)
            return false;
        turning += std::atan2(turn, glm::dot(a, b));
    }
    return std::abs(turning - 2.0 * Pi) < 1e-6;
}
} // namespace osgVis::core
