// SPDX-License-Identifier: MIT
#include <osgVis/core/octree/BoxOcclusion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

// Why Invisible is sound (one polygon). Let q be any box point: the segment eye→q crosses P's
// plane at x (eye and q strictly on opposite sides). The eye strictly and q weakly on the positive
// side of every supporting plane S_i put x strictly on its positive side; within P's plane that
// side is P's side of the edge line (S_i meets P's plane exactly in that line, and P is on its
// positive side), so x lies inside every edge's half-plane, i.e. in the convex P. The supporting
// plane is the extreme plane of the pencil with P and B on one side, so it is the least
// restrictive choice that keeps this argument; any other would reject eyes that are hidden.

namespace osgVis::core
{
namespace
{
// Relative tolerances, scaled by the polygon's size (geometric) or by the coordinates' magnitude
// (cancellation in plane distances far from the origin).
constexpr double RelativeSizeTolerance = 1e-9;
constexpr double RelativeReachTolerance = 1e-12;
// Polygons thinner than this (area relative to the squared diameter) are slivers: their edge
// lines are ill-conditioned and they hide next to nothing, so they are not used.
constexpr double MinRelativeArea = 1e-6;

int signOf(double value)
{
    return (value > 0.0) - (value < 0.0); // NaN counts as zero
}

struct SilhouetteEntry
{
    std::uint8_t count = 0;
    std::array<std::uint8_t, 6> corners{};
};

// Entry for the direction with component signs (sx, sy, sz), each in {-1, 0, 1}. Seen along a
// direction with no zero component the box outline is a hexagon through every corner except the
// two extreme along ±direction. With one zero component the outline is a rectangle: the two
// corner pairs extreme along ±direction (an edge each) project inside it. With two zeros the
// direction is an axis and the corners coincide in pairs: one of each pair suffices.
constexpr SilhouetteEntry makeSilhouetteEntry(int sx, int sy, int sz)
{
    const int signs[3] = {sx, sy, sz};
    int zeros = 0, axisMask = 0, extremeBits = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (signs[axis] == 0)
        {
            ++zeros;
            continue;
        }
        axisMask |= 1 << axis;
        if (signs[axis] > 0)
            extremeBits |= 1 << axis;
    }
    SilhouetteEntry entry;
    for (int corner = 0; corner < 8; ++corner)
    {
        bool keep = false;
        if (zeros == 2)
            keep = (corner & axisMask) == 0; // one of each pair coinciding along the axis: its min end
        else if (zeros < 2)
        {
            const int bits = corner & axisMask;
            keep = bits != extremeBits && bits != (~extremeBits & axisMask);
        }
        if (keep)
            entry.corners[entry.count++] = static_cast<std::uint8_t>(corner);
    }
    return entry;
}

constexpr std::array<SilhouetteEntry, 27> makeSilhouetteTable()
{
    std::array<SilhouetteEntry, 27> table{};
    for (int sz = -1; sz <= 1; ++sz)
        for (int sy = -1; sy <= 1; ++sy)
            for (int sx = -1; sx <= 1; ++sx)
                table[(sx + 1) + 3 * (sy + 1) + 9 * (sz + 1)] = makeSilhouetteEntry(sx, sy, sz);
    return table;
}

constexpr std::array<SilhouetteEntry, 27> SilhouetteTable = makeSilhouetteTable();
static_assert(SilhouetteTable[26].count == 6 && SilhouetteTable[13].count == 0, "silhouette table");

bool finiteVec(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Cross-section coordinates of a point relative to an edge: x along `a` (into the polygon),
// y along `b` (the reference normal).
struct Section
{
    double x, y;
};

// z-component of the 2D cross product: > 0 when q is counter-clockwise from p (larger angle).
double cross2(const Section& p, const Section& q)
{
    return p.x * q.y - p.y * q.x;
}

// Plane of the edge's pencil through the cross-section point p, with the polygon's side
// (direction a, section angle 0) positive when p.y > 0. Needs |p| > 0.
Plane pencilPlane(const Vec3& start, const Vec3& a, const Vec3& b, const Section& p)
{
    const Vec3 normal = (p.y * a - p.x * b) / std::sqrt(p.x * p.x + p.y * p.y);
    return Plane::fromPointNormal(start, normal);
}

// Stands in for the supporting plane of a skipped (zero-length) edge: satisfied by every finite eye.
Plane alwaysSatisfiedPlane()
{
    return Plane(Vec3(0.0), std::numeric_limits<double>::max());
}

void clearPlanes(BoxOccluderPlanes& out)
{
    out.supporting.clear();
    out.separating.clear();
    out.hasSeparating.clear();
    out.boxSide = 0;
}

// Which side of the polygon's plane the box is on, beyond the tolerance: +1 front, -1 back, 0
// touching or crossing it.
int boxSideOf(const PreparedOccluder& polygon, const Aabb& box, double planeTolerance)
{
    const Vec3 boxExtent = box.extent();
    const double sideTolerance =
        2.0 * planeTolerance + RelativeSizeTolerance * glm::length(boxExtent); // > any start-point offset
    double nearest = std::numeric_limits<double>::max(), farthest = std::numeric_limits<double>::lowest();
    for (int corner = 0; corner < 8; ++corner)
    {
        const double distance = polygon.plane.distance(box.corner(corner));
        nearest = std::min(nearest, distance);
        farthest = std::max(farthest, distance);
    }
    return nearest > sideTolerance ? 1 : (farthest < -sideTolerance ? -1 : 0);
}

// The edge's candidate box corners in its cross-section: x along `inward`, y along `towardsBox`.
void edgeSections(const PreparedOccluder::Edge& edge, const Aabb& box, const Vec3& towardsBox, Section points[8])
{
    for (int k = 0; k < edge.candidateCount; ++k)
    {
        const Vec3 w = box.corner(edge.candidates[k]) - edge.start;
        points[k] = {glm::dot(w, edge.inward), glm::dot(w, towardsBox)};
    }
}

// The box strictly on one side: edge i's supporting plane goes through the section point of the
// largest angle, its separating plane through the smallest. False when a point is not above the
// plane.
bool setExtremePlanes(const PreparedOccluder::Edge& edge, const Vec3& towardsBox, const Section points[8],
                      BoxOccluderPlanes& out, std::size_t i)
{
    const int candidates = edge.candidateCount;
    // Every section point has an angle in (0, pi): compare angles by cross products.
    int largest = 0, smallest = 0;
    for (int k = 0; k < candidates; ++k)
    {
        if (!(points[k].y > 0.0))
            return false;
        if (cross2(points[largest], points[k]) > 0.0)
            largest = k;
        if (cross2(points[smallest], points[k]) < 0.0)
            smallest = k;
    }
    out.supporting[i] = pencilPlane(edge.start, edge.inward, towardsBox, points[largest]);
    out.separating[i] = pencilPlane(edge.start, edge.inward, towardsBox, points[smallest]);
    out.hasSeparating[i] = 1;
    return true;
}

// The box touches or crosses the polygon's plane. A separating plane of the pencil is
// tangent to the box's section from the edge line; of the two tangents the one through a
// point below the plane (y < 0) leaves the larger region to eyes in front, so it is
// tried first, then the one above.
void setTangentSeparatingPlane(const PreparedOccluder::Edge& edge, const Vec3& towardsBox, const Section points[8],
                               BoxOccluderPlanes& out, std::size_t i)
{
    const int candidates = edge.candidateCount;
    for (const double side : {-1.0, 1.0})
    {
        for (int k = 0; k < candidates && !out.hasSeparating[i]; ++k)
        {
            const Section p{points[k].x, side * points[k].y};
            if (!(p.y > 0.0))
                continue;
            const double pLength = std::sqrt(p.x * p.x + p.y * p.y);
            bool separates = true;
            for (int j = 0; j < candidates && separates; ++j)
            {
                const Section q{points[j].x, side * points[j].y};
                separates = cross2(q, p) <= 1e-12 * pLength * std::sqrt(q.x * q.x + q.y * q.y);
            }
            if (separates)
            {
                out.separating[i] = pencilPlane(edge.start, edge.inward, side * towardsBox, p);
                out.hasSeparating[i] = 1;
            }
        }
    }
}
} // namespace

int silhouetteCorners(const Vec3& edgeDirection, int corners[8])
{
    const int sx = signOf(edgeDirection.x), sy = signOf(edgeDirection.y), sz = signOf(edgeDirection.z);
    if (sx == 0 && sy == 0 && sz == 0)
    {
        // No direction (zero or NaN): every corner is a candidate.
        for (int corner = 0; corner < 8; ++corner)
            corners[corner] = corner;
        return 8;
    }
    const SilhouetteEntry& entry = SilhouetteTable[(sx + 1) + 3 * (sy + 1) + 9 * (sz + 1)];
    for (int k = 0; k < entry.count; ++k)
        corners[k] = entry.corners[k];
    return entry.count;
}

void prepareOccluder(const OccluderPolygon& polygon, PreparedOccluder& out)
{
    out.usable = false;
    out.edges.clear();
    const std::vector<Vec3>& vertices = polygon.vertices;
    const std::size_t count = vertices.size();
    if (count < 3)
        return;

    // The polygon must be what classify assumes: finite, planar in its stated (unit) plane,
    // counter-clockwise around its normal, convex and not a sliver. Anything else gets no planes.
    const double normalLength = glm::length(polygon.plane.normal);
    if (!std::isfinite(polygon.plane.d) || !(std::abs(normalLength - 1.0) <= 1e-6))
        return;
    const Vec3 normal = polygon.plane.normal / normalLength;

    Aabb bounds;
    for (const Vec3& v : vertices)
    {
        if (!finiteVec(v))
            return;
        bounds.expand(v);
    }
    const double size = glm::length(bounds.extent());
    const double reach =
        std::max(glm::length(glm::max(glm::abs(bounds.min), glm::abs(bounds.max))), std::abs(polygon.plane.d));
    if (!(size > 0.0) || !std::isfinite(size) || !std::isfinite(reach))
        return;

    Vec3 twiceAreaVector(0.0);
    double planeDeviation = 0.0;
    for (std::size_t i = 0; i < count; ++i)
    {
        planeDeviation = std::max(planeDeviation, std::abs(polygon.plane.distance(vertices[i])));
        twiceAreaVector += glm::cross(vertices[i] - vertices[0], vertices[(i + 1) % count] - vertices[0]);
    }
    const double twiceArea = glm::dot(twiceAreaVector, normal); // negative when clockwise
    if (!(twiceArea > 2.0 * MinRelativeArea * size * size) || twiceArea < 0.999 * glm::length(twiceAreaVector))
        return;

    double concavity = 0.0;
    out.edges.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        PreparedOccluder::Edge& edgeOut = out.edges[i];
        const Vec3& start = vertices[i];
        const Vec3& end = vertices[(i + 1) % count];
        edgeOut.start = start;
        edgeOut.repeated = start == end;
        if (edgeOut.repeated)
            continue; // the neighbouring edges meet there, so the outline is unchanged
        const Vec3 edge = end - start;
        const Vec3 inPlane = edge - glm::dot(edge, normal) * normal;
        const double edgeLength = glm::length(inPlane);
        if (!(edgeLength > RelativeSizeTolerance * size))
        {
            // Nearly coincident vertices: the edge's direction is noise. Skipping it could open
            // the outline at a sharp corner, so the polygon is not used.
            out.edges.clear();
            return;
        }
        edgeOut.along = inPlane / edgeLength;
        edgeOut.inward = glm::cross(normal, edgeOut.along);
        for (const Vec3& v : vertices)
            concavity = std::max(concavity, -glm::dot(v - start, edgeOut.inward));
        int corners[8];
        edgeOut.candidateCount = std::uint8_t(silhouetteCorners(edgeOut.along, corners));
        for (int k = 0; k < edgeOut.candidateCount; ++k)
            edgeOut.candidates[k] = std::uint8_t(corners[k]);
    }
    out.usable = true;
    out.plane = polygon.plane;
    out.normal = normal;
    out.size = size;
    out.reach = reach;
    out.planeDeviation = planeDeviation;
    out.concavity = concavity;
}

