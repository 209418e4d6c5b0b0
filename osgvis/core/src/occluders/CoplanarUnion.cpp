// SPDX-License-Identifier: MIT
#include <osgVis/core/occluders/CoplanarUnion.h>

#include "Outline2.h"

#include <algorithm>
#include <cmath>
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
            Outline2 outline;
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
            if (onPlane && signedArea(piece.outline) > 0.0)
                pieces.push_back(std::move(piece));
        }

        for (bool merged = true; merged;)
        {
            merged = false;
            for (std::size_t i = 0; i < pieces.size(); ++i)
                for (std::size_t j = i + 1; j < pieces.size(); ++j)
                {
                    const std::vector<std::size_t> hull =
                        convexUnionIndices(pieces[i].outline, pieces[j].outline, MaxCorners);
                    if (hull.empty())
                        continue;
                    Outline2 joined;
                    for (std::size_t k : hull)
                        joined.push_back(k < pieces[i].outline.size() ? pieces[i].outline[k]
                                                                      : pieces[j].outline[k - pieces[i].outline.size()]);
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
