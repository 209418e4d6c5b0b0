// SPDX-License-Identifier: MIT
#include <osgVis/core/async/AsyncVisibility.h>

#include <osgVis/core/api/ModuleRegistry.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace osgVis::core
{
namespace
{
// A region's near-plane bounds leave room for a camera whose near/far the renderer recomputes.
constexpr double NearDistanceFactor = 0.5, NearReachFactor = 2.0;
// The longest predicted path a region covers, as a fraction of the scene's diagonal: a jump of the
// eye is not a velocity.
constexpr double MaxPathFraction = 0.05;
constexpr std::size_t KeptAnswers = 2;
} // namespace

AsyncVisibility::AsyncVisibility(const std::string& modes, const AsyncOptions& options,
                                 std::shared_ptr<const BakedData> baked)
    : _options(options), _chain(createChain(modes))
{
    _chain.setBakedData(std::move(baked));
    _supported = _chain.supportsRegions();
    if (_options.lookAheadFrames == 0)
        _options.lookAheadFrames = 1;
    _worker = std::thread([this] { run(); });
}

AsyncVisibility::~AsyncVisibility()
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _stop = true;
    }
    _wake.notify_all();
    _worker.join();
}

void AsyncVisibility::setScene(std::shared_ptr<const Scene> scene)
{
    _scene = scene;
    _requested.reset();
    _lastEye.reset();
    const Aabb bounds = scene ? scene->bounds() : Aabb();
    const double diagonal = bounds.empty() || !bounds.finite() ? 1.0 : std::max(glm::length(bounds.extent()), 1e-9);
    _slack = _options.slack > 0.0 ? _options.slack : 1e-4 * diagonal;
    _maxPath = MaxPathFraction * diagonal;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _sceneJobs.push_back({std::move(scene), false, {}});
        _pending.reset();
    }
    _wake.notify_all();
}

void AsyncVisibility::sceneReplaced(std::shared_ptr<const Scene> scene, std::vector<SceneChange> changes)
{
    _scene = scene;
    _requested.reset();
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _sceneJobs.push_back({std::move(scene), true, std::move(changes)});
        _pending.reset();
    }
    _wake.notify_all();
}

// The box the eye sweeps in the next lookAheadFrames frames at its latest step, grown by the slack
// (and by a quarter step, for a path that bends a little).
ViewRegion AsyncVisibility::regionAhead(const View& view) const
{
    Vec3 path = _step * double(_options.lookAheadFrames);
    const double length = glm::length(path);
    if (!(length <= _maxPath))
        path = Vec3(0.0);
    const Vec3 grow(_slack + 0.25 * std::min(glm::length(_step), _maxPath));
    ViewRegion region;
    region.eyes = Aabb(glm::min(view.eye, view.eye + path) - grow, glm::max(view.eye, view.eye + path) + grow);
    const Vec3& size = _options.regionSize;
    if (size.x > 0.0 && size.y > 0.0 && size.z > 0.0)
    {
        const Vec3 centre = view.eye + 0.5 * path;
        region.eyes.expand(Aabb(centre - 0.5 * size, centre + 0.5 * size));
    }
    region.minNearDistance = NearDistanceFactor * nearDistance(view);
    region.maxNearReach = NearReachFactor * nearPlaneReach(view);
    region.depthBits = view.depthBits;
    return region;
}

void AsyncVisibility::request(const View& view)
{
    const ViewRegion region = regionAhead(view);
    _requested = region;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _pending = Request{region, _scene}; // replaces a request the worker has not started
    }
    _wake.notify_all();
}

bool AsyncVisibility::cull(const View& view, VisibleSet& visible)
{
    if (!_supported || !_scene || view.orthographic || !std::isfinite(view.eye.x) || !std::isfinite(view.eye.y) ||
        !std::isfinite(view.eye.z))
        return false;
    _step = _lastEye ? view.eye - *_lastEye : Vec3(0.0);
    _lastEye = view.eye;

    std::shared_ptr<const Answer> answer;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        for (const std::shared_ptr<const Answer>& candidate : _answers)
            if (candidate->scene == _scene && candidate->region.holds(view))
            {
                answer = candidate;
                break;
            }
        ++(answer ? _statistics.answered : _statistics.missed);
    }

    // Ask for the next region once the eye, half the look-ahead on, would leave the last one asked
    // for: the worker then has the other half to finish it.
    const Vec3 predicted = view.eye + _step * (0.5 * double(_options.lookAheadFrames));
    if (!_requested || !_requested->eyes.contains(predicted) || !_requested->holds(view))
        request(view);

    if (!answer)
        return false;
    const std::vector<SceneObject>& objects = answer->scene->objects;
    visible.reset(objects.size());
    for (const ObjectId id : answer->objects)
    {
        const SceneObject& object = objects[id];
        if ((object.flags & OBJECT_ALWAYS_VISIBLE) || view.frustum.classify(object.bounds) != Containment::Outside)
            visible.set(id);
    }
    return true;
}

