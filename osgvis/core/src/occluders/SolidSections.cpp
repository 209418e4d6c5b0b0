// SPDX-License-Identifier: MIT
// Sections through closed convex objects as occluders: every sightline from outside a closed
// surface to a point inside it crosses the surface first, so a polygon inside hides, from outside,
// no more than the drawn surface does. docs/multifocal.md, "Solid sections".
#include <osgVis/core/occluders/SolidSections.h>

#include "OccluderSources.h"
#include "Outline2.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace osgVis::core
{
namespace
{
using Key = std::tuple<float, float, float>;

enum class Orientation
{
    Outwards,
    Inwards,
    Neither
};

/// Welds the object's vertices by exact position; empty when the triangles do not close up with
/// one orientation (every directed edge once, and its reverse once).
bool closedMesh(const Scene& scene, std::size_t first, std::size_t end, std::vector<Vec3>& vertices,
                std::vector<std::array<std::uint32_t, 3>>& faces)
{
    std::map<Key, std::uint32_t> index;
    vertices.clear();
    faces.clear();
    auto id = [&](const Vec3f& p)
    {
        const auto [it, added] = index.emplace(Key(p.x, p.y, p.z), std::uint32_t(vertices.size()));
        if (added)
            vertices.emplace_back(p);
        return it->second;
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = first; t < end; ++t)
    {
        const Triangle& tri = scene.triangles[t];
        const std::array<std::uint32_t, 3> f{id(tri.a), id(tri.b), id(tri.c)};
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
            return false;
        faces.push_back(f);
        for (int e = 0; e < 3; ++e)
            if (++directed[{f[e], f[(e + 1) % 3]}] > 1)
                return false;
    }
    for (const auto& [edge, count] : directed)
        if (!directed.count({edge.second, edge.first}))
            return false;
    return !faces.empty();
}

Orientation convexOrientation(const std::vector<Vec3>& vertices, const std::vector<std::array<std::uint32_t, 3>>& faces,
                              double tolerance)
{
    bool outwards = true, inwards = true;
    for (const auto& f : faces)
    {
        const Vec3 &a = vertices[f[0]], &b = vertices[f[1]], &c = vertices[f[2]];
        Vec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        if (!(length > 0.0))
            return Orientation::Neither;
        n /= length;
        for (const Vec3& v : vertices)
        {
            const double d = glm::dot(v - a, n);
            outwards = outwards && d <= tolerance;
            inwards = inwards && d >= -tolerance;
        }
        if (!outwards && !inwards)
            return Orientation::Neither;
    }
    return outwards ? Orientation::Outwards : (inwards ? Orientation::Inwards : Orientation::Neither);
}

/// The convex mesh's section by x[axis] = at: the hull of where its edges cross that plane.
bool section(const std::vector<Vec3>& vertices, const std::vector<std::array<std::uint32_t, 3>>& faces, int axis,
             double at, OccluderPolygon& out)
{
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    Outline2 points;
    std::vector<Vec3> points3;
    for (const auto& f : faces)
        for (int e = 0; e < 3; ++e)
        {
            const Vec3 &p = vertices[f[e]], &q = vertices[f[(e + 1) % 3]];
            const double dp = p[axis] - at, dq = q[axis] - at;
            if (dp == 0.0)
                points3.push_back(p);
            else if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0))
                points3.push_back(p + (q - p) * (dp / (dp - dq)));
        }
    for (Vec3& p : points3)
    {
        p[axis] = at; // the interpolation's rounding must not tilt the polygon
        points.emplace_back(p[u], p[v]);
    }
    const std::vector<std::size_t> hull = convexHullIndices(points);
    if (hull.size() < 3)
        return false;
    Outline2 outline;
    Vec3 centroid(0.0);
    for (std::size_t i : hull)
    {
        outline.push_back(points[i]);
        centroid += points3[i];
    }
    centroid /= double(hull.size());
    out = OccluderPolygon{};
    for (std::size_t i : hull)
        // Shrunk towards the centroid by a millionth: rounding of the crossings cannot put a
        // corner outside the surface.
        out.vertices.push_back(centroid + (points3[i] - centroid) * (1.0 - 1e-6));
    // The hull runs counter-clockwise in (u, v), which is counter-clockwise around +axis unless
    // (u, v, axis) is a left-handed frame (axis 1: x, z, y).
    if (axis == 1)
        std::reverse(out.vertices.begin(), out.vertices.end());
    Vec3 normal(0.0);
    normal[axis] = 1.0;
    out.plane = Plane(normal, -at);
    out.area = std::abs(signedArea(outline));
    out.centroid = centroid;
    out.neighbours.assign(out.vertices.size(), NoNeighbour);
    out.insideSolid = true;
    return true;
}
} // namespace

std::vector<OccluderPolygon> convexSolidSections(const Scene& scene, const SolidSectionOptions& options)
{
    std::vector<OccluderPolygon> out;
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> faces;
    for (const SceneObject& object : scene.objects)
    {
        if (!isEligible(object, true) || object.triangleCount < 4 || object.triangleCount > options.maxTriangles)
            continue;
        const auto [first, end] = scene.trianglesOf(object);
        if (!closedMesh(scene, first, end, vertices, faces))
            continue;
        Aabb box;
        for (const Vec3& p : vertices)
            box.expand(p);
        const double size = glm::length(box.extent());
        const Orientation orientation = convexOrientation(vertices, faces, options.convexTolerance * size);
        if (orientation == Orientation::Neither ||
            (orientation == Orientation::Outwards && (object.flags & OBJECT_CULL_FRONT)) ||
            (orientation == Orientation::Inwards && (object.flags & OBJECT_CULL_BACK)))
            continue;
        Vec3 centroid(0.0);
        for (const Vec3& p : vertices)
            centroid += p;
        centroid /= double(vertices.size());
        for (int axis = 0; axis < 3; ++axis)
        {
            OccluderPolygon polygon;
            if (!section(vertices, faces, axis, centroid[axis], polygon))
                continue;
            polygon.owner = object.id;
            out.push_back(std::move(polygon));
        }
    }
    return out;
}
} // namespace osgVis::core
