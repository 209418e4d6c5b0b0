// SPDX-License-Identifier: MIT
#include "CellObjects.h"

namespace osgVis::core
{
CellObjects assignObjectsToCells(const Scene& scene, const CellGraph& graph, double tolerance)
{
    CellObjects out;
    out.perCell.resize(graph.cells.size());
    std::vector<std::uint32_t> cells;
    for (const SceneObject& object : scene.objects)
    {
        const bool judged = !(object.flags & (OBJECT_DYNAMIC | OBJECT_ALWAYS_VISIBLE)) && !object.bounds.empty() &&
                            object.bounds.finite();
        cells.clear();
        if (judged)
            graph.cellsOverlapping(object.bounds, tolerance, cells);
        if (cells.empty())
        {
            out.everywhere.push_back(object.id);
            continue;
        }
        for (std::uint32_t cell : cells)
            out.perCell[cell].push_back(object.id);
    }
    return out;
}

double cellPortalTolerance(const CellGraph& graph)
{
    const double diagonal = graph.bounds.empty() ? 1.0 : glm::length(graph.bounds.extent());
    return 1e-6 * (diagonal > 0.0 ? diagonal : 1.0);
}

Aabb clippedToCell(const Aabb& box, const Aabb& cell, double tolerance)
{
    const Vec3 grow(tolerance);
    return {glm::max(box.min, cell.min - grow), glm::min(box.max, cell.max + grow)};
}
} // namespace osgVis::core