void computePlanes(const OccluderPolygon& polygon, const Aabb& box, BoxOccluderPlanes& out)
{
    PreparedOccluder prepared;
    prepareOccluder(polygon, prepared);
    computePlanes(prepared, box, out);
}

void computePlanes(const PreparedOccluder& polygon, const Aabb& box, BoxOccluderPlanes& out)
{
    clearPlanes(out);
    if (!polygon.usable || box.empty() || !box.finite())
        return;
    const double reach = std::max(polygon.reach, glm::length(glm::max(glm::abs(box.min), glm::abs(box.max))));
    if (!std::isfinite(reach))
        return;
    // Cancellation in plane distances grows with the coordinates' magnitude, so the planarity and
    // convexity tolerance depends on how far the box lies from the origin.
    const double planeTolerance = RelativeSizeTolerance * polygon.size + RelativeReachTolerance * reach;
    if (!(polygon.planeDeviation <= planeTolerance) || polygon.concavity > planeTolerance)
        return; // not planar, or not convex (or not counter-clockwise)
    const Vec3& normal = polygon.normal;
    const std::size_t count = polygon.edges.size();
    const int boxSide = boxSideOf(polygon, box, planeTolerance);

    // b points towards the box when it is on one side; otherwise it is the polygon's normal.
    const Vec3 towardsBox = boxSide < 0 ? -normal : normal;
    if (boxSide != 0)
        out.supporting.resize(count);
    out.separating.resize(count);
    out.hasSeparating.assign(count, 0);

    for (std::size_t i = 0; i < count; ++i)
    {
        const PreparedOccluder::Edge& edge = polygon.edges[i];
        if (edge.repeated)
        {
            if (boxSide != 0)
                out.supporting[i] = alwaysSatisfiedPlane();
            continue;
        }
        Section points[8];
        edgeSections(edge, box, towardsBox, points);
        if (boxSide == 0)
            setTangentSeparatingPlane(edge, towardsBox, points, out, i);
        else if (!setExtremePlanes(edge, towardsBox, points, out, i))
        {
            clearPlanes(out); // cannot happen past sideTolerance; never decide on it
            return;
        }
    }
    out.boxSide = boxSide;
}

