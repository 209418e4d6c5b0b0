// SPDX-License-Identifier: MIT
// Occluder polygons from scene geometry: weld, connect (OpenMesh), merge coplanar neighbours into
// convex polygons, then link polygons across the edges they share.
#include <osgVis/core/occluders/OccluderBuilder.h>

#include "BoundaryLoop.h"
#include "OccluderSources.h"
#include "CoplanarMerger.h"
#include "OccluderRegion.h"
#include "VertexWelder.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace osgVis::core
{
namespace
{
// More corners cost more per occlusion test than the extra area is worth.
constexpr std::uint32_t MaxCorners = 32;

bool isFinite(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

struct ObjectTriangles
{
    ObjectId owner;
    bool oneSided;
    std::vector<MergeTriangle> triangles;
};

using Region = OccluderRegion;

// The triangle with welded corners, or false when its plane cannot be trusted: repeated or
// collinear corners, or a sliver thinner than the plane tolerance relative to its length.
bool weldedTriangle(const std::array<std::uint32_t, 3>& ids, const std::vector<Vec3>& positions, double planeTolerance,
                    MergeTriangle& out)
{
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0])
        return false;
    const Vec3& a = positions[ids[0]];
    const Vec3& b = positions[ids[1]];
    const Vec3& c = positions[ids[2]];
    const Vec3 n = glm::cross(b - a, c - a);
    const double twiceArea = glm::length(n);
    const double longest2 = std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
    if (!(twiceArea > 0.0) || !std::isfinite(twiceArea) || 0.5 * twiceArea < planeTolerance * longest2)
        return false;
    out.vertices = ids;
    out.normal = n / twiceArea;
    // Float storage moves each corner by up to storageSlack, which tilts the normal by up to
    // about twice that over the triangle's smallest height.
    const double height = twiceArea / std::sqrt(longest2);
    out.normalSlack = 2.0 * std::max({storageSlack(a), storageSlack(b), storageSlack(c)}) / height;
    return true;
}

// Neighbour of each loop edge (as a region index): the one other region whose loop has an edge
// between the same two welded vertices; NoNeighbour when none or several do.
std::vector<std::vector<std::uint32_t>> edgeNeighbours(const std::vector<Region>& regions)
{
    struct Edge
    {
        std::uint64_t key;
        std::uint32_t region, index;
        bool forward; // runs from the smaller id to the larger
    };
    std::vector<Edge> edges;
    std::size_t total = 0;
    for (const Region& r : regions)
        total += r.loop.size();
    edges.reserve(total);
    for (std::uint32_t r = 0; r < regions.size(); ++r)
    {
        const auto& loop = regions[r].loop;
        for (std::uint32_t i = 0; i < loop.size(); ++i)
        {
            const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
            edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), r, i, a < b});
        }
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& x, const Edge& y) {
                  return x.key != y.key ? x.key < y.key
                                        : (x.region != y.region ? x.region < y.region : x.index < y.index);
              });

    std::vector<std::vector<std::uint32_t>> across(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r)
        across[r].assign(regions[r].loop.size(), NoNeighbour);
    for (std::size_t i = 0; i < edges.size();)
    {
        std::size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key)
            ++j;
        // note: three or more polygons on one edge (a fin on a wall) link none of them; an
        // unlinked edge is always safe. Two link only when they run the edge in opposite
        // directions, as consistently wound neighbours do: then, facing the eye alike, they lie
        // on opposite sides of it on screen, which the fused tests rely on. Two that run it the
        // same way lie on one side (coplanar overlapping faces, a union piece over its faces).
        if (j - i == 2 && edges[i].region != edges[i + 1].region && edges[i].forward != edges[i + 1].forward)
        {
            across[edges[i].region][edges[i].index] = edges[i + 1].region;
            across[edges[i + 1].region][edges[i + 1].index] = edges[i].region;
        }
        i = j;
    }
    return across;
}

// What may become an occluder: the eligible objects, the valid stated polygons, and the extent of
// them all (it scales the weld tolerance).
struct EligibleSources
{
    std::vector<ObjectId> objects;
    std::size_t triangleCount = 0;
    std::vector<const ConvexPolygon*> stated;
    Aabb extent;
};

