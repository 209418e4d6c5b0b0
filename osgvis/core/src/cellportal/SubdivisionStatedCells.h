// SPDX-License-Identifier: MIT
#pragma once
// Cells and portals a modeller stated with osgVis::Cell / osgVis::Portal markers, as a cell graph.
#include <osgVis/core/cellportal/CellSubdivision.h>

namespace osgVis::core
{
// One cell per Scene::cells entry (same order, names kept), no kd-tree. Each stated portal becomes
// the bounding rectangle of its polygon on the face its two cells share (of several shared faces,
// the one whose plane is closest to the centre of the polygon's bounding box), clipped to that
// face; when the clipped rectangle has no area the whole shared face is the portal. Cells that share no face get
// the polygon's bounding rectangle flattened onto the plane through its box centre normal to its
// dominant normal axis (for a degenerate polygon, the axis joining the cell centres the most); the
// cell with the smaller centre there is the low cell. Portals naming one cell twice, a cell out of
// range, or with no vertices are ignored.
CellGraph statedCellGraph(const Scene& scene, double tolerance);
} // namespace osgVis::core
