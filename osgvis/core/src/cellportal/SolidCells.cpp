// SPDX-License-Identifier: MIT
// Cells and portals from the solid space a model proves (docs/cellportal.md, "Solid space"). The
// kd-tree of Teller & Séquin, "Visibility Preprocessing for Interactive Walkthroughs" (SIGGRAPH
// '91), §3, split at the faces of solid boxes instead of at drawn faces; then, as a level
// compiler's outside fill does (q3map2's flood from the entities), open space is told apart by
// what it connects to, and a flood finds every leaf a sightline may enter. Only those are cells;
// a face between two cells is a portal unless an opaque face of a solid closes it.
#include <osgVis/core/cellportal/CellSubdivision.h>

#include "FaceKdTree.h"
#include "PortalEnumeration.h"
#include "SubdivisionTolerance.h"

#include <algorithm>
#include <deque>
#include <numeric>

namespace osgVis::core
{
namespace
{
enum class LeafKind : std::uint8_t
{
    Solid, // inside a solid box
    Mixed, // partly solid, not split further: open, and no face in it is trusted
    Open,
};

// The six faces of every solid box (clipped to the root), the planes the kd-tree splits at.
std::vector<OpaqueFace> solidBoxFaces(const std::vector<Aabb>& boxes)
{
    std::vector<OpaqueFace> faces;
    for (std::uint32_t b = 0; b < boxes.size(); ++b)
    {
        const Aabb& box = boxes[b];
        for (int axis = 0; axis < 3; ++axis)
        {
            const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
            for (const double coordinate : {box.min[axis], box.max[axis]})
            {
                AxialRect rect;
                rect.axis = std::uint8_t(axis);
                rect.coordinate = coordinate;
                rect.uMin = box.min[u];
                rect.uMax = box.max[u];
                rect.vMin = box.min[v];
                rect.vMax = box.max[v];
                faces.push_back({rect, b});
            }
        }
    }
    return faces;
}

// Every kd leaf as a cell, with the faces between them as portals: the adjacency the flood walks.
struct Leaves
{
    CellGraph graph;
    std::vector<LeafKind> kind;
    std::vector<std::vector<std::uint32_t>> containing; // solid boxes holding a Solid leaf
};

bool contains(const Aabb& outer, const Aabb& inner, double tolerance)
{
    for (int a = 0; a < 3; ++a)
        if (outer.min[a] > inner.min[a] + tolerance || outer.max[a] < inner.max[a] - tolerance)
            return false;
    return true;
}

bool interiorsMeet(const Aabb& a, const Aabb& b, double tolerance)
{
    for (int i = 0; i < 3; ++i)
        if (!(a.min[i] < b.max[i] - tolerance && b.min[i] < a.max[i] - tolerance))
            return false;
    return true;
}

void classifyLeaves(Leaves& leaves, const std::vector<Aabb>& boxes, double tolerance)
{
    const std::size_t count = leaves.graph.cells.size();
    leaves.kind.assign(count, LeafKind::Open);
    leaves.containing.assign(count, {});
    std::vector<bool> meetsSolid(count, false);
    std::vector<std::uint32_t> found;
    for (std::uint32_t b = 0; b < boxes.size(); ++b)
    {
        found.clear();
        leaves.graph.cellsOverlapping(boxes[b], 0.0, found);
        for (std::uint32_t leaf : found)
        {
            const Aabb& box = leaves.graph.cells[leaf];
            if (contains(boxes[b], box, tolerance))
                leaves.containing[leaf].push_back(b);
            else if (interiorsMeet(boxes[b], box, tolerance))
                meetsSolid[leaf] = true;
        }
    }
    for (std::size_t leaf = 0; leaf < count; ++leaf)
        leaves.kind[leaf] = !leaves.containing[leaf].empty() ? LeafKind::Solid
                            : meetsSolid[leaf]                ? LeafKind::Mixed
                                                              : LeafKind::Open;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x)
{
    while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
    return x;
}

// Per leaf: open space connected (through open leaves) to an eye point and not to the
// outside of the root box. Only there does a level compiler keep the faces of solids. A partly
// solid leaf, or one an unproven solid meets, is never eye space and joins nothing: a solid there
// may seal a pocket no eye reaches, whose faces the compiler drops as it drops the outside's
// (q3map2 fills every space its entities do not reach), and the boxes alone would count the pocket
// as reachable through it.
std::vector<bool> eyeSpace(const Leaves& leaves, const SolidSpace& solids, double tolerance)
{
    const CellGraph& graph = leaves.graph;
    const std::size_t count = graph.cells.size();
    std::vector<bool> joins(count);
    std::vector<std::uint32_t> found;
    for (std::uint32_t leaf = 0; leaf < count; ++leaf)
        joins[leaf] = leaves.kind[leaf] == LeafKind::Open;
    for (const Aabb& unproven : solids.unproven)
    {
        found.clear();
        graph.cellsOverlapping(unproven, 0.0, found);
        for (std::uint32_t leaf : found)
            if (interiorsMeet(unproven, graph.cells[leaf], tolerance))
                joins[leaf] = false;
    }
    std::vector<std::uint32_t> parent(count);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const CellPortal& p : graph.portals)
        if (joins[p.lowCell] && joins[p.highCell])
            parent[findRoot(parent, p.lowCell)] = findRoot(parent, p.highCell);

