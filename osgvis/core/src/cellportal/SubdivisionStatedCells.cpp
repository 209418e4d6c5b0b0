// SPDX-License-Identifier: MIT
// Stated cells and portals: the modeller's boxes are the cells; each portal polygon is turned into
// the axial rectangle the run-time and bake expect.
#include "SubdivisionStatedCells.h"

#include "PortalEnumeration.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
namespace
{
// The face the two boxes share whose plane is closest to `centroid`, as a rectangle with lowCell /
// highCell set (0 = a, 1 = b); false when they share no face of positive area.
bool closestSharedFace(const Aabb& a, const Aabb& b, const Vec3& centroid, double tolerance, AxialRect& face,
                       bool& aIsLow)
{
    double best = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis)
    {
        const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
        AxialRect shared;
        shared.axis = std::uint8_t(axis);
        shared.uMin = std::max(a.min[u], b.min[u]);
        shared.uMax = std::min(a.max[u], b.max[u]);
        shared.vMin = std::max(a.min[v], b.min[v]);
        shared.vMax = std::min(a.max[v], b.max[v]);
        if (!(shared.uMax - shared.uMin > tolerance) || !(shared.vMax - shared.vMin > tolerance))
            continue;
        for (int lowIsA = 1; lowIsA >= 0; --lowIsA)
        {
            const Aabb& low = lowIsA ? a : b;
            const Aabb& high = lowIsA ? b : a;
            if (std::abs(low.max[axis] - high.min[axis]) > tolerance)
                continue;
            shared.coordinate = low.max[axis];
            const double distance = std::abs(centroid[axis] - shared.coordinate);
            if (distance < best)
            {
                best = distance;
                face = shared;
                aIsLow = lowIsA != 0;
            }
        }
    }
    return best < std::numeric_limits<double>::infinity();
}
} // namespace

CellGraph statedCellGraph(const Scene& scene, double tolerance)
{
    CellGraph graph;
    for (const Cell& cell : scene.cells)
    {
        graph.cells.push_back(cell.bounds);
        graph.cellNames.push_back(cell.name);
        graph.bounds.expand(cell.bounds);
    }

    const std::uint32_t cellCount = std::uint32_t(graph.cells.size());
    for (const Portal& portal : scene.portals)
    {
        const std::uint32_t a = portal.cellA, b = portal.cellB;
        if (a == b || a >= cellCount || b >= cellCount || portal.polygon.empty())
            continue;
        const Aabb& boxA = graph.cells[a];
        const Aabb& boxB = graph.cells[b];
        Aabb polygonBox;
        for (const Vec3& p : portal.polygon.vertices())
            polygonBox.expand(p);
        if (!polygonBox.finite())
            continue;
        const Vec3 centroid = polygonBox.center();

        AxialRect rect;
        bool aIsLow = true;
        if (closestSharedFace(boxA, boxB, centroid, tolerance, rect, aIsLow))
        {
            const AxialRect clipped = rect.clippedTo(polygonBox);
            // A polygon off the shared face or edge-on to it still says the cells see each other.
            if (!clipped.empty())
                rect = clipped;
        }
        else
        {
            const Vec3 normal = glm::abs(portal.polygon.newellNormal());
            int axis = 0;
            if (normal.x + normal.y + normal.z > 0.0)
                axis = (normal.x >= normal.y && normal.x >= normal.z) ? 0 : (normal.y >= normal.z ? 1 : 2);
            else
            {
                const Vec3 apart = glm::abs(boxB.center() - boxA.center());
                axis = (apart.x >= apart.y && apart.x >= apart.z) ? 0 : (apart.y >= apart.z ? 1 : 2);
            }
            const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
            rect.axis = std::uint8_t(axis);
            rect.coordinate = centroid[axis];
            rect.uMin = polygonBox.min[u];
            rect.uMax = polygonBox.max[u];
            rect.vMin = polygonBox.min[v];
            rect.vMax = polygonBox.max[v];
            aIsLow = !(boxB.center()[axis] < boxA.center()[axis]);
        }
        graph.portals.push_back({rect, aIsLow ? a : b, aIsLow ? b : a});
    }
    indexCellPortals(graph);
    return graph;
}
} // namespace osgVis::core
