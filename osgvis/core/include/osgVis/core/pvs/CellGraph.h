// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The cells of a cell-and-portal subdivision: axis-aligned leaf boxes of a kd-tree (or boxes a
/// modeller stated), the portals joining them, and point location.
#include <osgVis/core/geometry/AxialRect.h>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::core
{
constexpr std::uint32_t NoCell = ~std::uint32_t(0);

/// The transparent part of a boundary shared by two cells, as an axial rectangle. `lowCell` lies on
/// the side of smaller coordinate along rect.axis, `highCell` on the larger side.
struct CellPortal
{
    AxialRect rect;
    std::uint32_t lowCell = NoCell, highCell = NoCell;

    std::uint32_t otherCell(std::uint32_t cell) const { return cell == lowCell ? highCell : lowCell; }
};

struct CellGraph
{
    /// kd-tree node: an inner node splits at `split` along `axis`; children[0] holds coordinates
    /// <= split, children[1] >= split. A leaf (axis == 3) names its cell in children[0].
    struct KdNode
    {
        std::uint8_t axis = 3;
        double split = 0.0;
        std::uint32_t children[2] = {NoCell, NoCell};
    };

    Aabb bounds;                            ///< the subdivided box (scene bounds, slightly enlarged)
    std::vector<Aabb> cells;                ///< leaf cells, disjoint interiors
    std::vector<std::string> cellNames;     ///< empty, or one name per cell (cells stated by markers)
    std::vector<CellPortal> portals;
    std::vector<std::vector<std::uint32_t>> cellPortals; ///< per cell: indices into `portals`
    std::vector<KdNode> nodes;              ///< node 0 is the root; empty for stated cells

    /// Appends to `out` every cell whose closed box, grown by `tolerance`, contains p (several near
    /// a boundary; none outside every cell). Uses the kd-tree when there is one, else scans.
    void locate(const Vec3& p, double tolerance, std::vector<std::uint32_t>& out) const;
    /// Appends to `out` every cell whose closed box meets `box` grown by `tolerance`.
    void cellsOverlapping(const Aabb& box, double tolerance, std::vector<std::uint32_t>& out) const;
};
} // namespace osgVis::core