    std::vector<bool> outside(count, false), seeded(count, false);
    for (std::uint32_t leaf = 0; leaf < count; ++leaf)
    {
        const Aabb& box = graph.cells[leaf];
        bool boundary = false;
        for (int a = 0; a < 3; ++a)
            boundary = boundary || box.min[a] <= graph.bounds.min[a] + tolerance ||
                       box.max[a] >= graph.bounds.max[a] - tolerance;
        if (boundary && joins[leaf])
            outside[findRoot(parent, leaf)] = true;
    }
    std::vector<std::uint32_t> at;
    for (const Vec3& eye : solids.eyePoints)
    {
        at.clear();
        graph.locate(eye, tolerance, at);
        for (std::uint32_t leaf : at)
            if (joins[leaf])
                seeded[findRoot(parent, leaf)] = true;
    }
    std::vector<bool> result(count, false);
    for (std::uint32_t leaf = 0; leaf < count; ++leaf)
    {
        const std::uint32_t root = findRoot(parent, leaf);
        result[leaf] = leaves.kind[leaf] == LeafKind::Open && joins[leaf] && seeded[root] && !outside[root];
    }
    return result;
}

// Whether an opaque face of a solid closes `portal`: it joins an eye-space leaf to a solid leaf,
// every solid box holding that leaf has its face there drawn opaque, and no unproven solid meets it.
bool closedFace(const CellPortal& portal, const Leaves& leaves, const std::vector<bool>& eyes,
                const std::vector<SolidBox>& boxes, const std::vector<Aabb>& clipped, const SolidSpace& solids,
                double tolerance)
{
    const std::uint32_t low = portal.lowCell, high = portal.highCell;
    std::uint32_t solid, open;
    if (leaves.kind[low] == LeafKind::Solid && eyes[high])
        solid = low, open = high;
    else if (leaves.kind[high] == LeafKind::Solid && eyes[low])
        solid = high, open = low;
    else
        return false;
    const int axis = portal.rect.axis;
    const bool openAbove = open == high; // the solid's high face looks at the open leaf
    for (std::uint32_t b : leaves.containing[solid])
    {
        const double faceAt = openAbove ? clipped[b].max[axis] : clipped[b].min[axis];
        const bool onFace = std::abs(faceAt - portal.rect.coordinate) <= tolerance;
        if (!onFace || !(boxes[b].opaqueFaces & (1u << (2 * axis + (openAbove ? 1 : 0)))))
            return false;
    }
    Aabb face;
    face.min[axis] = face.max[axis] = portal.rect.coordinate;
    const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
    face.min[u] = portal.rect.uMin;
    face.max[u] = portal.rect.uMax;
    face.min[v] = portal.rect.vMin;
    face.max[v] = portal.rect.vMax;
    face.min -= Vec3(tolerance);
    face.max += Vec3(tolerance);
    for (const Aabb& unproven : solids.unproven)
        if (unproven.intersects(face))
            return false;
    return true;
}

// The solid boxes clipped to the root, those with an interior left, and their SolidBox entries.
void clipSolidBoxes(const std::vector<SolidBox>& boxes, const Aabb& root, double tolerance, std::vector<Aabb>& clipped,
                    std::vector<SolidBox>& kept)
{
    for (const SolidBox& solid : boxes)
    {
        const Aabb box{glm::max(solid.box.min, root.min), glm::min(solid.box.max, root.max)};
        if (box.finite() && interiorsMeet(box, box, tolerance))
        {
            clipped.push_back(box);
            kept.push_back(solid);
        }
    }
}

// The kd-tree split at the faces of the clipped boxes; its leaves become leaves.graph's cells, with
// the faces between them as portals. Returns the tree, whose nodes the final graph reuses.
FaceKdTree splitAtSolidFaces(Leaves& leaves, const std::vector<Aabb>& clipped, const SubdivisionOptions& options,
                             double tolerance)
{
    const Aabb& root = leaves.graph.bounds;
    // Every face plane may split (coverage only orders the splits: large walls first), until a
    // node lies in one solid box or holds no face of one.
    SubdivisionOptions splitting = options;
    splitting.minCoverage = 0.0;
    splitting.minFaceArea = 0.0;
    const auto insideSolid = [&](const Aabb& node)
    { return std::any_of(clipped.begin(), clipped.end(), [&](const Aabb& box) { return contains(box, node, tolerance); }); };
    FaceKdTree tree = buildFaceKdTree(root, solidBoxFaces(clipped), splitting, tolerance, insideSolid);
    leaves.graph.nodes = tree.nodes;
    numberCells(leaves.graph, tree.nodeBoxes);
    enumeratePortals(leaves.graph, {}, tolerance);
    return tree;
}

// Per leaf: reached from the seeds through faces not `closed`. The seeds are the eye-space leaves,
// or without any every leaf not solid.
std::vector<bool> flood(const Leaves& leaves, const std::vector<bool>& eyes, const std::vector<bool>& closed)
{
    const std::size_t count = leaves.graph.cells.size();
    const bool anyEyeSpace = std::find(eyes.begin(), eyes.end(), true) != eyes.end();
    std::vector<bool> reached(count);
    std::deque<std::uint32_t> queue;
    for (std::uint32_t leaf = 0; leaf < count; ++leaf)
        if ((reached[leaf] = anyEyeSpace ? bool(eyes[leaf]) : leaves.kind[leaf] != LeafKind::Solid))
            queue.push_back(leaf);
    while (!queue.empty())
    {
        const std::uint32_t leaf = queue.front();
        queue.pop_front();
        for (std::uint32_t p : leaves.graph.cellPortals[leaf])
        {
            const std::uint32_t next = leaves.graph.portals[p].otherCell(leaf);
            if (!reached[next] && !closed[p])
            {
                reached[next] = true;
                queue.push_back(next);
            }
        }
    }
    return reached;
}

// The cells: the reached leaves, renumbered, with the open faces between them as portals.
CellGraph reachedCells(const Aabb& root, FaceKdTree& tree, const CellGraph& leafGraph, const std::vector<bool>& closed,
                       const std::vector<bool>& reached)
{
    const std::size_t count = leafGraph.cells.size();
    CellGraph graph;
    graph.bounds = root;
    graph.nodes = std::move(tree.nodes);
    numberCells(graph, tree.nodeBoxes, &reached);
    std::vector<std::uint32_t> cellOf(count, NoCell);
    for (std::uint32_t leaf = 0, cell = 0; leaf < count; ++leaf)
        if (reached[leaf])
            cellOf[leaf] = cell++;
    for (std::size_t p = 0; p < closed.size(); ++p)
    {
        const CellPortal& portal = leafGraph.portals[p];
        if (!closed[p] && reached[portal.lowCell] && reached[portal.highCell])
            graph.portals.push_back({portal.rect, cellOf[portal.lowCell], cellOf[portal.highCell]});
    }
    indexCellPortals(graph);
    return graph;
}

// The leaf and face counts of the report.
void countLeaves(const Leaves& leaves, const std::vector<bool>& eyes, const std::vector<bool>& closed,
                 const std::vector<bool>& reached, SolidSubdivisionReport& found)
{
    for (std::size_t p = 0; p < closed.size(); ++p)
        found.closedFaces += closed[p] ? 1 : 0;
    const std::size_t count = leaves.graph.cells.size();
    found.leaves = count;
    for (std::uint32_t leaf = 0; leaf < count; ++leaf)
    {
        const LeafKind kind = leaves.kind[leaf];
        found.solidLeaves += kind == LeafKind::Solid;
        found.mixedLeaves += kind == LeafKind::Mixed;
        found.eyeSpaceLeaves += eyes[leaf];
        found.outsideLeaves += kind == LeafKind::Open && !eyes[leaf];
        found.reachedSolidLeaves += kind == LeafKind::Solid && reached[leaf];
        found.unreachedOpenLeaves += kind != LeafKind::Solid && !reached[leaf];
    }
}
} // namespace

