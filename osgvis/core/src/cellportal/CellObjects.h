// SPDX-License-Identifier: MIT
#pragma once
// Which objects each cell holds: an object is incident on every cell its bounds meet. Objects that
// precomputed visibility may not judge (dynamic, unknown bounds, outside every cell) are listed as
// kept everywhere.
#include <osgVis/core/pvs/CellGraph.h>
#include <osgVis/core/scene/Scene.h>

#include <vector>

namespace osgVis::core
{
struct CellObjects
{
    std::vector<std::vector<ObjectId>> perCell;
    std::vector<ObjectId> everywhere;
};

CellObjects assignObjectsToCells(const Scene& scene, const CellGraph& graph, double tolerance);

// Geometric tolerance of cell-portal tests for a graph (world units): a millionth of its diagonal.
double cellPortalTolerance(const CellGraph& graph);

// The part of `box` inside `cell`, both grown by `tolerance` (objects straddle cells).
Aabb clippedToCell(const Aabb& box, const Aabb& cell, double tolerance);
} // namespace osgVis::core
