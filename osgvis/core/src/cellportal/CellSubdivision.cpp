// SPDX-License-Identifier: MIT
// Automatic cell subdivision after Teller & Séquin, "Visibility Preprocessing for Interactive
// Walkthroughs" (SIGGRAPH '91): a kd-tree over the scene box split along the planes that opaque
// axial faces cover most (union of the faces in the node's cross-section over its area), breadth
// first so a cell budget spreads evenly; leaves are the cells, then the portals between them.
#include <osgVis/core/cellportal/CellSubdivision.h>

#include "FaceKdTree.h"
#include "PortalEnumeration.h"
#include "SubdivisionStatedCells.h"
#include "SubdivisionTolerance.h"


namespace osgVis::core
{
namespace
{
CellGraph automaticCellGraph(const Scene& scene, const SubdivisionOptions& options)
{
    CellGraph graph;
    graph.bounds = subdivisionRootBox(scene);
    if (graph.bounds.empty())
        return graph; // nothing with finite bounds: no cell to stand in
    const double tolerance = subdivisionTolerance(graph.bounds);
    const std::vector<OpaqueFace> faces = findOpaqueAxialFaces(scene);
    FaceKdTree tree = buildFaceKdTree(graph.bounds, faces, options, tolerance);
    graph.nodes = std::move(tree.nodes);
    numberCells(graph, tree.nodeBoxes);
    enumeratePortals(graph, faces, tolerance);
    return graph;
}
} // namespace

CellGraph subdivideCells(const Scene& scene, const SubdivisionOptions& options)
{
    if (!scene.cells.empty())
    {
        Aabb statedBounds;
        for (const Cell& cell : scene.cells)
            statedBounds.expand(cell.bounds);
        return statedCellGraph(scene, subdivisionTolerance(statedBounds));
    }
    if (options.fromSolids)
        return subdivideSolidCells(scene, options, nullptr);
    return automaticCellGraph(scene, options);
}
} // namespace osgVis::core
