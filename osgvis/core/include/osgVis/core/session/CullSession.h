// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// One view's culling, whatever the renderer (issue 46): the chain its modes name, the asynchronous
/// worker and the do-no-harm back-off when asked for, the debug record, the visible set and the
/// figures of the latest cull. The OSG adapter keeps one per view, the C interface one per context:
/// both get async and back-off from here. Extraction, paging and statistics are the caller's steps
/// before and after cull().
///
/// Threads: one thread at a time (the view's cull thread); the async worker is the session's own.
#include <osgVis/core/async/AsyncVisibility.h>
#include <osgVis/core/module/BackOff.h>
#include <osgVis/core/module/ModuleChain.h>
#include <osgVis/core/scene/DebugRecord.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace osgVis::core
{
struct SessionOptions
{
    std::string modes = "frustum"; ///< as createChain takes them
    /// Data baked for the model, handed to the chain and the worker's (ModuleChain::setBakedData).
    std::shared_ptr<const BakedData> baked;
    /// Asynchronous visibility (AsyncVisibility), used when the chain answers regions.
    bool async = false;
    AsyncOptions asyncOptions;
    /// Do no harm (BackOff), on synchronous frames that record nothing; off unless enabled.
    BackOffOptions backOff = [] {
        BackOffOptions off;
        off.enabled = false;
        return off;
    }();
};

/// How the latest cull was answered.
struct SessionFigures
{
    bool async = false;         ///< the session has a worker
    bool asyncFallback = false; ///< …but no region held the view: the chain culled
    bool backOff = false;       ///< back-off was on for this frame
    bool backedOff = false;     ///< …and the frame skipped the chain: every object let through
};

class CullSession
{
public:
    /// Throws UnknownModeError for unknown modes.
    explicit CullSession(const SessionOptions& options = {});
    ~CullSession();
    CullSession(const CullSession&) = delete;
    CullSession& operator=(const CullSession&) = delete;

    /// A scene with new ids. The pointer keeps it alive while the worker uses it; without a worker
    /// the caller may own the scene and hand a non-owning pointer.
    void setScene(std::shared_ptr<const Scene> scene);
    /// `scene` replaces the one held, ids kept, with `changes` from it.
    void sceneReplaced(std::shared_ptr<const Scene> scene, const std::vector<SceneChange>& changes);
    /// Changes made in place to the scene held (synchronous sessions only: a worker needs a new
    /// scene through sceneReplaced).
    void sceneChanged(const SceneChange& change);
    const Scene* scene() const { return _scene.get(); }

    /// Every stage describes its queries into `record` from the next cull on (nullptr: none); a
    /// recording session culls synchronously, with its chain.
    void setDebugRecord(DebugRecord* record);

    /// The visible set of `view`, culled at `start` (back-off times frames by the interval between
    /// calls): every object on a backed-off frame, else the worker's region answer, else the chain's.
    const VisibleSet& cull(const View& view, std::chrono::steady_clock::time_point start);
    const VisibleSet& visible() const { return _visible; }
    /// For the caller's steps after the cull, which may take objects out (paging defers some).
    VisibleSet& visible() { return _visible; }
    const SessionFigures& figures() const { return _figures; }

    ModuleChain& chain() { return _chain; }
    AsyncVisibility* async() { return _async.get(); }
    const BackOff& backOff() const { return _backOff; }

private:
    ModuleChain _chain;
    std::shared_ptr<const Scene> _scene;
    // note: destroyed first (its worker joined) while the scene it may still read is held
    std::unique_ptr<AsyncVisibility> _async;
    BackOff _backOff;
    DebugRecord* _record = nullptr;
    VisibleSet _visible;
    SessionFigures _figures;
    std::chrono::steady_clock::time_point _previousCull{};
};
} // namespace osgVis::core
