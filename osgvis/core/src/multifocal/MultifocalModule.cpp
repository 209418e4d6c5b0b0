// SPDX-License-Identifier: MIT
// Marsden & Guibas, "The multifocal z-buffer", §6: the PVS of a view volume used for every eye in
// it (their first model, with cells made on demand instead of in a bake).
#include <osgVis/core/multifocal/MultifocalModule.h>

#include "BoxCover.h"

#include <osgVis/core/module/BakedDataStore.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <map>
#include <optional>
#include <tuple>

namespace osgVis::core
{
namespace
{
using CellKey = std::tuple<long long, long long, long long>;

// A cell is computed for near planes down to this fraction of the view's (the factor AsyncVisibility's
// regions take), so that a near plane that shrinks as the eye nears geometry (OSG computes it every
// frame) has the cell computed again only once it has halved.
constexpr double NearPlaneSlack = 0.5;

struct CellAnswer
{
    VisibleSet objects;
    MultifocalOptions computed; ///< the views it holds for: near-plane reach, nearest near plane, depth bits
};

// The volume options for views of near-plane reach `reach`, near plane at `nearest` (0: unknown)
// and `bits` of depth: the module's, narrowed to those views.
MultifocalOptions servedOptions(const MultifocalOptions& module, double reach, double nearest, std::uint32_t bits)
{
    MultifocalOptions options = module;
    options.nearDistance = std::max(module.nearDistance, reach);
    options.minNearDistance = module.minNearDistance > 0.0 ? std::min(module.minNearDistance, nearest) : nearest;
    options.depthBits = std::min(module.depthBits, bits);
    return options;
}

MultifocalOptions servedOptions(const MultifocalOptions& module, const View& view)
{
    return servedOptions(module, nearPlaneReach(view), nearDistance(view), view.depthBits);
}

MultifocalOptions servedOptions(const MultifocalOptions& module, const ViewRegion& region)
{
    return servedOptions(module, region.maxNearReach, region.minNearDistance, region.depthBits);
}

// What a bake assumed (osgvispvs: its near-plane reach, the default nearest plane and depth bits).
MultifocalOptions bakedOptions(const BakedViewCells& baked)
{
    MultifocalOptions options;
    options.nearDistance = baked.nearDistance;
    return options;
}

// What a cell's new answer is computed for: the views `wanted` serves, with the slack above, and
// every view the cell's last answer held for (a view alternating with another keeps one answer).
MultifocalOptions widened(MultifocalOptions wanted, const std::optional<MultifocalOptions>& last)
{
    double nearest = nearestNearPlane(wanted);
    if (last)
    {
        wanted.nearDistance = std::max(wanted.nearDistance, last->nearDistance);
        wanted.depthBits = std::min(wanted.depthBits, last->depthBits);
        nearest = std::min(nearest, nearestNearPlane(*last));
    }
    wanted.minNearDistance = NearPlaneSlack * nearest;
    return wanted;
}

// True when an answer computed with `computed` holds for the views `wanted` serves: it used no
// occluder their near plane could clip, and its depth margin is at least theirs.
bool holdsFor(const MultifocalOptions& computed, const MultifocalOptions& wanted)
{
    return wanted.nearDistance <= computed.nearDistance &&
           depthGapPerDistance2(wanted) <= depthGapPerDistance2(computed);
}
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
    const MultifocalOptions wanted = servedOptions(m.options.volume, view);
    if (m.baked)
    {
        const std::uint32_t cell = m.baked->cells.locate(view.eye);
        if (cell == NoCell || !holdsFor(bakedOptions(*m.baked), wanted))
            ++m.outsideBaked;
        else
            visible.intersectWith(m.baked->cells.pvs[cell]);
        return;
    }
    const Vec3 index = glm::floor((view.eye - m.options.cellOrigin) / m.cellSize);
    const CellKey key{(long long)index.x, (long long)index.y, (long long)index.z};
    auto found = m.cells.find(key);
    // An answer for a nearer reach may hold occluders this view clips; one for a farther near plane
    // (or more depth bits) has too fine a depth margin: the cell is computed again.
    std::optional<MultifocalOptions> last;
    if (found != m.cells.end() && !holdsFor(found->second.first.computed, wanted))
    {
        last = found->second.first.computed;
        m.recent.erase(found->second.second);
        m.cells.erase(found);
        found = m.cells.end();
    }
    if (found == m.cells.end())
    {
        const MultifocalOptions volume = widened(wanted, last);
        CellAnswer answer{computeVolumePvs(*_scene, m.occluders, cellOf(view.eye), volume).objects, volume};
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
    MultifocalOptions volume = servedOptions(_impl->options.volume, region);
    if (const auto& baked = _impl->baked; baked && holdsFor(bakedOptions(*baked), volume))
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
    if (pass == 0)
    {
        volume.planesPerDirection = std::min(volume.planesPerDirection, 3);
        volume.triangles = false;
        volume.maxOccludersPerPlane = std::min<std::uint32_t>(volume.maxOccludersPerPlane, 2000);
    }
    visible.intersectWith(computeVolumePvs(*_scene, _impl->occluders, region.eyes, volume).objects);
}
} // namespace osgVis::core
