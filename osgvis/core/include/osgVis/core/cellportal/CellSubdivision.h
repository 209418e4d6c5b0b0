// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Cell subdivision after Teller & Séquin: a kd-tree split along the model's large axial opaque faces
/// (walls, floors, ceilings, door frames) until every such face lies on a cell boundary, then the
/// portals: the parts of shared cell boundaries that no opaque axial face covers, as axial
/// rectangles. Non-axial geometry never occludes here (it only enlarges visibility), so any model
/// subdivides. Cells and portals stated with osgVis::Cell / osgVis::Portal markers (Scene::cells,
/// Scene::portals) are taken as they are instead.
#include <osgVis/core/pvs/CellGraph.h>
#include <osgVis/core/scene/Scene.h>

namespace osgVis::core
{
struct SubdivisionOptions
{
    /// A plane splits a node when the opaque axial faces lying in it cover at least this fraction of
    /// the node's cross-section there (scale-free: a wall splits a building, a door jamb splits the
    /// wall slab it sits in, a desk does not split a room) ...
    double minCoverage = 0.3;
    /// ... or at least this area in world units² (0: coverage alone decides).
    double minFaceArea = 0.0;
    /// No cell thinner than this fraction of the scene's diagonal is made by a split.
    double minCellSize = 1e-4;
    std::uint32_t maxDepth = 40;
    std::uint32_t maxCells = 200000;
};

/// One opaque axial face of the model (both sides opaque unless the source culls faces).
struct OpaqueFace
{
    AxialRect rect;
    ObjectId owner = InvalidObject;
};

/// The opaque axial rectangles of the scene: static, opaque, two-sided geometry (the same
/// eligibility as object-space occluders) merged into convex polygons, of which the axis-aligned
/// rectangles are kept. Everything else is treated as transparent.
std::vector<OpaqueFace> findOpaqueAxialFaces(const Scene& scene);

/// Automatic subdivision of `scene` (or its stated cells/portals when Scene::cells is not empty).
/// Automatic: the root box is the scene's finite bounds grown by 1e-3 of their diagonal (plus a
/// little), split breadth first at the best-covered opaque axial plane (ties: larger area, smaller
/// axis, smaller coordinate); cells are the kd leaves in depth-first order; portals are every shared
/// face minus the opaque faces in its plane (only gaps thinner than ~1e-7 of the diagonal dropped).
/// A scene with nothing of finite bounds gives no cells; one with no opaque axial faces one cell.
/// Stated: cells in Scene::cells order with their names; a portal polygon becomes its bounding
/// rectangle on the face its cells share that is nearest to it (clipped to that face, or the whole
/// face if the clip is empty); cells sharing no face get the polygon's bounding rectangle flattened
/// onto the plane through its centre across its dominant normal axis (low cell: smaller centre on
/// that axis). Portals naming one cell twice or a cell out of range are ignored.
CellGraph subdivideCells(const Scene& scene, const SubdivisionOptions& options = {});
} // namespace osgVis::core