EligibleSources eligibleSources(const Scene& scene, const OccluderBuildOptions& options, double planeTolerance)
{
    EligibleSources sources;
    for (const SceneObject& object : scene.objects)
    {
        if (!isEligible(object, options.sceneGeometry))
            continue;
        sources.objects.push_back(ObjectId(&object - scene.objects.data()));
        const auto [first, end] = scene.trianglesOf(object);
        sources.triangleCount += end - first;
        for (std::size_t t = first; t < end; ++t)
        {
            const Triangle& tri = scene.triangles[t];
            for (const Vec3f& v : {tri.a, tri.b, tri.c})
            {
                if (isFinite(Vec3(v)))
                    sources.extent.expand(Vec3(v));
            }
        }
    }
    for (const OccluderCandidate& candidate : scene.occluders)
    {
        if (!candidate.polygon.isValidOccluder(options.minArea, planeTolerance > 0.0 ? planeTolerance : 1e-6))
            continue;
        sources.stated.push_back(&candidate.polygon);
        for (const Vec3& v : candidate.polygon.vertices())
            sources.extent.expand(v);
    }
    return sources;
}

// Appends the usable triangles of `object` to `entry`, welded, with the winding of its drawn side.
void appendWeldedTriangles(const Scene& scene, const SceneObject& object, ObjectId id, bool flip, double planeTolerance,
                           VertexWelder& welder, ObjectTriangles& entry)
{
    const auto [first, end] = scene.trianglesOf(object);
    entry.triangles.reserve(entry.triangles.size() + (end - first));
    for (std::size_t t = first; t < end; ++t)
    {
        const Triangle& tri = scene.triangles[t];
        const Vec3 a(tri.a), b(tri.b), c(tri.c);
        if (!isFinite(a) || !isFinite(b) || !isFinite(c))
            continue;
        // Culled front faces: the drawn side is the back, so the winding turns round.
        std::array<std::uint32_t, 3> ids{welder.weld(a), welder.weld(flip ? c : b), welder.weld(flip ? b : c)};
        MergeTriangle merged;
        if (weldedTriangle(ids, welder.positions(), planeTolerance, merged))
        {
            merged.tag = id;
            entry.triangles.push_back(merged);
        }
    }
}

// The welded triangles of each source object; objects left without any go.
std::vector<ObjectTriangles> weldObjectTriangles(const Scene& scene, const std::vector<ObjectId>& sources,
                                                 double planeTolerance, VertexWelder& welder)
{
    // note: the clusters of one split drawable (SceneObject::group) merge as one object, so a face
    // that crosses cluster borders stays one polygon; each polygon names the clusters its triangles
    // come from (tags), and a module uses it only while all of them are drawn.
    std::vector<ObjectTriangles> objects;
    objects.reserve(sources.size());
    std::unordered_map<std::uint64_t, std::size_t> entryOfGroup;
    for (ObjectId id : sources)
    {
        const SceneObject& object = scene.objects[id];
        const bool flip = (object.flags & OBJECT_CULL_FRONT) != 0;
        const bool oneSided = (object.flags & (OBJECT_CULL_BACK | OBJECT_CULL_FRONT)) != 0;
        std::size_t entryIndex = objects.size();
        if (object.group != InvalidObject)
        {
            const std::uint64_t key = (std::uint64_t(object.group) << 2) |
                                      ((object.flags & OBJECT_CULL_BACK) ? 1u : 0u) | (flip ? 2u : 0u);
            const auto [found, inserted] = entryOfGroup.emplace(key, objects.size());
            entryIndex = found->second;
            if (inserted)
                objects.push_back({id, oneSided, {}});
        }
        else
            objects.push_back({id, oneSided, {}});
        appendWeldedTriangles(scene, object, id, flip, planeTolerance, welder, objects[entryIndex]);
    }
    objects.erase(std::remove_if(objects.begin(), objects.end(),
                                 [](const ObjectTriangles& entry) { return entry.triangles.empty(); }),
                  objects.end());
    return objects;
}

// The stated polygons as loops of welded ids without repeated corners; loops that collapse go.
std::vector<std::vector<std::uint32_t>> weldStatedLoops(const std::vector<const ConvexPolygon*>& stated,
                                                        VertexWelder& welder)
{
    std::vector<std::vector<std::uint32_t>> statedLoops;
    for (const ConvexPolygon* polygon : stated)
    {
        std::vector<std::uint32_t> loop;
        for (const Vec3& v : polygon->vertices())
        {
            const std::uint32_t id = welder.weld(v);
            if (loop.empty() || loop.back() != id)
                loop.push_back(id);
        }
        while (loop.size() > 1 && loop.front() == loop.back())
            loop.pop_back();
        if (loop.size() >= 3)
            statedLoops.push_back(std::move(loop));
    }
    return statedLoops;
}