bool AsyncVisibility::regionsAhead(VisibleSet& visible) const
{
    if (!_scene)
        return false;
    std::vector<std::shared_ptr<const Answer>> answers;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        for (const std::shared_ptr<const Answer>& answer : _answers)
            if (answer->scene == _scene)
                answers.push_back(answer);
    }
    if (answers.empty())
        return false;
    visible.reset(_scene->objects.size());
    for (const std::shared_ptr<const Answer>& answer : answers)
        for (const ObjectId id : answer->objects)
            visible.set(id);
    return true;
}

AsyncStatistics AsyncVisibility::statistics() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _statistics;
}

void AsyncVisibility::waitIdle()
{
    std::unique_lock<std::mutex> lock(_mutex);
    _idle.wait(lock, [&] { return _stop || (!_busy && _sceneJobs.empty() && !_pending); });
}

void AsyncVisibility::run()
{
    using Clock = std::chrono::steady_clock;
    VisibleSet scratch;
    std::unique_lock<std::mutex> lock(_mutex);
    for (;;)
    {
        _idle.notify_all();
        _wake.wait(lock, [&] { return _stop || !_sceneJobs.empty() || _pending; });
        if (_stop)
            return;
        _busy = true;
        if (!_sceneJobs.empty())
        {
            SceneJob job = std::move(_sceneJobs.front());
            _sceneJobs.pop_front();
            _answers.clear();
            lock.unlock();
            // The previous scene stays alive until its modules have moved to the new one.
            const std::shared_ptr<const Scene> previous = _workerScene;
            if (job.scene && job.replaced && previous)
                _chain.sceneReplaced(*job.scene, job.changes);
            else if (job.scene)
                _chain.setScene(*job.scene);
            _workerScene = job.scene;
            lock.lock();
            _busy = false;
            continue;
        }
        Request next = std::move(*_pending);
        _pending.reset();
        if (!_supported || !next.scene || next.scene != _workerScene)
        {
            _busy = false;
            continue; // asked for a scene the worker no longer (or not yet) has
        }
        lock.unlock();
        const Clock::time_point start = Clock::now();
        const std::uint32_t passes = _chain.regionPasses();
        for (std::uint32_t pass = 0; pass < passes; ++pass)
        {
            _chain.cullRegionPass(next.region, scratch, pass);
            auto answer = std::make_shared<Answer>();
            answer->region = next.region;
            answer->scene = next.scene;
            answer->objects = scratch.ids();
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            lock.lock();
            if (pass == 0)
            {
                _statistics.regionsComputed++;
                _statistics.lastFirstPassMs = ms;
            }
            _statistics.lastRegionMs = ms;
            _statistics.lastRegionObjects = answer->objects.size();
            // A later pass replaces the earlier answer of its region; a scene job queued meanwhile
            // makes this answer useless, and the cull side ignores it anyway.
            const auto sameRegion = std::find_if(_answers.begin(), _answers.end(),
                                                 [&](const std::shared_ptr<const Answer>& a)
                                                 { return pass > 0 && a->scene == answer->scene && a->region.eyes.min == answer->region.eyes.min &&
                                                          a->region.eyes.max == answer->region.eyes.max; });
            if (sameRegion != _answers.end())
            {
                _answers.erase(sameRegion);
                _statistics.refinedAnswers++;
            }
            _answers.insert(_answers.begin(), std::move(answer));
            if (_answers.size() > KeptAnswers)
                _answers.resize(KeptAnswers);
            // A newer request or scene wins over refining this region further.
            const bool interrupted = _stop || _pending || !_sceneJobs.empty();
            if (interrupted || pass + 1 == passes)
                break;
            lock.unlock();
        }
        _busy = false;
    }
}
} // namespace osgVis::core
