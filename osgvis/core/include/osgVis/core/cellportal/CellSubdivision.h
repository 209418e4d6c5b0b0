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
    /// Cells from the solid space the model states (Scene::solids; docs/cellportal.md, "Solid
    /// space") instead of its opaque axial faces: the kd-tree splits at the faces of solid boxes,
    /// cells are the leaves sightlines can reach, portals the faces between them no opaque face of
    /// a solid closes; every face plane of a solid may split (minCoverage and minFaceArea only
    /// apply to faces), the cell-size, depth and cell limits apply. Off: the faces decide.
    bool fromSolids = false;
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

/// What the subdivision from solid space found, for `osgvispvs --explain` and the docs' tables.
struct SolidSubdivisionReport
{
    std::size_t solidBoxes = 0, eyePoints = 0, unproven = 0; ///< what the scene stated
    std::size_t leaves = 0;        ///< kd leaves
    std::size_t solidLeaves = 0;   ///< inside a solid box
    std::size_t mixedLeaves = 0;   ///< partly solid, no split worth making: open
    std::size_t eyeSpaceLeaves = 0; ///< open, enclosed, connected to an eye point: faces trusted
    std::size_t outsideLeaves = 0; ///< open but connected to the bounds' outside or to no eye point
    std::size_t reachedSolidLeaves = 0; ///< solid leaves a sightline from eye space may enter (cells)
    std::size_t unreachedOpenLeaves = 0; ///< open leaves no sightline from eye space reaches (no cell)
    std::size_t closedFaces = 0;   ///< leaf faces closed by an opaque face of a solid
    std::size_t cells = 0, portals = 0;
};

/// The subdivision from solid space (what subdivideCells does with SubdivisionOptions::fromSolids
/// and no stated cells), reporting what it found.
CellGraph subdivideSolidCells(const Scene& scene, const SubdivisionOptions& options, SolidSubdivisionReport* report);
} // namespace osgVis::core
