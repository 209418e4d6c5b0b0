// SPDX-License-Identifier: MIT
#include <osgVis/core/session/CullSession.h>

#include <osgVis/core/api/ModuleRegistry.h>

namespace osgVis::core
{
CullSession::CullSession(const SessionOptions& options)
    : _chain(createChain(options.modes)), _backOff(options.backOff)
{
    _chain.setBakedData(options.baked);
    if (options.async && _chain.supportsRegions())
        _async = std::make_unique<AsyncVisibility>(options.modes, options.asyncOptions, options.baked);
}

CullSession::~CullSession()
{
    _async.reset();
}

void CullSession::setScene(std::shared_ptr<const Scene> scene)
{
    _chain.setScene(*scene);
    if (_async)
        _async->setScene(scene);
    _scene = std::move(scene);
}

void CullSession::sceneReplaced(std::shared_ptr<const Scene> scene, const std::vector<SceneChange>& changes)
{
    _chain.sceneReplaced(*scene, changes);
    if (_async)
        _async->sceneReplaced(scene, changes);
    _scene = std::move(scene);
}

void CullSession::sceneChanged(const SceneChange& change)
{
    _chain.sceneChanged(change);
}

void CullSession::setDebugRecord(DebugRecord* record)
{
    if (record == _record)
        return;
    for (std::size_t stage = 0; stage < _chain.size(); ++stage)
        _chain.module(stage).setDebugRecord(record);
    _record = record;
}

const VisibleSet& CullSession::cull(const View& view, std::chrono::steady_clock::time_point start)
{
    SessionFigures& figures = _figures;
    figures = {};
    figures.async = _async != nullptr;
    // Do no harm, on synchronous sessions that record nothing: the interval since the last cull is
    // the previous frame's time, with or without the chain.
    figures.backOff = !_async && !_record && _backOff.enabled();
    const bool useChain =
        !figures.backOff || _backOff.useChain(std::chrono::duration<double>(start - _previousCull).count());
    _previousCull = start;
    if (!useChain)
    {
        figures.backedOff = true;
        _visible.reset(_scene ? _scene->objects.size() : 0, true);
    }
    // A debug record describes the chain's own decisions: recording sessions cull synchronously.
    else if (!_async || _record || !_async->cull(view, _visible))
    {
        figures.asyncFallback = figures.async;
        _chain.cull(view, _visible);
    }
    return _visible;
}
} // namespace osgVis::core
