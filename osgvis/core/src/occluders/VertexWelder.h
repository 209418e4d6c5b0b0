// SPDX-License-Identifier: MIT
#pragma once
// Joins vertices closer than a tolerance into one id, through a hash grid whose cells are much
// wider than the tolerance, so a query mostly looks at its own cell only.
#include <osgVis/core/geometry/Math.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace osgVis::core
{
class VertexWelder
{
public:
    // `origin` and `size` span the points to come (their bounding box corner and diagonal); they
    // keep the grid coordinates small. A zero tolerance welds exact duplicates only.
    VertexWelder(const Vec3& origin, double size, double tolerance);

    void reserve(std::size_t vertices);

    // Id of the first vertex within the tolerance of `p`, or a new id; ids are dense from 0.
    std::uint32_t weld(const Vec3& p) { return weld(p, _tolerance); }
    // The same with a tighter tolerance (at most the welder's), for points that must not move as
    // far as the welder lets input vertices move.
    std::uint32_t weld(const Vec3& p, double tolerance);
    const std::vector<Vec3>& positions() const { return _positions; }

private:
    struct CellKey
    {
        std::int64_t x, y, z;
        bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct CellKeyHash
    {
        std::size_t operator()(const CellKey& k) const;
    };

    std::uint32_t find(const CellKey& key, const Vec3& p, double tolerance) const;

    Vec3 _origin;
    double _tolerance;
    double _cellSize;
    std::unordered_map<CellKey, std::uint32_t, CellKeyHash> _firstInCell;
    std::vector<std::uint32_t> _nextInCell; // per vertex: the next vertex of its cell, or ~0
    std::vector<Vec3> _positions;
};
} // namespace osgVis::core