Occlusion classify(const OccluderPolygon& polygon, const BoxOccluderPlanes& planes, const EyeVolume& eyes,
                   double margin)
{
    if (!(margin >= 0.0))
        margin = 0.0;
    const double eyeDistance = polygon.plane.distance(eyes.center);
    // Edge-on (some eye on or near the plane), or no finite eye: no decision can be trusted.
    if (!(std::abs(eyeDistance) > margin + eyes.spread(polygon.plane.normal)) || !std::isfinite(eyeDistance))
        return Occlusion::Visible;
    if (polygon.oneSided && eyeDistance < 0.0)
        return Occlusion::Visible;

    const std::size_t separatingCount = std::min(planes.separating.size(), planes.hasSeparating.size());
    const auto separatedByAPlane = [&]
    {
        for (std::size_t i = 0; i < separatingCount; ++i)
        {
            if (planes.hasSeparating[i] && eyes.maxDistance(planes.separating[i]) < -margin)
                return true;
        }
        return false;
    };

    if (planes.boxSide == 0)
        return separatedByAPlane() ? Occlusion::Visible : Occlusion::Partial;
    if ((planes.boxSide > 0) == (eyeDistance > 0.0))
        return Occlusion::Visible; // the box is on the eyes' side of the polygon

    bool hidden = planes.supporting.size() == polygon.vertices.size() && !planes.supporting.empty();
    for (std::size_t i = 0; hidden && i < planes.supporting.size(); ++i)
        hidden = eyes.minDistance(planes.supporting[i]) > margin;
    if (hidden)
        return Occlusion::Invisible;
    return separatedByAPlane() ? Occlusion::Visible : Occlusion::Partial;
}

