// SPDX-License-Identifier: MIT
// Portal enumeration: neighbours across each cell's upper faces by kd-tree query, then the shared
// rectangle minus the opaque faces lying in its plane (exact grid subtraction).
#include "PortalEnumeration.h"

#include "SubdivisionRectSet.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
// Opaque faces per axis, sorted by coordinate, for the faces lying in one plane.
class FacePlanes
{
public:
    explicit FacePlanes(const std::vector<OpaqueFace>& faces)
    {
        for (const OpaqueFace& f : faces)
            _byAxis[f.rect.axis].push_back(f.rect);
        for (auto& list : _byAxis)
            std::sort(list.begin(), list.end(),
                      [](const AxialRect& a, const AxialRect& b) { return a.coordinate < b.coordinate; });
    }

    // The faces within tolerance of region's plane that overlap it, clipped to it.
    void clippedInPlane(const AxialRect& region, double tolerance, std::vector<AxialRect>& out) const
    {
        out.clear();
        const std::vector<AxialRect>& list = _byAxis[region.axis];
        auto it = std::lower_bound(list.begin(), list.end(), region.coordinate - tolerance,
                                   [](const AxialRect& r, double c) { return r.coordinate < c; });
        for (; it != list.end() && it->coordinate <= region.coordinate + tolerance; ++it)
        {
            const AxialRect r = it->clippedTo(region);
            if (!r.empty())
                out.push_back(r);
        }
    }

private:
    std::vector<AxialRect> _byAxis[3];
};
} // namespace

void enumeratePortals(CellGraph& graph, const std::vector<OpaqueFace>& faces, double tolerance)
{
    graph.portals.clear();
    const FacePlanes planes(faces);
    std::vector<std::uint32_t> across;
    std::vector<AxialRect> holes;
    for (std::uint32_t c = 0; c < graph.cells.size(); ++c)
    {
        const Aabb& cell = graph.cells[c];
        if (cell.empty())
            continue;
        // Each adjacent pair once: from its low cell, across that cell's upper face on each axis.
        for (int axis = 0; axis < 3; ++axis)
        {
            const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
            Aabb face = cell;
            face.min[axis] = cell.max[axis];
            across.clear();
            graph.cellsOverlapping(face, tolerance, across);
            std::sort(across.begin(), across.end());
            for (std::uint32_t d : across)
            {
                const Aabb& other = graph.cells[d];
                if (d == c || std::abs(other.min[axis] - cell.max[axis]) > tolerance)
                    continue;
                AxialRect shared;
                shared.axis = std::uint8_t(axis);
                shared.coordinate = cell.max[axis];
                shared.uMin = std::max(cell.min[u], other.min[u]);
                shared.uMax = std::min(cell.max[u], other.max[u]);
                shared.vMin = std::max(cell.min[v], other.min[v]);
                shared.vMax = std::min(cell.max[v], other.max[v]);
                if (!(shared.uMax - shared.uMin > tolerance) || !(shared.vMax - shared.vMin > tolerance))
                    continue; // they touch along an edge or corner only
                planes.clippedInPlane(shared, tolerance, holes);
                for (const AxialRect& open : subtractRects(shared, holes, tolerance))
                    graph.portals.push_back({open, c, d});
            }
        }
    }
    indexCellPortals(graph);
}

void indexCellPortals(CellGraph& graph)
{
    graph.cellPortals.assign(graph.cells.size(), {});
    for (std::uint32_t p = 0; p < graph.portals.size(); ++p)
    {
        const CellPortal& portal = graph.portals[p];
        graph.cellPortals[portal.lowCell].push_back(p);
        if (portal.highCell != portal.lowCell)
            graph.cellPortals[portal.highCell].push_back(p);
    }
}
} // namespace osgVis::core
