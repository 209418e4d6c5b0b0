// SPDX-License-Identifier: MIT
#include "VertexWelder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
namespace
{
constexpr std::uint32_t None = ~std::uint32_t(0);
} // namespace

std::size_t VertexWelder::CellKeyHash::operator()(const CellKey& k) const
{
    // Large odd multipliers spread neighbouring cells over the table.
    std::uint64_t h = std::uint64_t(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= std::uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full + (h >> 29);
    h ^= std::uint64_t(k.z) * 0x165667B19E3779F9ull + (h >> 32);
    return std::size_t(h ^ (h >> 31));
}

VertexWelder::VertexWelder(const Vec3& origin, double size, double tolerance)
    : _origin(origin), _tolerance(std::max(tolerance, 0.0))
{
    // note: cells never finer than size·1e-12, so grid coordinates of the scene fit an int64 and
    // stay far from overflow even for a zero tolerance.
    const double floorSize = std::max(size, 1.0) * 1e-12;
    // Cells 16 × the tolerance: a point's tolerance ball leaves its own cell along an axis with
    // probability 1/8, so a new vertex costs about 1.4 cell probes on average.
    _cellSize = std::max(16.0 * _tolerance, floorSize);
}

std::uint32_t VertexWelder::find(const CellKey& key, const Vec3& p, double tolerance) const
{
    const auto it = _firstInCell.find(key);
    if (it == _firstInCell.end())
        return None;
    std::uint32_t best = None;
    for (std::uint32_t v = it->second; v != None; v = _nextInCell[v])
    {
        const Vec3 d = _positions[v] - p;
        if (glm::dot(d, d) <= tolerance * tolerance)
            best = std::min(best, v);
    }
    return best;
}

void VertexWelder::reserve(std::size_t vertices)
{
    _firstInCell.reserve(vertices);
    _nextInCell.reserve(vertices);
    _positions.reserve(vertices);
}

std::uint32_t VertexWelder::weld(const Vec3& p, double tolerance)
{
    tolerance = std::clamp(tolerance, 0.0, _tolerance);
    const Vec3 local = (p - _origin) / _cellSize;
    const CellKey key{std::int64_t(std::floor(local.x)), std::int64_t(std::floor(local.y)),
                      std::int64_t(std::floor(local.z))};

    // Per axis: the own cell, plus the neighbour the tolerance ball reaches into, if any.
    int lo[3], hi[3];
    const double reach = tolerance / _cellSize;
    const double fractions[3] = {local.x - double(key.x), local.y - double(key.y), local.z - double(key.z)};
    for (int axis = 0; axis < 3; ++axis)
    {
        lo[axis] = fractions[axis] < reach ? -1 : 0;
        hi[axis] = 1.0 - fractions[axis] <= reach ? 1 : 0;
    }
    // An exact copy of a vertex that started its own id: nothing earlier was within reach of it.
    if (const auto it = _firstInCell.find(key); it != _firstInCell.end())
    {
        for (std::uint32_t v = it->second; v != None; v = _nextInCell[v])
        {
            if (_positions[v] == p)
                return v;
        }
    }

    std::uint32_t best = None;
    for (int dz = lo[2]; dz <= hi[2]; ++dz)
        for (int dy = lo[1]; dy <= hi[1]; ++dy)
            for (int dx = lo[0]; dx <= hi[0]; ++dx)
                best = std::min(best, find({key.x + dx, key.y + dy, key.z + dz}, p, tolerance));
    if (best != None)
        return best;

    const std::uint32_t id = std::uint32_t(_positions.size());
    _positions.push_back(p);
    auto [it, inserted] = _firstInCell.try_emplace(key, id);
    _nextInCell.push_back(inserted ? None : it->second);
    it->second = id;
    return id;
}
} // namespace osgVis::core