Occlusion classifyBox(const OccluderPolygon& polygon, const Aabb& box, const Vec3& eye, double margin)
{
    BoxOccluderPlanes planes;
    computePlanes(polygon, box, planes);
    return classify(polygon, planes, eye, margin);
}

// Why fusedInvisible is sound for any (also non-convex) union. Project from the eye onto the
// sphere of directions and sum the active polygons' projections, each signed by the side the eye
// sees (+1 front). A skipped edge occurs in two polygons with equal sign and opposite direction,
// so it cancels: the tested edges form the boundary cycle of that sum. For a direction d to a box
// point, d lies strictly on the inner side of every tested edge's great circle (its supporting
// plane), so the angle around d grows along every tested edge: the cycle winds at least once
// around d, while the opposite direction -d (away from every plane) is covered by nothing. The
// signed coverage at d is therefore >= 1, so some polygon covers d, and it lies before the box
// because the box is behind every plane. This needs at least one tested edge.
bool fusedInvisible(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& active,
                    const std::vector<BoxOccluderPlanes>& planes, const EyeVolume& eyes, double margin)
{
    // Every eye of the volume lies on the same side of every active polygon's plane (checked
    // below), so the sides taken at the centre are every eye's, and the proof holds per eye.
    const Vec3& eye = eyes.center;
    if (!(margin >= 0.0))
        margin = 0.0;
    if (active.empty() || planes.size() < active.size())
        return false;

    const auto isActive = [&](std::uint32_t index)
    {
        for (const std::uint32_t a : active)
        {
            if (a == index)
                return true;
        }
        return false;
    };
    const auto eyeSide = [&](const OccluderPolygon& polygon) { return polygon.plane.distance(eye) > 0.0 ? 1 : -1; };

    // Every polygon must hide on its own terms: eye clearly off its plane, not culled, box behind.
    for (std::size_t j = 0; j < active.size(); ++j)
    {
        if (active[j] >= polygons.size())
            return false;
        const OccluderPolygon& polygon = polygons[active[j]];
        const BoxOccluderPlanes& own = planes[j];
        const double eyeDistance = polygon.plane.distance(eye);
        if (!(std::abs(eyeDistance) > margin + eyes.spread(polygon.plane.normal)) || !std::isfinite(eyeDistance))
            return false;
        if (polygon.oneSided && eyeDistance < 0.0)
            return false;
        if (own.boxSide == 0 || (own.boxSide > 0) == (eyeDistance > 0.0))
            return false;
        if (own.supporting.size() != polygon.vertices.size())
            return false;
    }

    std::size_t testedEdges = 0;
    for (std::size_t j = 0; j < active.size(); ++j)
    {
        const std::uint32_t index = active[j];
        const OccluderPolygon& polygon = polygons[index];
        const std::vector<Vec3>& vertices = polygon.vertices;
        const std::size_t count = vertices.size();
        for (std::size_t i = 0; i < count; ++i)
        {
            const std::uint32_t neighbour = i < polygon.neighbours.size() ? polygon.neighbours[i] : NoNeighbour;
            if (neighbour != NoNeighbour && neighbour != index && neighbour < polygons.size() && isActive(neighbour) &&
                eyeSide(polygons[neighbour]) == eyeSide(polygon))
            {
                // Skip only a truly shared edge, traversed the other way round by the neighbour
                // (consistent orientation is what makes equal eye sides mean "not a silhouette").
                const OccluderPolygon& other = polygons[neighbour];
                const Vec3& start = vertices[i];
                const Vec3& end = vertices[(i + 1) % count];
                bool shared = false;
                for (std::size_t k = 0; k < other.vertices.size() && !shared; ++k)
                {
                    shared = k < other.neighbours.size() && other.neighbours[k] == index && other.vertices[k] == end &&
                             other.vertices[(k + 1) % other.vertices.size()] == start;
                }
                if (shared)
                    continue;
            }
            const Plane& supporting = planes[j].supporting[i];
            if (!(eyes.minDistance(supporting) > margin))
                return false;
            if (supporting.normal != Vec3(0.0))
                ++testedEdges;
        }
    }
    return testedEdges > 0;
}
} // namespace osgVis::core
