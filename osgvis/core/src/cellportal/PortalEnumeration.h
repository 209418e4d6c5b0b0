// SPDX-License-Identifier: MIT
#pragma once
// Portals of a cell graph: for every pair of face-adjacent cells, the part of their shared
// rectangle that no opaque axial face in that plane covers, as disjoint axial rectangles.
#include <osgVis/core/cellportal/CellSubdivision.h>

namespace osgVis::core
{
// Replaces graph.portals and graph.cellPortals. Pairs come in order of the low cell, then the axis,
// then the high cell; a pair's rectangles in (vMin, uMin) order. Faces within `tolerance` of a shared plane count
// as lying in it; uncovered parts thinner than `tolerance` are dropped, nothing wider.
void enumeratePortals(CellGraph& graph, const std::vector<OpaqueFace>& faces, double tolerance);

// Fills graph.cellPortals from graph.portals (each cell's portals in ascending order).
void indexCellPortals(CellGraph& graph);
} // namespace osgVis::core
