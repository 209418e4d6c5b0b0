// SPDX-License-Identifier: MIT
// Point and box location in a cell graph: kd-tree descent, taking both children where the query
// comes within tolerance of the split, so points on a shared boundary find every cell they touch.
#include <osgVis/core/pvs/CellGraph.h>

#include <cmath>

namespace osgVis::core
{
namespace
{
Aabb grown(const Aabb& box, double tolerance)
{
    return {box.min - Vec3(tolerance), box.max + Vec3(tolerance)};
}

// Visits the leaves whose half-spaces meet [lo, hi] (within tolerance), low side first, so cells
// come out in ascending order (cells are numbered in that order).
void descend(const CellGraph& graph, std::uint32_t node, const Vec3& lo, const Vec3& hi, double tolerance,
             std::vector<std::uint32_t>& out)
{
    for (;;)
    {
        const CellGraph::KdNode& n = graph.nodes[node];
        if (n.axis > 2)
        {
            const std::uint32_t cell = n.children[0];
            if (cell < graph.cells.size() && grown(graph.cells[cell], tolerance).intersects({lo, hi}))
                out.push_back(cell);
            return;
        }
        const bool low = lo[n.axis] <= n.split + tolerance;
        const bool high = hi[n.axis] >= n.split - tolerance;
        if (low && high)
            descend(graph, n.children[0], lo, hi, tolerance, out);
        if (!low && !high)
            return;
        node = high ? n.children[1] : n.children[0];
    }
}
} // namespace

void CellGraph::locate(const Vec3& p, double tolerance, std::vector<std::uint32_t>& out) const
{
    cellsOverlapping({p, p}, tolerance, out);
}

void CellGraph::cellsOverlapping(const Aabb& box, double tolerance, std::vector<std::uint32_t>& out) const
{
    // note: NaN coordinates would pass every comparison test below; such a query meets no cell.
    if (box.empty() || !std::isfinite(box.min.x + box.min.y + box.min.z + box.max.x + box.max.y + box.max.z))
        return;
    if (!nodes.empty())
    {
        descend(*this, 0, box.min, box.max, tolerance, out);
        return;
    }
    for (std::uint32_t c = 0; c < cells.size(); ++c)
    {
        if (!cells[c].empty() && grown(cells[c], tolerance).intersects(box))
            out.push_back(c);
    }
}
} // namespace osgVis::core
