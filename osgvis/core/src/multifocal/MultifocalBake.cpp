// SPDX-License-Identifier: MIT
// Marsden & Guibas, "The multifocal z-buffer", §6: a PVS per view volume, baked ahead of time.
#include <osgVis/core/multifocal/MultifocalBake.h>

#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

namespace osgVis::core
{
namespace
{
bool finite(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void checkCellSize(const Vec3& cellSize)
{
    if (!finite(cellSize) || !(cellSize.x > 0.0 && cellSize.y > 0.0 && cellSize.z > 0.0))
        throw std::invalid_argument("view cells need a positive, finite size");
}
} // namespace

std::vector<Aabb> gridViewCells(const Aabb& box, const Vec3& cellSize)
{
    checkCellSize(cellSize);
    if (box.empty() || !finite(box.min) || !finite(box.max))
        throw std::invalid_argument("the box to cover with view cells is empty or not finite");
    const Vec3 counts = glm::max(glm::ceil(box.extent() / cellSize), Vec3(1.0));
    if (counts.x * counts.y * counts.z > 1e7)
        throw std::invalid_argument("more than ten million view cells: use larger cells");
    std::vector<Aabb> cells;
    for (int k = 0; k < int(counts.z); ++k)
        for (int j = 0; j < int(counts.y); ++j)
            for (int i = 0; i < int(counts.x); ++i)
            {
                const Vec3 lo = box.min + Vec3(i, j, k) * cellSize;
                cells.emplace_back(lo, lo + cellSize);
            }
    return cells;
}

std::vector<Aabb> viewCellsAlong(const std::vector<Vec3>& eyes, const Vec3& cellSize, const Vec3& origin)
{
    checkCellSize(cellSize);
    std::map<std::tuple<long long, long long, long long>, Aabb> cells; // ordered z, y, x
    for (const Vec3& eye : eyes)
    {
        if (!finite(eye))
            continue;
        const Vec3 at = (eye - origin) / cellSize;
        const Vec3 lo = glm::floor(at);
        // An eye on a cell boundary lies in the closed cells on both sides.
        for (int k = 0; k < 8; ++k)
        {
            Vec3 index = lo;
            bool valid = true;
            for (int a = 0; a < 3; ++a)
                if (k & (1 << a))
                {
                    valid = valid && at[a] == lo[a];
                    index[a] -= 1.0;
                }
            if (!valid)
                continue;
            const Vec3 cellLo = origin + index * cellSize;
            cells.emplace(std::make_tuple((long long)index.z, (long long)index.y, (long long)index.x),
                          Aabb(cellLo, cellLo + cellSize));
        }
    }
    std::vector<Aabb> out;
    for (const auto& entry : cells)
        out.push_back(entry.second);
    return out;
}

ViewCellBake bakeViewCells(const Scene& scene, const std::vector<Aabb>& cells, std::size_t first, std::size_t end,
                           const MultifocalOptions& options, const std::function<void(std::size_t, std::size_t)>& progress)
{
    return bakeViewCells(scene, volumeOccluders(scene), cells, first, end, options, progress);
}

ViewCellBake bakeViewCells(const Scene& scene, const std::vector<OccluderPolygon>& occluders,
                           const std::vector<Aabb>& cells, std::size_t first, std::size_t end,
                           const MultifocalOptions& options, const std::function<void(std::size_t, std::size_t)>& progress)
{
    if (first > end || end > cells.size())
        throw std::invalid_argument("bakeViewCells: cell range out of bounds");
    ViewCellBake bake;
    const std::size_t count = end - first;
    bake.pvs.resize(count);
    bake.statistics.resize(count);
    std::mutex report;
    std::size_t done = 0;
    tbb::parallel_for(std::size_t(0), count,
                      [&](std::size_t i)
                      {
                          VolumePvs pvs = computeVolumePvs(scene, occluders, cells[first + i], options);
                          bake.pvs[i] = std::move(pvs.objects);
                          bake.statistics[i] = pvs.statistics;
                          std::lock_guard<std::mutex> lock(report);
                          ++done;
                          if (progress)
                              progress(done, count);
                      });
    return bake;
}

std::vector<double> viewCellCostEstimates(const Scene& scene, const std::vector<Aabb>& cells)
{
    std::vector<double> costs(cells.size(), 1.0);
    if (cells.empty())
        return costs;
    double diagonal = 0.0;
    for (const Aabb& cell : cells)
        diagonal = std::max(diagonal, glm::length(cell.extent()));
    const double bin = 4.0 * std::max(diagonal, 1e-9);
    using Key = std::tuple<long long, long long, long long>;
    const auto keyOf = [bin](const Vec3& p) {
        return Key{(long long)std::floor(p.x / bin), (long long)std::floor(p.y / bin), (long long)std::floor(p.z / bin)};
    };
    std::map<Key, double> objectsPerBin;
    for (const SceneObject& object : scene.objects)
        if (!object.bounds.empty())
            objectsPerBin[keyOf(object.bounds.center())] += 1.0;
    for (std::size_t c = 0; c < cells.size(); ++c)
    {
        const auto [x, y, z] = keyOf(cells[c].center());
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz)
                    if (const auto found = objectsPerBin.find(Key{x + dx, y + dy, z + dz}); found != objectsPerBin.end())
                        costs[c] += found->second;
    }
    return costs;
}
} // namespace osgVis::core