CellGraph subdivideSolidCells(const Scene& scene, const SubdivisionOptions& options, SolidSubdivisionReport* report)
{
    SolidSubdivisionReport found;
    const SolidSpace& solids = scene.solids;
    found.solidBoxes = solids.boxes.size();
    found.eyePoints = solids.eyePoints.size();
    found.unproven = solids.unproven.size();

    Leaves leaves;
    leaves.graph.bounds = subdivisionRootBox(scene);
    const Aabb& root = leaves.graph.bounds;
    if (root.empty())
    {
        if (report)
            *report = found;
        return {};
    }
    const double tolerance = subdivisionTolerance(root);
    std::vector<Aabb> clipped; // the boxes inside the root (no cell lies outside it)
    std::vector<SolidBox> kept;
    clipSolidBoxes(solids.boxes, root, tolerance, clipped, kept);
    FaceKdTree tree = splitAtSolidFaces(leaves, clipped, options, tolerance);
    classifyLeaves(leaves, clipped, tolerance);
    const std::vector<bool> eyes = eyeSpace(leaves, solids, tolerance);

    // The flood: every leaf a sightline from eye space may reach, through any face no opaque face
    // of a solid closes. Only those are cells; an eye anywhere else is in no cell and keeps
    // everything. Without eye space (no eye point stated) every open leaf is a seed.
    std::vector<bool> closed(leaves.graph.portals.size());
    for (std::size_t p = 0; p < closed.size(); ++p)
        closed[p] = closedFace(leaves.graph.portals[p], leaves, eyes, kept, clipped, solids, tolerance);
    const std::vector<bool> reached = flood(leaves, eyes, closed);

    CellGraph graph = reachedCells(root, tree, leaves.graph, closed, reached);
    countLeaves(leaves, eyes, closed, reached, found);
    found.cells = graph.cells.size();
    found.portals = graph.portals.size();
    if (report)
        *report = found;
    return graph;
}
} // namespace osgVis::core
