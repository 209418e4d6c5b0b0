// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Asynchronous visibility: a worker thread computes, with its own module chain, the visible set of
/// a region of viewpoints (ViewRegion: a box of eyes along the eye's predicted path, every
/// direction); the cull thread only intersects a region's answer with its view frustum, for as long
/// as the eye stays inside the region. It predicts the eye from its last step and asks for the next
/// region while the current one still holds, so the answer is usually ready before the eye gets
/// there. When no region holds a view (a turn the prediction missed, a jump, a new scene) cull()
/// says so and the caller culls that frame itself: a stale answer is never used. A chain with
/// progressive region answers (VisibilityModule::regionPasses) publishes each pass as it finishes,
/// so the cull thread has a first answer early and uses the best finished one; a new request stops
/// the refinement of the old region.
///
/// Threads: one worker per object. cull(), setScene() and sceneReplaced() belong to one thread at
/// a time (the view's cull thread); statistics() may be called from anywhere.
#include <osgVis/core/module/ModuleChain.h>
#include <osgVis/core/scene/ViewRegion.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace osgVis::core
{
struct AsyncOptions
{
    std::uint32_t lookAheadFrames = 4; ///< a region covers the path the eye takes in this many frames
    double slack = 0.0;                ///< grows a region's box every way (world units); 0: 1/10000 of the scene's diagonal
    /// When positive (every component): a region is at least this box (a bake cell's size), centred
    /// half the look-ahead path ahead of the eye, so it lasts while the eye crosses it.
    Vec3 regionSize{0.0};
};

struct AsyncStatistics
{
    std::uint64_t regionsComputed = 0; ///< by the worker
    std::uint64_t answered = 0;        ///< cull() calls answered from a region
    std::uint64_t missed = 0;          ///< cull() calls no region held (the caller culled itself)
    double lastRegionMs = 0.0;         ///< worker time of the latest region
    std::size_t lastRegionObjects = 0; ///< objects in the latest region's answer
    std::uint64_t refinedAnswers = 0;  ///< answers replaced by a later pass of the same region
    double lastFirstPassMs = 0.0;      ///< worker time to the first (fastest) pass of the latest region
};

class AsyncVisibility
{
public:
    /// `modes` as createChain takes them (throws UnknownModeError), given the model's `baked` data
    /// (ModuleChain::setBakedData). Starts the worker thread.
    explicit AsyncVisibility(const std::string& modes, const AsyncOptions& options = {},
                             std::shared_ptr<const BakedData> baked = nullptr);
    /// Stops the worker, after the region or scene update it is busy with.
    ~AsyncVisibility();
    AsyncVisibility(const AsyncVisibility&) = delete;
    AsyncVisibility& operator=(const AsyncVisibility&) = delete;

    /// The chain answers region queries (else cull() always answers false).
    bool supported() const { return _supported; }

    /// Scene updates, applied by the worker in order. Regions of earlier scenes stop holding at
    /// once. The pointer keeps the scene alive while the worker uses it.
    void setScene(std::shared_ptr<const Scene> scene);
    void sceneReplaced(std::shared_ptr<const Scene> scene, std::vector<SceneChange> changes);

    /// True: `visible` is the answer of a region computed for the current scene that holds `view`,
    /// less objects wholly outside the view frustum (plus always-visible ones). False: no region
    /// holds the view; `visible` is untouched. Never waits for the worker.
    bool cull(const View& view, VisibleSet& visible);

    AsyncStatistics statistics() const;
    /// The union of the finished region answers for the current scene (the region the eye stands in
    /// and the one asked for ahead of it), every direction, no frustum cut: what the eye may see over
    /// its next frames, for a prefetch. False, `visible` untouched, when none is finished. Cull thread.
    bool regionsAhead(VisibleSet& visible) const;

    /// Blocks until the worker has nothing queued or running (tests and tools; never the cull thread).
    void waitIdle();

private:
    struct Answer
    {
        ViewRegion region;
        std::shared_ptr<const Scene> scene;
        std::vector<ObjectId> objects;
    };
    struct SceneJob
    {
        std::shared_ptr<const Scene> scene;
        bool replaced = false;
        std::vector<SceneChange> changes;
    };
    struct Request
    {
        ViewRegion region;
        std::shared_ptr<const Scene> scene;
    };

    void run();
    void request(const View& view);
    ViewRegion regionAhead(const View& view) const;

    AsyncOptions _options;
    bool _supported = false;

    /// Cull-thread state.
    std::shared_ptr<const Scene> _scene;
    double _slack = 0.0, _maxPath = 0.0;
    std::optional<Vec3> _lastEye;
    Vec3 _step{0.0};                      ///< the eye's latest move per frame
    std::optional<ViewRegion> _requested; ///< the latest region asked for

    /// Shared with the worker.
    mutable std::mutex _mutex;
    std::condition_variable _wake, _idle;
    std::deque<SceneJob> _sceneJobs;
    std::optional<Request> _pending;
    std::vector<std::shared_ptr<const Answer>> _answers; ///< newest first, at most two
    bool _busy = false, _stop = false;
    AsyncStatistics _statistics;

    /// Worker-only.
    ModuleChain _chain;
    std::shared_ptr<const Scene> _workerScene;
    std::thread _worker;
};
} // namespace osgVis::core
