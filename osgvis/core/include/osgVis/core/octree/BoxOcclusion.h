// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Occlusion of an axial box (a tree node) by convex occluder polygons from a viewpoint, after
/// Coorg & Teller. The planes are independent of the eye: for each occluder edge, the supporting
/// plane (through the edge and a box vertex, occluder and box on the same side) and the separating
/// plane (through the edge and a box vertex, occluder and box on opposite sides). The eye decides
/// by which side of them it is on, so a plane list can be kept between frames and only re-checked.
///
///   Invisible: the box lies strictly behind the occluder's plane and the eye is strictly on the
///              occluder's side of every supporting plane (every ray from the eye to the box
///              crosses the polygon).
///   Visible:   the occluder hides no part of the box: the eye is strictly on the box's side of a
///              separating plane, or the box is not behind the occluder's plane at all.
///   Partial:   anything else (the occluder may hide part of the box; children may be hidden).
/// Invisible is exact up to a safety margin: whenever the answer is Invisible the whole box is
/// hidden. Visible and Partial may be pessimistic (they only cost culling, never correctness).
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/occluders/OccluderPolygon.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace osgVis::core
{
enum class Occlusion : std::uint8_t
{
    Visible,
    Partial,
    Invisible
};

/// The eye-independent planes of one occluder against one box.
struct BoxOccluderPlanes
{
    /// Per edge i of the polygon. A supporting plane is oriented so that the polygon and the box
    /// are on its positive side; a separating plane so that the polygon is on its positive side
    /// and the box on its negative side. `hasSeparating[i]` is false when no plane through edge i
    /// separates them (the box reaches across the edge's line). All normals are unit.
    /// An edge between repeated vertices is skipped: its supporting plane has a zero normal and
    /// d = +max (satisfied by every finite eye) and it has no separating plane. When the box
    /// crosses the polygon's plane, of the two separating planes an edge may have the one better
    /// for eyes in front (through the part of the box behind the plane) is kept if it exists.
    std::vector<Plane> supporting, separating;
    std::vector<std::uint8_t> hasSeparating;
    /// The box lies strictly on one side of the polygon's plane: +1 front (normal side), -1 back,
    /// 0 it touches or straddles the plane (then `supporting` is empty: never Invisible).
    /// A polygon that cannot be trusted (fewer than 3 vertices, not finite, not planar in its
    /// stated plane, clockwise, not convex, a sliver, nearly coincident vertices) and an empty or
    /// non-finite box give boxSide 0 and all three vectors empty.
    int boxSide = 0;
};

/// Candidate box corners for the extreme planes through an edge of direction `edgeDirection`:
/// the corners on the box's silhouette seen along that direction (6, or 4 when the direction lies
/// in a coordinate plane), from a table indexed by the direction's signs. Returns the count
/// written to `corners` (corner indices as in Aabb::corner).
int silhouetteCorners(const Vec3& edgeDirection, int corners[8]);

/// The eyes a decision must hold for: one point (zero half extent) or every point of an axial box
/// (a region of viewpoints). A plane test on the volume uses its nearest or farthest point.
struct EyeVolume
{
    Vec3 center{0.0};
    Vec3 halfExtent{0.0};

    /// How far the volume reaches from its centre along a unit `normal`.
    double spread(const Vec3& normal) const
    {
        return std::abs(normal.x) * halfExtent.x + std::abs(normal.y) * halfExtent.y +
               std::abs(normal.z) * halfExtent.z;
    }
    double minDistance(const Plane& plane) const { return plane.distance(center) - spread(plane.normal); }
    double maxDistance(const Plane& plane) const { return plane.distance(center) + spread(plane.normal); }
};

/// The part of computePlanes that depends on the polygon alone, done once per polygon instead of
/// once per box: the checks that need no box (finite, unit plane, not a sliver, no near-zero edge),
/// each edge's in-plane frame and the box corners that can lie on the silhouette along it. The
/// planarity and convexity checks, whose tolerance grows with the box's distance from the origin,
/// keep the polygon's worst deviation, compared per box.
struct PreparedOccluder
{
    struct Edge
    {
        Vec3 start{0.0};
        Vec3 along{0.0};  ///< unit edge direction in the polygon's plane
        Vec3 inward{0.0}; ///< unit, in the plane, towards the polygon's inside
        std::uint8_t candidateCount = 0;
        std::array<std::uint8_t, 8> candidates{}; ///< silhouetteCorners(along)
        bool repeated = false;                    ///< start equals end: no edge
    };
    bool usable = false; ///< false: computePlanes gives no planes for any box
    Plane plane;
    Vec3 normal{0.0};      ///< plane.normal made unit
    double size = 0.0;     ///< the polygon's bounds' diagonal
    double reach = 0.0;    ///< the largest of its vertices' magnitude (per axis) and |plane.d|
    double planeDeviation = 0.0; ///< the largest |distance| of a vertex from the plane
    double concavity = 0.0;      ///< the farthest a vertex lies outside an edge's inner side
    std::vector<Edge> edges;
};

void prepareOccluder(const OccluderPolygon& polygon, PreparedOccluder& out);

/// Computes the planes of a prepared polygon against `box`: the same planes, bit for bit, as the
/// overload below.
void computePlanes(const PreparedOccluder& polygon, const Aabb& box, BoxOccluderPlanes& out);

/// Computes the planes of `polygon` against `box` (prepareOccluder, then the above).
void computePlanes(const OccluderPolygon& polygon, const Aabb& box, BoxOccluderPlanes& out);

/// Classifies from `eye` with planes computed by computePlanes. `margin` (world units) is the
/// distance the eye must keep from every deciding plane; closer counts as on the plane, which
/// never gives Invisible (an eye within `margin` of the polygon's plane gives Visible). It must
/// exceed rounding, e.g. 1e-9 of the scene's size. A one-sided polygon seen from its culled side
/// hides nothing: Visible. Allocation-free.
Occlusion classify(const OccluderPolygon& polygon, const BoxOccluderPlanes& planes, const EyeVolume& eyes,
                   double margin);
/// For a volume of eyes: Invisible only when every eye of the volume has the box hidden; Visible
/// when no eye has any of it hidden, and also when the volume comes within `margin` of the
/// occluder's plane (no decision, as for a point eye on the plane).
inline Occlusion classify(const OccluderPolygon& polygon, const BoxOccluderPlanes& planes, const Vec3& eye,
                          double margin)
{
    return classify(polygon, planes, EyeVolume{eye, Vec3(0.0)}, margin);
}

/// Convenience: computePlanes then classify.
Occlusion classifyBox(const OccluderPolygon& polygon, const Aabb& box, const Vec3& eye, double margin);

/// Connected occluders (paper §2.1): the box is hidden by the union of `active` polygons (indices
/// into `polygons`, each one Partial for this box) when the box lies strictly behind every one of
/// their planes and the eye is strictly on the inner side of the supporting plane of every edge
/// of theirs, except edges shared by two active polygons that are not a silhouette edge from the
/// eye (the eye on the same side of both planes). An edge whose neighbour is not active is always
/// tested. Conservative also for non-convex unions: the eye inside all those planes puts the box's
/// projection inside the kernel of the union's projected outline, which lies within the union.
/// `planes[j]` are the planes of polygons[active[j]] against `box`.
/// For a volume of eyes the union must hide the box from every one of them.
bool fusedInvisible(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& active,
                    const std::vector<BoxOccluderPlanes>& planes, const EyeVolume& eyes, double margin);
inline bool fusedInvisible(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& active,
                           const std::vector<BoxOccluderPlanes>& planes, const Vec3& eye, double margin)
{
    return fusedInvisible(polygons, active, planes, EyeVolume{eye, Vec3(0.0)}, margin);
}
} // namespace osgVis::core
