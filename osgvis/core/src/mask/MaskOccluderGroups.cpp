// SPDX-License-Identifier: MIT
#include "MaskOccluderGroups.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace osgVis::core
{
namespace
{
struct FlaggedPolygon
{
    std::vector<Vec3> vertices;          // eye space
    std::vector<std::uint32_t> neighbour; // per edge: polygon of the same group across it, or NoNeighbour
};

// Sutherland–Hodgman that carries each edge's neighbour: a kept piece of an edge keeps it, the
// new edge along the clip plane is an outline edge.
void clip(FlaggedPolygon& polygon, const Plane& plane, FlaggedPolygon& scratch)
{
    scratch.vertices.clear();
    scratch.neighbour.clear();
    const std::size_t n = polygon.vertices.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& a = polygon.vertices[i];
        const Vec3& b = polygon.vertices[(i + 1) % n];
        const double da = plane.distance(a), db = plane.distance(b);
        const bool aIn = da >= 0.0, bIn = db >= 0.0;
        if (aIn)
        {
            scratch.vertices.push_back(a);
            scratch.neighbour.push_back(polygon.neighbour[i]);
        }
        if (aIn != bIn)
        {
            const Vec3 cut = a + (b - a) * (da / (da - db));
            scratch.vertices.push_back(cut);
            scratch.neighbour.push_back(aIn ? NoNeighbour : polygon.neighbour[i]);
        }
    }
    std::swap(polygon, scratch);
}
} // namespace

