// SPDX-License-Identifier: MIT
// Coplanar regions of different objects (and overlapping ones of one object) united into few
// convex pieces: the plane groups, their 2-D frame, and the pieces back in welded ids.
#include "BoundaryLoop.h"
#include "OccluderRegion.h"
#include "PlanarUnion.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace osgVis::core
{
namespace
{
using PlaneKey = std::tuple<long long, long long, long long, long long, bool>;

// A two-sided region's plane may point either way: the canonical normal has its largest
// component positive.
Vec3 canonicalNormal(const Vec3& n, bool oneSided)
{
    if (oneSided)
        return n;
    const Vec3 a = glm::abs(n);
    const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    return n[axis] < 0.0 ? -n : n;
}

bool withinOneInput(const UnionPiece& piece, const std::vector<UnionInput>& inputs)
{
    for (std::uint32_t source : piece.sources)
    {
        const Outline2& convex = inputs[source].points;
        const double slack = 1e-12 * std::sqrt(std::abs(signedArea(convex)));
        bool inside = true;
        for (std::size_t c = 0; c < piece.corners.size() && inside; ++c)
            for (std::size_t i = 0; i < convex.size() && inside; ++i)
            {
                const Point2& a = convex[i];
                const Point2& b = convex[(i + 1) % convex.size()];
                inside = cross2(a, b, piece.corners[c].point) >= -slack * glm::length(b - a);
            }
        if (inside)
            return true;
    }
    return false;
}

// The regions of objects (not stated occluders) grouped by plane, in key order.
std::map<PlaneKey, std::vector<std::uint32_t>> planeGroups(const std::vector<OccluderRegion>& regions,
                                                           const std::vector<Vec3>& positions, double sceneSize)
{
    const double offsetStep = 1e-7 * sceneSize;
    std::map<PlaneKey, std::vector<std::uint32_t>> groups;
    for (std::uint32_t r = 0; r < regions.size(); ++r)
    {
        const OccluderRegion& region = regions[r];
        if (region.owner == InvalidObject || region.loop.size() < 3)
            continue; // a stated occluder is the modeller's polygon: left as it is
        const Vec3 n = canonicalNormal(region.normal, region.oneSided);
        const double d = -glm::dot(n, positions[region.loop[0]]);
        groups[{std::llround(n.x * 1e7), std::llround(n.y * 1e7), std::llround(n.z * 1e7), std::llround(d / offsetStep),
                region.oneSided}]
            .push_back(r);
    }
    return groups;
}

// The slab direction follows the longest edge, so walls of axial rectangles cut into
// axial rectangles. Returns that edge's in-plane length (0 when none has one); `along` gets its
// direction and `extent` widens over the members' vertices.
double longestEdgeDirection(const std::vector<OccluderRegion>& regions, const std::vector<std::uint32_t>& members,
                            const std::vector<Vec3>& positions, const Vec3& n, Vec3& along, Aabb& extent)
{
    double longest = 0.0;
    for (std::uint32_t r : members)
    {
        const auto& loop = regions[r].loop;
        for (std::size_t i = 0; i < loop.size(); ++i)
        {
            const Vec3 e = positions[loop[(i + 1) % loop.size()]] - positions[loop[i]];
            const Vec3 inPlane = e - glm::dot(e, n) * n;
            const double length = glm::length(inPlane);
            if (length > longest)
            {
                longest = length;
                along = inPlane / length;
            }
            extent.expand(positions[loop[i]]);
        }
    }
    return longest;
}

// The plane's 2-D frame: coordinates along u and v from `origin`, with normal n.
struct PlaneFrame
{
    Vec3 origin, n, u, v;
};

// The members in the frame's coordinates, counter-clockwise around n, and the region each came
// from; a member farther than `offPlane` from the plane is left out.
void unionInputs(const std::vector<OccluderRegion>& regions, const std::vector<std::uint32_t>& members,
                 const std::vector<Vec3>& positions, const PlaneFrame& frame, double offPlane,
                 std::vector<UnionInput>& inputs, std::vector<std::uint32_t>& inputRegion)
{
    for (std::uint32_t r : members)
    {
        const OccluderRegion& region = regions[r];
        UnionInput in;
        bool planar = true;
        for (std::uint32_t id : region.loop)
        {
            const Vec3 p = positions[id] - frame.origin;
            planar = planar && std::abs(glm::dot(p, frame.n)) <= offPlane;
            in.points.push_back({glm::dot(p, frame.u), glm::dot(p, frame.v)});
            in.ids.push_back(id);
        }
        if (!planar)
            continue;
        if (glm::dot(region.normal, frame.n) < 0.0)
        {
            std::reverse(in.points.begin(), in.points.end());
            std::reverse(in.ids.begin(), in.ids.end());
        }
        inputs.push_back(std::move(in));
        inputRegion.push_back(r);
    }
}

// The piece's corners as welded ids (a corner on an input edge welded in, tightly), without
// repeated ones.
std::vector<std::uint32_t> weldedPieceLoop(const UnionPiece& piece, VertexWelder& welder, double sceneSize)
{
    const std::vector<Vec3>& positions = welder.positions();
    std::vector<std::uint32_t> loop;
    for (const UnionCorner& c : piece.corners)
    {
        std::uint32_t id = c.id;
        if (id == NoUnionId)
        {
            const Vec3 p = positions[c.from] + c.t * (positions[c.to] - positions[c.from]);
            id = welder.weld(p, 1e-12 * sceneSize);
        }
        if (loop.empty() || loop.back() != id)
            loop.push_back(id);
    }
    while (loop.size() > 1 && loop.front() == loop.back())
        loop.pop_back();
    return loop;
}

// Sets the piece region's parts (ascending, none when only one) and owner from its sources.
void setPieceParts(const UnionPiece& piece, const std::vector<OccluderRegion>& regions,
                   const std::vector<std::uint32_t>& inputRegion, OccluderRegion& region)
{
    for (std::uint32_t source : piece.sources)
    {
        // a source over several clusters of one drawable stands for all of them
        const OccluderRegion& input = regions[inputRegion[source]];
        if (input.parts.empty())
            region.parts.push_back(input.owner);
        else
            region.parts.insert(region.parts.end(), input.parts.begin(), input.parts.end());
    }
    std::sort(region.parts.begin(), region.parts.end());
    region.parts.erase(std::unique(region.parts.begin(), region.parts.end()), region.parts.end());
    region.owner = region.parts.front();
    if (region.parts.size() == 1)
        region.parts.clear();
}

// Appends to `pieces` the convex pieces of the union of one plane's `members` that unite two or
// more of them.
void unitePlaneGroup(const std::vector<OccluderRegion>& regions, const std::vector<std::uint32_t>& members,
                     VertexWelder& welder, const RegionUnionOptions& options, std::vector<OccluderRegion>& pieces)
{
    const std::vector<Vec3>& positions = welder.positions();
    const OccluderRegion& first = regions[members.front()];
    const Vec3 n = canonicalNormal(first.normal, first.oneSided);
    const Vec3 origin = positions[first.loop[0]];

    Vec3 along(0.0);
    Aabb extent;
    if (!(longestEdgeDirection(regions, members, positions, n, along, extent) > 0.0))
        return;
    const Vec3 u = along, v = glm::cross(n, u);
    // Only members truly in the plane: a piece must be as planar as its parts.
    const double offPlane = 1e-10 * glm::length(extent.extent());

    std::vector<UnionInput> inputs;
    std::vector<std::uint32_t> inputRegion;
    unionInputs(regions, members, positions, {origin, n, u, v}, offPlane, inputs, inputRegion);
    if (inputs.size() < 2)
        return;
    PlanarUnionOptions unionOptions;
    unionOptions.maxCorners = options.maxCorners;
    const std::vector<UnionPiece> united = planarUnion(inputs, unionOptions);
    if (united.empty())
        return;

    for (const UnionPiece& piece : united)
    {
        // A piece inside one input adds nothing (the two sides of a wall, an object's own
        // pieces cut again); one straddling inputs hides what none of them hides alone.
        if (piece.sources.size() < 2 || withinOneInput(piece, inputs))
            continue;
        OccluderRegion region;
        region.normal = n;
        region.oneSided = first.oneSided;
        region.loop = weldedPieceLoop(piece, welder, options.sceneSize);
        setPieceParts(piece, regions, inputRegion, region);
        // Rounding may have bent a piece out of shape: then it is left out.
        if (isConvexLoop(region.loop, positions, n, options.turnTolerance, options.planeTolerance,
                         std::max<std::uint32_t>(options.maxCorners, std::uint32_t(region.loop.size()))))
            pieces.push_back(std::move(region));
    }
}
} // namespace

void unitePlanarRegions(std::vector<OccluderRegion>& regions, VertexWelder& welder, const RegionUnionOptions& options)
{
    const std::map<PlaneKey, std::vector<std::uint32_t>> groups =
        planeGroups(regions, welder.positions(), options.sceneSize);

    std::vector<OccluderRegion> pieces;
    for (const auto& [key, members] : groups)
    {
        if (members.size() < 2)
            continue;
        unitePlaneGroup(regions, members, welder, options, pieces);
    }
    if (pieces.empty())
        return;
    // Object regions, then the pieces, then the stated occluders.
    const auto stated = std::stable_partition(regions.begin(), regions.end(),
                                              [](const OccluderRegion& r) { return r.owner != InvalidObject; });
    regions.insert(stated, std::make_move_iterator(pieces.begin()), std::make_move_iterator(pieces.end()));
}
} // namespace osgVis::core
