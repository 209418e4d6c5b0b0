// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Turns a scene into occluder polygons: welds identical vertices, finds shared edges (OpenMesh
/// half-edge connectivity), merges coplanar adjacent triangles into convex polygons so tessellated
/// walls act as large occluders, and links polygons that share an edge.
#include <osgVis/core/occluders/OccluderPolygon.h>

namespace osgVis::core
{
struct OccluderBuildOptions
{
    /// Polygons smaller than this (world units²) are dropped: they hide too little to pay for a test.
    double minArea = 1e-4;
    /// Triangles whose unit normals differ by less than this angle (radians) and whose planes are
    /// within planeTolerance × polygon size count as coplanar. planeTolerance is also the sine of
    /// the largest bend of an outline that still counts as straight (convexity, collinear vertices),
    /// and triangles thinner than it relative to their length are slivers. Both tests also allow
    /// the few units in the last place that float storage of Scene::triangles may have moved a
    /// vertex, so tessellated walls far from the origin still merge.
    double coplanarAngle = 1e-5;
    double planeTolerance = 1e-6;
    /// Vertices closer than this (relative to the scene size) are welded before connectivity.
    double weldTolerance = 1e-7;
    /// Coplanar faces of different objects, and overlapping coplanar faces of one, also give the
    /// convex pieces of their union as polygons of their own (docs/occluders.md): a wall of many
    /// faces hides as one. Such a polygon names its objects in OccluderPolygon::parts; the faces
    /// stay as they were. Off by default: a union also spans faces that only abut along a
    /// T-junction, where the renderer's rasterization leaves pixel cracks that show what is behind
    /// (measured: one object seen through one pixel on OpenArena's oa_dm4). Turn it on only for
    /// models whose drawn faces are watertight.
    bool planarUnions = false;
    /// A vertex lying on another polygon's edge splits that edge, so both share it (links). Off by
    /// default for the same reason: the drawn faces keep their T-junction and its cracks.
    bool repairTJunctions = false;
    /// Use the triangles of every eligible object (static, opaque, not OBJECT_NO_AUTO_OCCLUDER), not
    /// only OBJECT_OCCLUDER objects and the scene's stated occluder polygons.
    bool sceneGeometry = true;
};

/// Eligible sources: Scene::occluders (stated polygons, two-sided), OBJECT_OCCLUDER objects and,
/// with sceneGeometry, every object that is not DYNAMIC, TRANSPARENT, ALWAYS_VISIBLE or
/// NO_AUTO_OCCLUDER. OBJECT_OCCLUDER overrides NO_AUTO_OCCLUDER only: DYNAMIC, TRANSPARENT and
/// ALWAYS_VISIBLE objects never occlude. OBJECT_CULL_BACK objects give one-sided polygons;
/// OBJECT_CULL_FRONT ones give one-sided polygons facing the other way; both flags: none.
/// Degenerate triangles (zero area, slivers, collinear or non-finite vertices) never become
/// occluders. Polygons have at most 32 corners, plus straight-line vertices kept where the
/// neighbour across the outline changes; they come in object order (per object, in the order of
/// the triangles that seeded them), then the stated polygons. Deterministic.
std::vector<OccluderPolygon> buildOccluderPolygons(const Scene& scene, const OccluderBuildOptions& options = {});
} // namespace osgVis::core