// The convex polygons each object's coplanar triangles merge into, per object.
std::vector<std::vector<MergedPolygon>> mergeCoplanarTriangles(const std::vector<ObjectTriangles>& objects,
                                                               const std::vector<Vec3>& positions,
                                                               const OccluderBuildOptions& options,
                                                               double planeTolerance)
{
    CoplanarMergeOptions mergeOptions;
    mergeOptions.sinCoplanarAngle = std::sin(std::clamp(options.coplanarAngle, 0.0, 1.5));
    mergeOptions.planeTolerance = planeTolerance;
    mergeOptions.turnTolerance = planeTolerance;
    mergeOptions.maxCorners = MaxCorners;

    // Objects merge independently (one OpenMesh mesh each), so they run in parallel; results are
    // gathered in object order, which keeps the output the same on every run.
    std::vector<std::vector<MergedPolygon>> mergedPerObject(objects.size());
    tbb::enumerable_thread_specific<CoplanarMerger> mergers([&] { return CoplanarMerger(positions, mergeOptions); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size()),
                      [&](const tbb::blocked_range<std::size_t>& range)
                      {
                          CoplanarMerger& merger = mergers.local();
                          for (std::size_t i = range.begin(); i != range.end(); ++i)
                              merger.merge(objects[i].triangles, mergedPerObject[i]);
                      });
    return mergedPerObject;
}

// The merged polygons as regions, in object order, then the stated loops (moved from).
std::vector<Region> regionsOf(const std::vector<ObjectTriangles>& objects,
                              std::vector<std::vector<MergedPolygon>>& mergedPerObject,
                              std::vector<std::vector<std::uint32_t>>& statedLoops, const std::vector<Vec3>& positions)
{
    std::vector<Region> regions;
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
        for (MergedPolygon& polygon : mergedPerObject[i])
        {
            // A polygon of one object (or of one cluster) has no parts; one over several clusters
            // names them all.
            const ObjectId owner = polygon.tags.empty() ? objects[i].owner : polygon.tags.front();
            std::vector<ObjectId> parts;
            if (polygon.tags.size() > 1)
                parts.assign(polygon.tags.begin(), polygon.tags.end());
            regions.push_back({std::move(polygon.loop), polygon.normal, owner, objects[i].oneSided, std::move(parts)});
        }
    }
    for (std::vector<std::uint32_t>& loop : statedLoops)
    {
        const Vec3 normal = glm::normalize(loopNormal(loop, positions));
        regions.push_back({std::move(loop), normal, InvalidObject, false, {}});
    }
    return regions;
}

// The optional coplanar unions and T-junction repair, and the dropping of pieces too small.
void refineRegions(std::vector<Region>& regions, VertexWelder& welder, double sceneSize, double planeTolerance,
                   const OccluderBuildOptions& options)
{
    const std::vector<Vec3>& positions = welder.positions();
    if (options.planarUnions)
    {
        RegionUnionOptions unionOptions;
        unionOptions.sceneSize = sceneSize;
        unionOptions.turnTolerance = planeTolerance;
        unionOptions.planeTolerance = planeTolerance;
        unionOptions.maxCorners = MaxCorners;
        unitePlanarRegions(regions, welder, unionOptions);
    }
    // Small pieces go only now: many small faces may unite into a large one.
    regions.erase(std::remove_if(regions.begin(), regions.end(),
                                 [&](const Region& region)
                                 {
                                     const double area = 0.5 * glm::length(loopNormal(region.loop, positions));
                                     return !(std::isfinite(area) && area > 0.0 && area >= options.minArea);
                                 }),
                  regions.end());
    if (options.repairTJunctions)
        repairTJunctions(regions, positions, sceneSize);
}

