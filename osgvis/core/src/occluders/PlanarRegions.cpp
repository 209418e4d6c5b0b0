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
} // namespace

void unitePlanarRegions(std::vector<OccluderRegion>& regions, VertexWelder& welder, const RegionUnionOptions& options)
{
    const std::vector<Vec3>& positions = welder.positions();
    const double offsetStep = 1e-7 * options.sceneSize;
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

    std::vector<OccluderRegion> pieces;
    for (const auto& [key, members] : groups)
    {
        if (members.size() < 2)
            continue;
        const OccluderRegion& first = regions[members.front()];
        const Vec3 n = canonicalNormal(first.normal, first.oneSided);
        const Vec3 origin = positions[first.loop[0]];

        // The slab direction follows the longest edge, so walls of axial rectangles cut into
        // axial rectangles.
        Vec3 along(0.0);
        double longest = 0.0;
        Aabb extent;
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
        if (!(longest > 0.0))
            continue;
        const Vec3 u = along, v = glm::cross(n, u);
        // Only members truly in the plane: a piece must be as planar as its parts.
        const double offPlane = 1e-10 * glm::length(extent.extent());

        std::vector<UnionInput> inputs;
        std::vector<std::uint32_t> inputRegion;
        for (std::uint32_t r : members)
        {
            const OccluderRegion& region = regions[r];
            UnionInput in;
            bool planar = true;
            for (std::uint32_t id : region.loop)
            {
                const Vec3 p = positions[id] - origin;
                planar = planar && std::abs(glm::dot(p, n)) <= offPlane;
                in.points.push_back({glm::dot(p, u), glm::dot(p, v)});
                in.ids.push_back(id);
            }
            if (!planar)
                continue;
            if (glm::dot(region.normal, n) < 0.0)
            {
                std::reverse(in.points.begin(), in.points.end());
                std::reverse(in.ids.begin(), in.ids.end());
            }
            inputs.push_back(std::move(in));
            inputRegion.push_back(r);
        }
        if (inputs.size() < 2)
            continue;
        PlanarUnionOptions unionOptions;
        unionOptions.maxCorners = options.maxCorners;
        const std::vector<UnionPiece> united = planarUnion(inputs, unionOptions);
        if (united.empty())
            continue;

        for (const UnionPiece& piece : united)
        {
            // A piece inside one input adds nothing (the two sides of a wall, an object's own
            // pieces cut again); one straddling inputs hides what none of them hides alone.
            if (piece.sources.size() < 2 || withinOneInput(piece, inputs))
                continue;
            OccluderRegion region;
            region.normal = n;
            region.oneSided = first.oneSided;
            for (const UnionCorner& c : piece.corners)
            {
                std::uint32_t id = c.id;
                if (id == NoUnionId)
                {
                    const Vec3 p = positions[c.from] + c.t * (positions[c.to] - positions[c.from]);
                    id = welder.weld(p, 1e-12 * options.sceneSize);
                }
                if (region.loop.empty() || region.loop.back() != id)
                    region.loop.push_back(id);
            }
            while (region.loop.size() > 1 && region.loop.front() == region.loop.back())
                region.loop.pop_back();
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
            // Rounding may have bent a piece out of shape: then it is left out.
            if (isConvexLoop(region.loop, positions, n, options.turnTolerance, options.planeTolerance,
                             std::max<std::uint32_t>(options.maxCorners, std::uint32_t(region.loop.size()))))
                pieces.push_back(std::move(region));
        }
    }
    if (pieces.empty())
        return;
    // Object regions, then the pieces, then the stated occluders.
    const auto stated = std::stable_partition(regions.begin(), regions.end(),
                                              [](const OccluderRegion& r) { return r.owner != InvalidObject; });
    regions.insert(stated, std::make_move_iterator(pieces.begin()), std::make_move_iterator(pieces.end()));
}
} // namespace osgVis::core
