// SPDX-License-Identifier: MIT
// Marsden & Guibas, "The multifocal z-buffer": §4.5 (dynamic occluder selection — geometry is
// occluder and occludee at once, good occluders first, distant ones left out, everything retested
// after all insertions; several planes with the PVS passed on), §6 (PVS for a view volume).
// Conservativeness of every rule here: docs/multifocal.md.
#include <osgVis/core/multifocal/VolumeVisibility.h>

#include "MultifocalZBuffer.h"
#include "PlanePlacement.h"

#include <osgVis/core/geometry/ConvexPolygon.h>
#include <osgVis/core/occluders/OccluderBuilder.h>
#include <osgVis/core/occluders/SolidSections.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace osgVis::core
{
std::string MultifocalOptions::canonical() const
{
    std::ostringstream s;
    s.precision(17);
    s << "resolution=" << planeResolution << " planes=" << planesPerDirection << " angle=" << maxWindowAngle
      << " minAreaAngle=" << minAreaAngle << " maxOccluders=" << maxOccludersPerPlane << " near=" << nearDistance
      << " triangles=" << (triangles ? 1 : 0) << " fragments=" << maxFragmentsPerPixel;
    // note: only where set, so that files baked before these options existed keep their identity
    if (minNearDistance > 0.0)
        s << " minNear=" << minNearDistance;
    if (depthBits != 24)
        s << " depthBits=" << depthBits;
    return s.str();
}

double nearestNearPlane(const MultifocalOptions& options)
{
    return options.minNearDistance > 0.0 ? options.minNearDistance : options.nearDistance / 8.0;
}

double depthGapPerDistance2(const MultifocalOptions& options)
{
    const double nearest = nearestNearPlane(options);
    if (!(nearest > 0.0))
        return 0.0;
    return 8.0 / std::ldexp(nearest, int(std::min<std::uint32_t>(options.depthBits, 64)));
}

namespace
{
constexpr std::uint32_t NeverCulled = OBJECT_DYNAMIC | OBJECT_ALWAYS_VISIBLE;

struct FaceOccluder
{
    std::vector<Vec3> vertices; ///< the part beyond V's face
    Plane plane;
    ObjectId owner = InvalidObject;
    double areaAngle = 0.0;
    double depth = 0.0;
};

double polygonArea(const std::vector<Vec3>& v)
{
    Vec3 n(0.0);
    for (std::size_t i = 0; i < v.size(); ++i)
        n += glm::cross(v[i], v[(i + 1) % v.size()]);
    return 0.5 * glm::length(n);
}

/// True when every corner of V lies strictly on one side of the plane (beyond `margin`), and on its
/// front side when the polygon hides only from there.
bool planeClearOfVolume(const OccluderPolygon& polygon, const std::array<Vec3, 8>& corners, double margin)
{
    bool above = true, below = true;
    for (const Vec3& c : corners)
    {
        const double d = polygon.plane.distance(c);
        above = above && d > margin;
        below = below && d < -margin;
    }
    return polygon.oneSided ? above : (above || below);
}

/// The occluders usable on planes beyond `face`: clipped to the part beyond it, their plane clear
/// of V, not nearer than the near distance, not distant; best area-angle first.
std::vector<FaceOccluder> faceOccluders(const Scene& scene, const std::vector<OccluderPolygon>& occluders, const VolumeFace& face,
                                        const Aabb& volume, const std::array<Vec3, 8>& corners, double margin,
                                        const MultifocalOptions& options)
{
    std::vector<FaceOccluder> out;
    Vec3 normal(0.0);
    normal[face.axis] = face.direction;
    // Keeps depth >= 2·margin: the clipped piece is real geometry, so it hides what it hides.
    const Plane beyond(normal, -face.direction * face.coordinate - 2.0 * margin);
    const Vec3 centre = volume.center();
    const Aabb grown(volume.min - Vec3(margin), volume.max + Vec3(margin));
    for (const OccluderPolygon& polygon : occluders)
    {
        if (!planeClearOfVolume(polygon, corners, margin))
            continue;
        // A section inside a solid hides only from eyes outside it: sightlines from there reach
        // it through the drawn surface.
        if (polygon.insideSolid &&
            (polygon.owner >= scene.objects.size() || scene.objects[polygon.owner].bounds.intersects(grown)))
            continue;
        const ConvexPolygon piece = ConvexPolygon(polygon.vertices).clipped(beyond);
        if (piece.size() < 3)
            continue;
        FaceOccluder o;
        o.vertices = piece.vertices();
        o.plane = polygon.plane;
        o.owner = polygon.owner;
        double nearest = std::numeric_limits<double>::infinity();
        Vec3 centroid(0.0);
        for (const Vec3& p : o.vertices)
        {
            nearest = std::min(nearest, face.depth(p));
            centroid += p;
        }
        if (nearest < options.nearDistance)
            continue;
        centroid /= double(o.vertices.size());
        const Vec3 toward = centroid - centre;
        const double distance2 = glm::dot(toward, toward);
        if (!(distance2 > 0.0))
            continue;
        o.areaAngle = polygonArea(o.vertices) * std::abs(glm::dot(o.plane.normal, toward)) / (distance2 * std::sqrt(distance2));
        if (o.areaAngle < options.minAreaAngle)
            continue;
        o.depth = face.depth(centroid);
        out.push_back(std::move(o));
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const FaceOccluder& a, const FaceOccluder& b) { return a.areaAngle > b.areaAngle; });
    return out;
}

bool facesAwayFromVolume(const Triangle& t, const std::array<Vec3, 8>& corners)
{
    const Vec3 a(t.a), b(t.b), c(t.c);
    const Vec3 n = glm::cross(b - a, c - a);
    for (const Vec3& corner : corners)
        if (!(glm::dot(corner - a, n) < 0.0))
            return false;
    return true;
}

// What computeVolumePvs shares between V's faces and their planes: its arguments, V's corners, the
// scene's scale and rounding margin, the answer being built, and buffers reused from plane to plane.
struct VolumeCulling
{
    const Scene& scene;
    const std::vector<OccluderPolygon>& occluders;
    const Aabb& volume;
    const MultifocalOptions& options;
    const std::array<Vec3, 8> corners;
    const double size;
    const double margin;
    const bool withTriangles;
    VolumePvs& result;
    MultifocalZBuffer buffer{};
    std::vector<ObjectId> candidates{};
    std::vector<Aabb> candidateBounds{};
    std::vector<std::uint8_t> ownerCulled{}; // per object: culled, so its polygons add no cover
};

// Occludees: objects wholly beyond the face, still in the PVS.
void collectCandidates(VolumeCulling& c, const VolumeFace& face)
{
    c.candidates.clear();
    c.candidateBounds.clear();
    for (const SceneObject& object : c.scene.objects)
    {
        if ((object.flags & NeverCulled) || !c.result.objects.test(object.id) || object.bounds.empty())
            continue;
        const double nearest = face.direction > 0 ? object.bounds.min[face.axis] - face.coordinate
                                                  : face.coordinate - object.bounds.max[face.axis];
        if (nearest > 2.0 * c.margin)
        {
            c.candidates.push_back(object.id);
            c.candidateBounds.push_back(object.bounds);
        }
    }
}

// Inserts the usable occluders into the plane's buffer, best first, up to the per-plane limit;
// returns how many went in.
std::uint32_t insertOccluders(VolumeCulling& c, const std::vector<FaceOccluder>& usable)
{
    const std::size_t objectCount = c.scene.objects.size();
    std::uint32_t inserted = 0;
    for (const FaceOccluder& o : usable)
    {
        if (inserted >= c.options.maxOccludersPerPlane)
            break;
        if (o.owner != InvalidObject && o.owner < objectCount && c.ownerCulled[o.owner])
            continue; // its object is hidden whole: nothing of it adds cover
        // Occluder and occludee at once (§4.5): a hidden polygon adds no cover.
        if (c.buffer.hidden(o.vertices.data(), o.vertices.size()))
            continue;
        if (c.buffer.insert(o.vertices, o.plane))
            ++inserted;
    }
    return inserted;
}

// Tests the triangles [first, end) not hidden yet, marking those hidden now; true when all are.
bool allTrianglesHidden(VolumeCulling& c, std::size_t first, std::size_t end)
{
    bool allHidden = true;
    for (std::size_t index = first; index < end; ++index)
    {
        if (c.result.hiddenTriangles[index])
            continue;
        const Triangle& tri = c.scene.triangles[index];
        const Vec3 points[3] = {Vec3(tri.a), Vec3(tri.b), Vec3(tri.c)};
        ++c.result.statistics.trianglesTested;
        if (c.buffer.hidden(points, 3))
            c.result.hiddenTriangles[index] = 1;
        else
            allHidden = false;
    }
    return allHidden;
}

// Everything still in the PVS is tested after all insertions (§4.5, "apply twice"),
// so the answer does not depend on the order occluders came in.
void cullCandidates(VolumeCulling& c)
{
    for (ObjectId id : c.candidates)
    {
        if (!c.result.objects.test(id))
            continue;
        const SceneObject& object = c.scene.objects[id];
        const auto box = boxCorners(object.bounds);
        bool culled = c.buffer.hidden(box.data(), box.size());
        const auto [first, end] = c.scene.trianglesOf(object);
        if (!culled && c.withTriangles && end > first)
            culled = allTrianglesHidden(c, first, end);
        if (culled)
        {
            c.result.objects.clear(id);
            c.ownerCulled[id] = 1;
        }
    }
}

// Culls the candidates beyond `face` on the planes placed beyond it.
void cullBeyondFace(VolumeCulling& c, const VolumeFace& face)
{
    collectCandidates(c, face);
    if (c.candidates.empty())
        return;
    const std::vector<FaceOccluder> usable =
        faceOccluders(c.scene, c.occluders, face, c.volume, c.corners, c.margin, c.options);
    if (usable.empty())
        return;
    std::vector<DepthSample> samples;
    samples.reserve(usable.size());
    for (const FaceOccluder& o : usable)
        samples.push_back({o.depth, std::sqrt(o.areaAngle)});
    const double minDepth = std::max(1e-3 * c.size, 4.0 * c.margin);
    for (double depth : planeDepths(samples, c.options.planesPerDirection, minDepth))
    {
        const CorrespondencePlane plane =
            placePlane(face, c.volume, depth, c.candidateBounds, c.options.maxWindowAngle, c.options.planeResolution);
        if (plane.width <= 0)
            continue;
        c.buffer.reset(plane, c.volume, c.margin, depthGapPerDistance2(c.options));
        ++c.result.statistics.planes;
        c.result.statistics.occludersInserted += insertOccluders(c, usable);
        cullCandidates(c);
    }
}

// The statistics of the final PVS; the triangles of culled objects count as culled.
void countCulled(const Scene& scene, const std::array<Vec3, 8>& corners, bool withTriangles, VolumePvs& result)
{
    for (const SceneObject& object : scene.objects)
    {
        const bool culled = !result.objects.test(object.id);
        result.statistics.objectsCulled += culled ? 1 : 0;
        if (!withTriangles)
            continue;
        const auto [first, end] = scene.trianglesOf(object);
        for (std::size_t index = first; index < end; ++index)
        {
            if (culled)
                result.hiddenTriangles[index] = 1;
            const bool away = facesAwayFromVolume(scene.triangles[index], corners);
            result.statistics.trianglesBackFacing += away ? 1 : 0;
            result.statistics.trianglesBackFacingNotCulled += (away && !result.hiddenTriangles[index]) ? 1 : 0;
            result.statistics.trianglesCulled += result.hiddenTriangles[index];
        }
    }
}
} // namespace

