// SPDX-License-Identifier: MIT
#include "MaskOccluderGroups.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
namespace
{
using ClippedPolygon = MaskGroups::ClippedPolygon;

// Sutherland–Hodgman that carries each edge's neighbour: a kept piece of an edge keeps it, the
// new edge along the clip plane is an outline edge.
void clip(ClippedPolygon& polygon, const Plane& plane, ClippedPolygon& scratch)
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
    std::swap(polygon.vertices, scratch.vertices);
    std::swap(polygon.neighbour, scratch.neighbour);
}

// Each selected polygon's δ (from its nearest point) and its facing from every eye of that ball.
void classifyFacing(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& selected,
                    const MaskProjection& projection, double nearDepth, double shift, MaskGroups& out)
{
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
        const double margin = delta + 1e-9 * (1.0 + glm::length(p0));
        int side = eyeDistance > margin ? 1 : eyeDistance < -margin ? -1 : 0;
        if (polygon.oneSided && side < 0)
            side = 0;
        MaskGroups::PolygonState& state = out.state[index];
        state = MaskGroups::PolygonState{};
        state.mark = out.frame;
        state.facing = std::int8_t(side);
        state.delta = delta;
    }
}

// Connected components over shared edges between usable polygons of the same facing: out.order
// lists them component by component, out.starts[c] where component c begins.
void findComponents(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& selected,
                    MaskGroups& out)
{
    const auto usable = [&](std::uint32_t p) { return out.state[p].mark == out.frame && out.state[p].facing != 0; };
    out.order.clear();
    out.starts.clear();
    for (std::uint32_t seed : selected)
    {
        if (!usable(seed) || out.state[seed].component != ~0u)
            continue;
        out.starts.push_back(static_cast<std::uint32_t>(out.order.size()));
        const std::uint32_t id = static_cast<std::uint32_t>(out.starts.size() - 1);
        out.state[seed].component = id;
        out.stack.push_back(seed);
        while (!out.stack.empty())
        {
            const std::uint32_t p = out.stack.back();
            out.stack.pop_back();
            out.order.push_back(p);
            for (std::uint32_t q : polygons[p].neighbours)
            {
                if (q == NoNeighbour || !usable(q) || out.state[q].component != ~0u ||
                    out.state[q].facing != out.state[p].facing)
                    continue;
                out.state[q].component = id;
                out.stack.push_back(q);
            }
        }
    }
    out.starts.push_back(static_cast<std::uint32_t>(out.order.size()));
}

// The clipped polygon's plane in eye space from its vertices (n·p + d = 0); false when degenerate.
bool eyePlane(const std::vector<Vec3>& vertices, Vec3& normal, double& d)
{
    normal = Vec3(0.0);
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
        const Vec3& a = vertices[i];
        const Vec3& b = vertices[(i + 1) % vertices.size()];
        normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const double length = glm::length(normal);
    if (!(length > 0.0))
        return false;
    normal /= length;
    d = 0.0;
    for (const Vec3& v : vertices)
        d -= glm::dot(normal, v);
    d /= double(vertices.size());
    return std::abs(d) > 0.0;
}

