// SPDX-License-Identifier: MIT
#pragma once
// The kd-tree of the automatic subdivisions: split at the planes opaque axial faces cover most.
#include <osgVis/core/cellportal/CellSubdivision.h>

#include <functional>
#include <vector>

namespace osgVis::core
{
struct FaceKdTree
{
    std::vector<CellGraph::KdNode> nodes; ///< node 0 the root; leaves have axis 3
    std::vector<Aabb> nodeBoxes;          ///< per node
};

// The scene's finite bounds grown so an eye at the model's very edge is inside a cell.
Aabb subdivisionRootBox(const Scene& scene);

// Splits `root` breadth first at the plane whose faces cover most of a node's cross-section
// (SubdivisionOptions: coverage, area, size, depth and cell limits) until no plane qualifies.
// `settled`, when given, stops the splitting of a node it accepts (a node inside solid space).
FaceKdTree buildFaceKdTree(const Aabb& root, const std::vector<OpaqueFace>& faces, const SubdivisionOptions& options,
                           double tolerance, const std::function<bool(const Aabb&)>& settled = {});

// Numbers the leaves of graph.nodes in depth-first order, low child first (nearby cells get
// nearby numbers; kd queries report cells in ascending order), appending their boxes to
// graph.cells. With `leafIsCell` (per leaf, in that order) a leaf it rejects names NoCell.
void numberCells(CellGraph& graph, const std::vector<Aabb>& nodeBoxes, const std::vector<bool>* leafIsCell = nullptr);
} // namespace osgVis::core
