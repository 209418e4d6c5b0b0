// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Baking volume PVS for view cells (Marsden & Guibas, §6, first model): the cells (a grid over a
/// box, or the grid cells a walk passes through) and each cell's PVS by computeVolumePvs, in
/// parallel. A cell's answer depends only on the scene, the options and the cell, never on the
/// thread count or on which other cells are baked with it, so ranges baked apart merge into the
/// same result.
#include <osgVis/core/multifocal/VolumeVisibility.h>

#include <functional>
#include <vector>

namespace osgVis::core
{
/// Cells of edge `cellSize` covering `box` (the last row/column/layer may reach past it), x
/// fastest, then y, then z. Throws std::invalid_argument for an empty or non-finite box or a cell
/// size that is not positive and finite.
std::vector<Aabb> gridViewCells(const Aabb& box, const Vec3& cellSize);
/// The cells of the grid through `origin` with edge `cellSize` that hold one of `eyes` (closed
/// boxes: an eye on a boundary gives both cells), each once, in the grid's z, y, x order.
std::vector<Aabb> viewCellsAlong(const std::vector<Vec3>& eyes, const Vec3& cellSize, const Vec3& origin);

struct ViewCellBake
{
    std::vector<VisibleSet> pvs;              ///< one per cell baked
    std::vector<VolumeStatistics> statistics; ///< parallel
};

/// The PVS of cells [first, end) of `cells`. `progress(done, total)` is called from one thread at
/// a time as cells finish. Occluders are built once from the scene (buildOccluderPolygons).
ViewCellBake bakeViewCells(const Scene& scene, const std::vector<Aabb>& cells, std::size_t first, std::size_t end,
                           const MultifocalOptions& options,
                           const std::function<void(std::size_t, std::size_t)>& progress = {});
/// The same with the occluders built once by the caller (volumeOccluders(scene)), for a caller that
/// bakes many ranges of one scene.
ViewCellBake bakeViewCells(const Scene& scene, const std::vector<OccluderPolygon>& occluders,
                           const std::vector<Aabb>& cells, std::size_t first, std::size_t end,
                           const MultifocalOptions& options,
                           const std::function<void(std::size_t, std::size_t)>& progress = {});
/// A guess of each cell's bake cost, to hand out the dearest first: the objects whose centres lie
/// in the cell's neighbourhood (bins of four cell diagonals, the bin and its 26 neighbours), where
/// occluders near the cell cover most and the z-buffer work concentrates.
std::vector<double> viewCellCostEstimates(const Scene& scene, const std::vector<Aabb>& cells);
} // namespace osgVis::core
