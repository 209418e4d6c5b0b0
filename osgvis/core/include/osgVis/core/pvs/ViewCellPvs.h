// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Potentially visible sets of view cells without portals: boxes of eye positions, each with the
/// objects visible from anywhere in it (what a multifocal bake produces). A bake may be split into
/// ranges of cells, each written to its own `.pvs` file; mergeViewCellPvs joins them again.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/pvs/CellGraph.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
struct ViewCellPvs
{
    std::uint32_t totalCells = 0;           ///< cells of the whole bake (a range file holds some)
    std::vector<std::uint32_t> cellIndices; ///< absolute index of each cell held, strictly ascending, < totalCells
    std::vector<Aabb> cells;                ///< view cell boxes, parallel to cellIndices (non-empty, finite)
    std::vector<VisibleSet> pvs;            ///< parallel: capacity = object count

    /// Index into `cells` of a cell whose closed box contains p (the first), or NoCell. A scan: view
    /// cells are few, and a range file holds no search structure.
    std::uint32_t locate(const Vec3& p) const;
};
} // namespace osgVis::core