// Fills `polygon` and `outlineIds` with the corners of `region` (its neighbours across each loop
// edge in `across`); returns whether the polygon can be used.
bool outlinePolygon(const Region& region, const std::vector<std::uint32_t>& across, const std::vector<Vec3>& positions,
                    double planeTolerance, OccluderPolygon& polygon, std::vector<std::uint32_t>& outlineIds)
{
    const std::size_t n = region.loop.size();
    std::vector<bool> keep(n);
    for (std::size_t i = 0; i < n; ++i)
        keep[i] = across[(i + n - 1) % n] != across[i];
    const std::vector<std::size_t> corners = cornerIndices(region.loop, positions, region.normal, planeTolerance, keep);

    for (std::size_t i : corners)
    {
        outlineIds.push_back(region.loop[i]);
        polygon.vertices.push_back(positions[region.loop[i]]);
        polygon.neighbours.push_back(across[i]);
    }
    const ConvexPolygon outline(polygon.vertices);
    const Vec3 newell = outline.newellNormal();
    polygon.area = 0.5 * glm::length(newell);
    polygon.centroid = outline.centroid();
    polygon.plane = Plane::fromPointNormal(polygon.centroid, newell / glm::length(newell));
    polygon.oneSided = region.oneSided;
    polygon.owner = region.owner;
    polygon.parts = region.parts;
    return corners.size() >= 3 && polygon.area > 0.0 && isFinite(polygon.plane.normal) &&
           std::isfinite(polygon.plane.d);
}

// A neighbour must have the very same edge back; tolerance calls made on each side alone
// could differ, and then the edge is left unlinked.
void unlinkUnmatchedEdges(std::vector<OccluderPolygon>& polygons,
                          const std::vector<std::vector<std::uint32_t>>& outlineIds)
{
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
        const auto& ids = outlineIds[p];
        for (std::size_t i = 0; i < ids.size(); ++i)
        {
            std::uint32_t& q = polygons[p].neighbours[i];
            if (q == NoNeighbour)
                continue;
            const std::uint32_t a = ids[i], b = ids[(i + 1) % ids.size()];
            const auto& other = outlineIds[q];
            bool matched = false;
            for (std::size_t j = 0; j < other.size() && !matched; ++j)
            {
                const std::uint32_t c = other[j], d = other[(j + 1) % other.size()];
                matched = c == b && d == a && polygons[q].neighbours[j] == p;
            }
            if (!matched)
                q = NoNeighbour;
        }
    }
}

// note: outlines are built from loops that passed the convexity check, so none should fail
// here; should one, it goes and its neighbours' links to it are cut.
void dropUnusablePolygons(std::vector<OccluderPolygon>& polygons, const std::vector<bool>& usable)
{
    std::vector<std::uint32_t> newIndex(polygons.size(), NoNeighbour);
    std::uint32_t kept = 0;
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
        if (usable[p])
            newIndex[p] = kept++;
    }
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
        if (!usable[p])
            continue;
        for (std::uint32_t& q : polygons[p].neighbours)
            q = q == NoNeighbour ? NoNeighbour : newIndex[q];
        if (newIndex[p] != p)
            polygons[newIndex[p]] = std::move(polygons[p]);
    }
    polygons.resize(kept);
}
} // namespace

std::vector<OccluderPolygon> buildOccluderPolygons(const Scene& scene, const OccluderBuildOptions& options)
{
    const double planeTolerance = std::max(options.planeTolerance, 0.0);

    const EligibleSources sources = eligibleSources(scene, options, planeTolerance);
    if (sources.extent.empty())
        return {};

    const double sceneSize = glm::length(sources.extent.extent());
    VertexWelder welder(sources.extent.min, sceneSize, std::max(options.weldTolerance, 0.0) * sceneSize);
    welder.reserve(sources.triangleCount); // closed meshes have about half as many vertices as triangles

    const std::vector<ObjectTriangles> objects = weldObjectTriangles(scene, sources.objects, planeTolerance, welder);
    std::vector<std::vector<std::uint32_t>> statedLoops = weldStatedLoops(sources.stated, welder);
    const std::vector<Vec3>& positions = welder.positions();

    std::vector<std::vector<MergedPolygon>> mergedPerObject =
        mergeCoplanarTriangles(objects, positions, options, planeTolerance);
    std::vector<Region> regions = regionsOf(objects, mergedPerObject, statedLoops, positions);
    refineRegions(regions, welder, sceneSize, planeTolerance, options);

    // Straight-line vertices go, except where the neighbour across the outline changes: there
    // both polygons keep the vertex, so their shared edges still match end to end.
    const std::vector<std::vector<std::uint32_t>> across = edgeNeighbours(regions);
    std::vector<OccluderPolygon> polygons(regions.size());
    std::vector<std::vector<std::uint32_t>> outlineIds(regions.size());
    std::vector<bool> usable(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r)
        usable[r] = outlinePolygon(regions[r], across[r], positions, planeTolerance, polygons[r], outlineIds[r]);

    unlinkUnmatchedEdges(polygons, outlineIds);
    dropUnusablePolygons(polygons, usable);
    return polygons;
}
} // namespace osgVis::core
