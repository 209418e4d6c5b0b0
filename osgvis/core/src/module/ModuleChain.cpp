// SPDX-License-Identifier: MIT
#include <osgVis/core/module/ModuleChain.h>

#include <algorithm>
#include <chrono>

namespace osgVis::core
{
void ModuleChain::add(std::unique_ptr<VisibilityModule> module)
{
    if (_baked)
        module->setBakedData(*_baked);
    if (_scene)
        module->setScene(*_scene);
    _modules.push_back(std::move(module));
}

void ModuleChain::setBakedData(std::shared_ptr<const BakedData> baked)
{
    _baked = std::move(baked);
    const BakedData none;
    for (const auto& module : _modules)
        module->setBakedData(_baked ? *_baked : none);
}

std::string ModuleChain::name() const
{
    std::string result;
    for (const auto& m : _modules)
    {
        if (!result.empty())
            result += ',';
        result += m->name();
    }
    return result;
}

bool ModuleChain::approximate() const
{
    for (const auto& m : _modules)
    {
        if (m->approximate())
            return true;
    }
    return false;
}

void ModuleChain::setScene(const Scene& scene)
{
    _scene = &scene;
    _removed.assign(scene.objects.size(), false);
    for (auto& m : _modules)
        m->setScene(scene);
}

void ModuleChain::rememberRemoved(const SceneChange& change)
{
    _removed.resize(_scene->objects.size(), false);
    for (ObjectId id : change.objects)
    {
        if (id >= _removed.size())
            continue;
        if (change.kind == SceneChange::Kind::Removed)
            _removed[id] = true;
        else if (change.kind == SceneChange::Kind::Inserted)
            _removed[id] = false;
    }
}

void ModuleChain::sceneChanged(const SceneChange& change)
{
    if (!_scene)
        return;
    rememberRemoved(change);
    for (auto& m : _modules)
        m->sceneChanged(change);
}

void ModuleChain::sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes)
{
    if (!_scene)
    {
        setScene(scene);
        return;
    }
    _scene = &scene;
    for (const SceneChange& change : changes)
        rememberRemoved(change);
    _removed.resize(scene.objects.size(), false);
    for (auto& m : _modules)
        m->sceneReplaced(scene, changes);
}

template <class Refine> void ModuleChain::runStages(VisibleSet& visible, const Frustum* frustum, Refine refine)
{
    using Clock = std::chrono::steady_clock;
    if (!_scene)
    {
        visible.reset(0);
        _timings.clear();
        return;
    }
    const std::vector<SceneObject>& objects = _scene->objects;
    visible.reset(objects.size(), true);
    for (std::size_t id = 0; id < _removed.size() && id < objects.size(); ++id)
    {
        if (_removed[id])
            visible.clear(static_cast<ObjectId>(id));
    }

    _timings.resize(_modules.size());
    for (std::size_t i = 0; i < _modules.size(); ++i)
    {
        const Clock::time_point start = Clock::now();
        refine(*_modules[i]);
        const Clock::time_point end = Clock::now();
        StageTiming& t = _timings[i];
        t.module = _modules[i]->name();
        t.milliseconds = std::chrono::duration<double, std::milli>(end - start).count();
        t.visibleAfter = visible.count();
    }

    const bool judgedSlivers = !_modules.empty() && std::all_of(_modules.begin(), _modules.end(),
                                                                [](const auto& m) { return m->judgesSlivers(); });
    const std::uint32_t sliverFlag = judgedSlivers ? 0u : std::uint32_t(OBJECT_SLIVERS);
    for (const SceneObject& o : objects)
    {
        const bool removed = o.id < _removed.size() && _removed[o.id];
        if (removed || o.id >= objects.size())
            continue;
        // note: a sliver's pixels may take any depth, and an unoccludable object passes its depth
        // test wherever it lies, so no occluder hides either; the frustum still does (regions have
        // no single frustum: kept)
        const bool occlusionProof =
            (o.flags & (sliverFlag | OBJECT_UNOCCLUDABLE)) && (!frustum || frustum->classify(o.bounds) != Containment::Outside);
        if ((o.flags & OBJECT_ALWAYS_VISIBLE) || occlusionProof)
            visible.set(o.id);
    }
}

void ModuleChain::cull(const View& view, VisibleSet& visible)
{
    runStages(visible, &view.frustum, [&](VisibilityModule& module) { module.cull(view, visible); });
}

bool ModuleChain::supportsRegions() const
{
    if (_modules.empty())
        return false;
    for (const auto& m : _modules)
    {
        if (!m->supportsRegions())
            return false;
    }
    return true;
}

void ModuleChain::cullRegion(const ViewRegion& region, VisibleSet& visible)
{
    runStages(visible, nullptr, [&](VisibilityModule& module) { module.cullRegion(region, visible); });
}

std::uint32_t ModuleChain::regionPasses() const
{
    std::uint32_t passes = 1;
    for (const auto& m : _modules)
        passes = std::max(passes, m->regionPasses());
    return passes;
}

void ModuleChain::cullRegionPass(const ViewRegion& region, VisibleSet& visible, std::uint32_t pass)
{
    runStages(visible, nullptr,
              [&](VisibilityModule& module)
              {
                  const std::uint32_t last = std::max<std::uint32_t>(module.regionPasses(), 1) - 1;
                  module.cullRegionPass(region, visible, std::min(pass, last));
              });
}
} // namespace osgVis::core
