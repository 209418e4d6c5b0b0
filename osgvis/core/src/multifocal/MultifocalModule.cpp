// SPDX-License-Identifier: MIT
// Marsden & Guibas, "The multifocal z-buffer", §6: the PVS of a view volume used for every eye in
// it (their first model, with cells made on demand instead of in a bake).
#include <osgVis/core/multifocal/MultifocalModule.h>

#include "BoxCover.h"

#include <osgVis/core/module/BakedDataStore.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <cmath>
#include <list>
#include <map>
#include <tuple>

namespace osgVis::core
{
namespace
{
using CellKey = std::tuple<long long, long long, long long>;

struct CellAnswer
{
    VisibleSet objects;
    double nearReach = 0.0; ///< the near-plane reach it assumed
};
} // namespace

void registerBakedViewCells(std::shared_ptr<const BakedViewCells> cells)
{
    if (!cells)
        return;
    const std::uint64_t fingerprint = cells->fingerprint; // read before the move below
    BakedDataStore<BakedViewCells>::instance().put(fingerprint, std::move(cells));
}

std::shared_ptr<const BakedViewCells> findBakedViewCells(std::uint64_t fingerprint)
{
    return BakedDataStore<BakedViewCells>::instance().find(fingerprint);
}

struct MultifocalModule::Impl
{
    MultifocalModuleOptions options;
    std::vector<OccluderPolygon> occluders;
    Vec3 cellSize{1.0};
    std::list<CellKey> recent; ///< most recent first
    std::map<CellKey, std::pair<CellAnswer, std::list<CellKey>::iterator>> cells;
    std::size_t computed = 0;
    std::shared_ptr<const BakedViewCells> given; ///< by whoever holds the model (setBakedData)
    std::shared_ptr<const BakedViewCells> baked;
    std::size_t outsideBaked = 0;
};

MultifocalModule::MultifocalModule(const MultifocalModuleOptions& options) : _impl(std::make_unique<Impl>())
{
    _impl->options = options;
}

MultifocalModule::~MultifocalModule() = default;

void MultifocalModule::setBakedData(const BakedData& baked)
{
    _impl->given = baked.get<BakedViewCells>();
}

void MultifocalModule::setScene(const Scene& scene)
{
    _scene = &scene;
    _impl->occluders = volumeOccluders(scene);
    const std::uint64_t fingerprint = sceneFingerprint(scene);
    const auto fits = [&](const std::shared_ptr<const BakedViewCells>& cells)
    { return cells && cells->fingerprint == fingerprint && cells->objectCount == scene.objects.size(); };
    _impl->baked = fits(_impl->given) ? _impl->given : findBakedViewCells(fingerprint);
    if (_impl->baked && _impl->baked->objectCount != scene.objects.size())
        _impl->baked.reset();
    _impl->outsideBaked = 0;
    _impl->cells.clear();
    _impl->recent.clear();
    const Aabb bounds = scene.bounds();
    const double diagonal = bounds.empty() ? 1.0 : std::max(glm::length(bounds.extent()), 1e-6);
    for (int a = 0; a < 3; ++a)
        _impl->cellSize[a] = _impl->options.cellSize[a] > 0.0 ? _impl->options.cellSize[a] : diagonal / 100.0;
}

Aabb MultifocalModule::cellOf(const Vec3& eye) const
{
    const Vec3& size = _impl->cellSize;
    const Vec3& origin = _impl->options.cellOrigin;
    const Vec3 lo = origin + glm::floor((eye - origin) / size) * size;
    return Aabb(lo, lo + size);
}

std::size_t MultifocalModule::cellsComputed() const
{
    return _impl->computed;
}

std::shared_ptr<const BakedViewCells> MultifocalModule::bakedCells() const
{
    return _impl->baked;
}

std::size_t MultifocalModule::viewsOutsideBakedCells() const
{
    return _impl->outsideBaked;
}

void MultifocalModule::cull(const View& view, VisibleSet& visible)
{
    if (!_scene || view.orthographic || !std::isfinite(view.eye.x + view.eye.y + view.eye.z))
        return;
    Impl& m = *_impl;
    if (m.baked)
    {
        const std::uint32_t cell = m.baked->cells.locate(view.eye);
        if (cell == NoCell || nearPlaneReach(view) > m.baked->nearDistance)
            ++m.outsideBaked;
        else
            visible.intersectWith(m.baked->cells.pvs[cell]);
        return;
    }
    const Vec3 index = glm::floor((view.eye - m.options.cellOrigin) / m.cellSize);
    const CellKey key{(long long)index.x, (long long)index.y, (long long)index.z};
    const double reach = nearPlaneReach(view);
    auto found = m.cells.find(key);
    if (found != m.cells.end() && found->second.first.nearReach < reach)
    {
        m.recent.erase(found->second.second);
        m.cells.erase(found);
        found = m.cells.end();
    }
    if (found == m.cells.end())
    {
        MultifocalOptions volume = m.options.volume;
        volume.nearDistance = std::max(volume.nearDistance, reach);
        CellAnswer answer{computeVolumePvs(*_scene, m.occluders, cellOf(view.eye), volume).objects, volume.nearDistance};
        ++m.computed;
        if (m.cells.size() >= std::max<std::size_t>(1, m.options.cachedCells))
        {
            m.cells.erase(m.recent.back());
            m.recent.pop_back();
        }
        m.recent.push_front(key);
        found = m.cells.emplace(key, std::make_pair(std::move(answer), m.recent.begin())).first;
    }
    else if (found->second.second != m.recent.begin())
        m.recent.splice(m.recent.begin(), m.recent, found->second.second);
    visible.intersectWith(found->second.first.objects);
}

void MultifocalModule::cullRegion(const ViewRegion& region, VisibleSet& visible)
{
    cullRegionPass(region, visible, regionPasses() - 1);
}

void MultifocalModule::cullRegionPass(const ViewRegion& region, VisibleSet& visible, std::uint32_t pass)
{
    const Vec3 lo = region.eyes.min, hi = region.eyes.max;
    if (!_scene || region.eyes.empty() || !std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z))
        return;
    // A region inside baked cells takes the union of their PVS at once: each holds for every eye
    // in its cell, and every eye of the region lies in one of them.
    if (const auto& baked = _impl->baked; baked && region.maxNearReach <= baked->nearDistance)
    {
        std::vector<Aabb> boxes;
        std::vector<std::size_t> overlapping;
        for (std::size_t i = 0; i < baked->cells.cells.size(); ++i)
            if (baked->cells.cells[i].intersects(region.eyes))
            {
                boxes.push_back(baked->cells.cells[i]);
                overlapping.push_back(i);
            }
        if (!boxes.empty() && boxes.size() <= 27 && boxCoveredBy(region.eyes, boxes))
        {
            VisibleSet any(visible.capacity());
            for (std::size_t i : overlapping)
                for (ObjectId id : baked->cells.pvs[i].ids())
                    if (id < any.capacity())
                        any.set(id);
            visible.intersectWith(any);
            return;
        }
    }
    MultifocalOptions volume = _impl->options.volume;
    volume.nearDistance = std::max(volume.nearDistance, region.maxNearReach);
    if (pass == 0)
    {
        volume.planesPerDirection = std::min(volume.planesPerDirection, 3);
        volume.triangles = false;
        volume.maxOccludersPerPlane = std::min<std::uint32_t>(volume.maxOccludersPerPlane, 2000);
    }
    visible.intersectWith(computeVolumePvs(*_scene, _impl->occluders, region.eyes, volume).objects);
}
} // namespace osgVis::core
