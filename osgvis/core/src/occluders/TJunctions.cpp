// SPDX-License-Identifier: MIT
// T-junction repair of occluder regions: where a vertex of one region lies on an edge of another
// (a BSP compiler's split face, a wall meeting a floor cut in two), the edge gets that vertex, so
// the two regions share an edge the fusion of connected occluders (octree, docs/octree.md) and
// the mask's rasterizer groups (docs/mask.md) can use.
#include "OccluderRegion.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace osgVis::core
{
namespace
{
std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b)
{
    return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

// Welded vertices by grid cell, for the ones near a segment.
class VertexGrid
{
public:
    VertexGrid(const std::vector<Vec3>& positions, const std::vector<std::uint32_t>& ids, const Aabb& bounds)
        : _positions(positions), _origin(bounds.min)
    {
        const double size = std::max(glm::length(bounds.extent()), 1e-30);
        _cell = std::max(size / std::max(1.0, std::cbrt(double(ids.size()))), size * 1e-6);
        for (std::uint32_t id : ids)
            _cells[key(cellOf(positions[id]))].push_back(id);
    }

    // Ids within the cells a segment from a to b (widened by one cell) passes through.
    template <class Visit> void near(const Vec3& a, const Vec3& b, Visit visit)
    {
        _visited.clear();
        const double length = glm::length(b - a);
        const int steps = int(std::min(4096.0, std::ceil(2.0 * length / _cell))) + 1;
        for (int s = 0; s <= steps; ++s)
        {
            const glm::ivec3 c = cellOf(a + (b - a) * (double(s) / steps));
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                    {
                        const std::uint64_t k = key(c + glm::ivec3(dx, dy, dz));
                        if (!_visited.insert(k).second)
                            continue;
                        const auto it = _cells.find(k);
                        if (it != _cells.end())
                            for (std::uint32_t id : it->second)
                                visit(id);
                    }
        }
    }

private:
    glm::ivec3 cellOf(const Vec3& p) const
    {
        const Vec3 local = glm::clamp((p - _origin) / _cell, Vec3(-1.0), Vec3(1 << 20));
        return glm::ivec3(std::floor(local.x), std::floor(local.y), std::floor(local.z));
    }
    static std::uint64_t key(const glm::ivec3& c)
    {
        const auto part = [](int v) { return std::uint64_t(std::uint32_t(v + 2) & 0x1FFFFFu); };
        return (part(c.x) << 42) | (part(c.y) << 21) | part(c.z);
    }

    const std::vector<Vec3>& _positions;
    Vec3 _origin;
    double _cell = 1.0;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> _cells;
    std::unordered_set<std::uint64_t> _visited;
};
} // namespace

void repairTJunctions(std::vector<OccluderRegion>& regions, const std::vector<Vec3>& positions, double sceneSize)
{
    std::unordered_map<std::uint64_t, std::uint32_t> edgeUses;
    std::vector<std::uint32_t> used;
    Aabb bounds;
    for (const OccluderRegion& region : regions)
        for (std::size_t i = 0; i < region.loop.size(); ++i)
        {
            ++edgeUses[edgeKey(region.loop[i], region.loop[(i + 1) % region.loop.size()])];
            used.push_back(region.loop[i]);
            bounds.expand(positions[region.loop[i]]);
        }
    if (used.empty())
        return;
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    VertexGrid grid(positions, used, bounds);

    std::vector<std::pair<double, std::uint32_t>> onEdge;
    std::vector<std::uint32_t> repaired;
    for (OccluderRegion& region : regions)
    {
        const std::size_t n = region.loop.size();
        repaired.clear();
        bool changed = false;
        for (std::size_t i = 0; i < n; ++i)
        {
            const std::uint32_t ia = region.loop[i], ib = region.loop[(i + 1) % n];
            repaired.push_back(ia);
            if (edgeUses[edgeKey(ia, ib)] >= 2)
                continue; // already shared whole
            const Vec3 &a = positions[ia], &b = positions[ib];
            const double length = glm::length(b - a);
            if (!(length > 0.0))
                continue;
            const Vec3 d = (b - a) / length;
            // On the edge: within 1e-10 of its length (below what the occlusion tests resolve, so
            // the loop stays convex to them), and clear of the ends.
            const double offLine = 1e-10 * length;
            const double clear = std::max(1e-6 * length, 1e-9 * sceneSize);
            onEdge.clear();
            grid.near(a, b,
                      [&](std::uint32_t id)
                      {
                          if (id == ia || id == ib ||
                              std::find(region.loop.begin(), region.loop.end(), id) != region.loop.end())
                              return;
                          const Vec3 w = positions[id] - a;
                          const double t = glm::dot(w, d);
                          if (t <= clear || t >= length - clear)
                              return;
                          if (glm::length(w - t * d) <= offLine)
                              onEdge.push_back({t, id});
                      });
            if (onEdge.empty())
                continue;
            std::sort(onEdge.begin(), onEdge.end());
            for (const auto& [t, id] : onEdge)
                if (repaired.back() != id)
                    repaired.push_back(id);
            changed = true;
        }
        if (changed)
            region.loop = repaired;
    }
}
} // namespace osgVis::core