std::vector<OccluderPolygon> volumeOccluders(const Scene& scene)
{
    std::vector<OccluderPolygon> occluders = buildOccluderPolygons(scene);
    std::vector<OccluderPolygon> sections = convexSolidSections(scene);
    occluders.insert(occluders.end(), std::make_move_iterator(sections.begin()), std::make_move_iterator(sections.end()));
    return occluders;
}

VolumePvs computeVolumePvs(const Scene& scene, const std::vector<OccluderPolygon>& occluders, const Aabb& volume,
                           const MultifocalOptions& options)
{
    const Vec3 extent = volume.extent();
    if (volume.empty() || !std::isfinite(extent.x + extent.y + extent.z + volume.min.x + volume.min.y + volume.min.z))
        throw std::invalid_argument("computeVolumePvs: the view volume is empty or not finite");

    VolumePvs result;
    const std::size_t objectCount = scene.objects.size();
    result.objects.reset(objectCount, true);
    const bool withTriangles = options.triangles && !scene.triangles.empty();
    if (withTriangles)
        result.hiddenTriangles.assign(scene.triangles.size(), 0);

    const auto corners = boxCorners(volume);
    Aabb all = scene.bounds();
    all.expand(volume);
    const double size = all.empty() ? 1.0 : std::max(glm::length(all.extent()), 1e-30);
    const double margin = 1e-9 * std::max(size, glm::length(glm::abs(all.center())));

    VolumeCulling culling{scene, occluders, volume, options, corners, size, margin, withTriangles, result};
    culling.buffer.maxFragmentsPerPixel = options.maxFragmentsPerPixel;
    culling.ownerCulled.assign(objectCount, 0);

    for (int axis = 0; axis < 3; ++axis)
        for (int direction : {1, -1})
            cullBeyondFace(culling, VolumeFace{axis, direction, direction > 0 ? volume.max[axis] : volume.min[axis]});

    countCulled(scene, corners, withTriangles, result);
    return result;
}
} // namespace osgVis::core