void buildMaskGroups(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& selected,
                     const MaskProjection& projection, double nearDepth, double shift, MaskGroups& out)
{
    out.polygons.clear();
    out.groupStart.clear();
    out.groupDelta.clear();
    out.groupRect.clear();
    std::unordered_map<std::uint32_t, double> polygonDelta;
    polygonDelta.reserve(selected.size() * 2);
    // Facing from every eye of the ball: +1 front, −1 back, 0 unusable.
    std::unordered_map<std::uint32_t, int> facing;
    facing.reserve(selected.size() * 2);
    for (std::uint32_t index : selected)
    {
        const OccluderPolygon& polygon = polygons[index];
        const Vec3 n = polygon.plane.normal;
        // The plane in eye space: distance of the eye (origin) = d_eye.
        const Vec3 p0 = projection.toEye(polygon.vertices.front());
        const Vec3 p1 = projection.toEye(polygon.vertices.front() + n);
        const Vec3 nEye = p1 - p0;
        const double eyeDistance = -glm::dot(nEye, p0); // signed distance of the eye from the plane
        // Nothing nearer than the clipping depth is rasterized.
        double nearest = std::numeric_limits<double>::max();
        for (const Vec3& v : polygon.vertices)
            nearest = std::min(nearest, projection.viewDepth(v));
        const double delta = projection.deltaFor(shift, std::max(nearest, nearDepth));
        polygonDelta.emplace(index, delta);
        const double margin = delta + 1e-9 * (1.0 + glm::length(p0));
        int side = eyeDistance > margin ? 1 : eyeDistance < -margin ? -1 : 0;
        if (polygon.oneSided && side < 0)
            side = 0;
        if (side != 0)
            facing.emplace(index, side);
    }
    // Connected components over shared edges between usable polygons of the same facing.
    std::unordered_map<std::uint32_t, std::uint32_t> component;
    std::vector<std::uint32_t> order, stack;
    std::vector<std::uint32_t> starts;
    for (std::uint32_t seed : selected)
    {
        if (!facing.count(seed) || component.count(seed))
            continue;
        starts.push_back(static_cast<std::uint32_t>(order.size()));
        const std::uint32_t id = static_cast<std::uint32_t>(starts.size() - 1);
        component[seed] = id;
        stack.push_back(seed);
        while (!stack.empty())
        {
            const std::uint32_t p = stack.back();
            stack.pop_back();
            order.push_back(p);
            for (std::uint32_t q : polygons[p].neighbours)
            {
                if (q == NoNeighbour || component.count(q))
                    continue;
                const auto f = facing.find(q);
                if (f == facing.end() || f->second != facing[p])
                    continue;
                component[q] = id;
                stack.push_back(q);
            }
        }
    }
    starts.push_back(static_cast<std::uint32_t>(order.size()));

    const std::array<Plane, 5> planes = projection.clipPlanes(nearDepth);
    FlaggedPolygon work, scratch;
    std::unordered_set<std::uint32_t> emitted;
    std::vector<std::vector<std::uint32_t>> edgeNeighbours;
    for (std::size_t g = 0; g + 1 < starts.size(); ++g)
    {
        out.groupStart.push_back(static_cast<std::uint32_t>(out.polygons.size()));
        double groupDelta = std::numeric_limits<double>::max();
        glm::dvec4 rect(std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                        std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest());
        for (std::uint32_t k = starts[g]; k < starts[g + 1]; ++k)
        {
            const std::uint32_t index = order[k];
            groupDelta = std::min(groupDelta, polygonDelta[index]);
            const OccluderPolygon& polygon = polygons[index];
            const std::size_t n = polygon.vertices.size();
            work.vertices.resize(n);
            work.neighbour.resize(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                work.vertices[i] = projection.toEye(polygon.vertices[i]);
                const std::uint32_t q = polygon.neighbours.size() == n ? polygon.neighbours[i] : NoNeighbour;
                const auto c = q == NoNeighbour ? component.end() : component.find(q);
                work.neighbour[i] = c != component.end() && c->second == g ? q : NoNeighbour;
            }
            for (const Plane& plane : planes)
            {
                clip(work, plane, scratch);
                if (work.vertices.size() < 3)
                    break;
            }
            if (work.vertices.size() < 3)
                continue;
            // The plane in eye space from the (clipped) vertices: n·p + d = 0.
            Vec3 normal(0.0);
            for (std::size_t i = 0; i < work.vertices.size(); ++i)
            {
                const Vec3& a = work.vertices[i];
                const Vec3& b = work.vertices[(i + 1) % work.vertices.size()];
                normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            }
            const double length = glm::length(normal);
            if (!(length > 0.0))
                continue;
            normal /= length;
            double d = 0.0;
            for (const Vec3& v : work.vertices)
                d -= glm::dot(normal, v);
            d /= double(work.vertices.size());
            if (!(std::abs(d) > 0.0))
                continue;
            ScreenPolygon screen;
            screen.vertices.reserve(work.vertices.size());
            for (const Vec3& v : work.vertices)
            {
                screen.vertices.push_back(projection.toMask(v));
                const glm::dvec2& m = screen.vertices.back();
                rect = glm::dvec4(std::min(rect.x, m.x), std::min(rect.y, m.y), std::max(rect.z, m.x), std::max(rect.w, m.y));
            }
            screen.depth = projection.depthPlane(normal, d);
            out.polygons.push_back(std::move(screen));
            emitted.insert(index);
            edgeNeighbours.push_back(work.neighbour);
        }
        out.groupDelta.push_back(groupDelta);
        out.groupRect.push_back(rect);
    }
    out.groupStart.push_back(static_cast<std::uint32_t>(out.polygons.size()));
    // An edge is inside the group's union only if the polygon across it made it to the mask too
    // (a neighbour clipped to a sliver and dropped leaves an outline there).
    for (std::size_t k = 0; k < out.polygons.size(); ++k)
    {
        const std::vector<std::uint32_t>& across = edgeNeighbours[k];
        out.polygons[k].sharedEdge.resize(across.size());
        for (std::size_t i = 0; i < across.size(); ++i)
            out.polygons[k].sharedEdge[i] = across[i] != NoNeighbour && emitted.count(across[i]) != 0;
    }
}
} // namespace osgVis::core