// Clips polygon `index` of group `g` and appends it to the group's screen polygons, growing `rect`;
// false when nothing of it is left.
bool emitPolygon(const OccluderPolygon& polygon, std::uint32_t g, const std::array<Plane, 5>& planes,
                 const MaskProjection& projection, MaskGroups& out, glm::dvec4& rect)
{
    ClippedPolygon& work = out.work;
    const std::size_t n = polygon.vertices.size();
    work.vertices.resize(n);
    work.neighbour.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        work.vertices[i] = projection.toEye(polygon.vertices[i]);
        const std::uint32_t q = polygon.neighbours.size() == n ? polygon.neighbours[i] : NoNeighbour;
        const bool inGroup = q != NoNeighbour && out.state[q].mark == out.frame && out.state[q].component == g;
        work.neighbour[i] = inGroup ? q : NoNeighbour;
    }
    for (const Plane& plane : planes)
    {
        clip(work, plane, out.spare);
        if (work.vertices.size() < 3)
            return false;
    }
    Vec3 normal;
    double d = 0.0;
    if (!eyePlane(work.vertices, normal, d))
        return false;
    const std::size_t k = out.polygonCount();
    if (out.polygons.size() <= k)
        out.polygons.resize(k + 1);
    ScreenPolygon& screen = out.polygons[k];
    screen.vertices.clear();
    glm::dvec4 own(std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest());
    for (const Vec3& v : work.vertices)
    {
        screen.vertices.push_back(projection.toMask(v));
        const glm::dvec2& m = screen.vertices.back();
        own = glm::dvec4(std::min(own.x, m.x), std::min(own.y, m.y), std::max(own.z, m.x), std::max(own.w, m.y));
    }
    rect = glm::dvec4(std::min(rect.x, own.x), std::min(rect.y, own.y), std::max(rect.z, own.z), std::max(rect.w, own.w));
    // Tiles its rectangle reaches within the mask (clipping keeps it within the grown frame).
    const auto tiles = [](double lo, double hi, double size)
    {
        const double a = std::clamp(lo, 0.0, size), b = std::clamp(hi, 0.0, size);
        return std::floor(b / 8.0) - std::floor(a / 8.0) + 1.0;
    };
    out.emittedWork = 1 + std::uint64_t(tiles(own.x, own.z, projection.width()) * tiles(own.y, own.w, projection.height()));
    screen.depth = projection.depthPlane(normal, d);
    out.acrossStart.push_back(static_cast<std::uint32_t>(out.across.size()));
    out.across.insert(out.across.end(), work.neighbour.begin(), work.neighbour.end());
    ++out.groupStart.back();
    return true;
}
} // namespace

void buildMaskGroups(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& selected,
                     const MaskProjection& projection, double nearDepth, double shift, MaskGroups& out)
{
    out.groupStart.assign(1, 0u);
    out.groupDelta.clear();
    out.groupRect.clear();
    out.groupWork.clear();
    out.across.clear();
    out.acrossStart.clear();
    if (out.state.size() < polygons.size())
        out.state.resize(polygons.size());
    if (++out.frame == 0) // wrapped: no stale mark may match
    {
        for (MaskGroups::PolygonState& state : out.state)
            state.mark = 0;
        out.frame = 1;
    }
    classifyFacing(polygons, selected, projection, nearDepth, shift, out);
    findComponents(polygons, selected, out);

    const std::array<Plane, 5> planes = projection.clipPlanes(nearDepth);
    for (std::size_t g = 0; g + 1 < out.starts.size(); ++g)
    {
        double groupDelta = std::numeric_limits<double>::max();
        std::uint64_t work = 0;
        glm::dvec4 rect(std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                        std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest());
        out.groupStart.push_back(out.groupStart.back());
        for (std::uint32_t k = out.starts[g]; k < out.starts[g + 1]; ++k)
        {
            const std::uint32_t index = out.order[k];
            groupDelta = std::min(groupDelta, out.state[index].delta);
            if (emitPolygon(polygons[index], std::uint32_t(g), planes, projection, out, rect))
            {
                out.state[index].emitted = true;
                work += out.emittedWork;
            }
        }
        out.groupDelta.push_back(groupDelta);
        out.groupWork.push_back(work);
        out.groupRect.push_back(rect);
    }
    // An edge is inside the group's union only if the polygon across it made it to the mask too
    // (a neighbour clipped to a sliver and dropped leaves an outline there).
    const std::size_t count = out.polygonCount();
    out.acrossStart.push_back(static_cast<std::uint32_t>(out.across.size()));
    for (std::size_t k = 0; k < count; ++k)
    {
        ScreenPolygon& screen = out.polygons[k];
        const std::uint32_t first = out.acrossStart[k], edges = out.acrossStart[k + 1] - first;
        screen.sharedEdge.resize(edges);
        for (std::uint32_t i = 0; i < edges; ++i)
        {
            const std::uint32_t q = out.across[first + i];
            screen.sharedEdge[i] = q != NoNeighbour && out.state[q].mark == out.frame && out.state[q].emitted;
        }
    }
}
} // namespace osgVis::core
