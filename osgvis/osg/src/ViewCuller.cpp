// SPDX-License-Identifier: MIT
#include <osgVis/ViewCuller>

#include "Extraction.h"
#include "OsgCullRules.h"
#include "PagingPolicy.h"
#include "SceneWatch.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/api/ModuleSettings.h>
#include <osgVis/core/scene/View.h>

#include <osg/Camera>
#include <osg/FrameStamp>
#include <osg/Notify>
#include <osg/Viewport>
#include <osgDB/DatabasePager>

#include <glm/gtc/type_ptr.hpp>

#include <chrono>
#include <cmath>
#include <limits>

namespace osgVis
{
namespace
{
// An object's bounds in floats, rounded outwards, and its id: a walk over every object that reads
// nothing else (the extraction's records are large and scattered).
struct ObjectBox
{
    float min[3], max[3];
    core::ObjectId id;
};
} // namespace

struct ViewCuller::PerView
{
    explicit PerView(const core::SessionOptions& options) : session(options) {}

    osg::ref_ptr<const osg::Referenced> key; // held so the address is never reused by another view
    core::CullSession session;
    osg::ref_ptr<const ExtractedScene> scene; // the one `session` holds
    std::size_t objects = 0;                  // of `scene`, live and not placeholders
    std::vector<unsigned> placeholderLastVisible; // per object id: the frame this view last saw a paged node
    osg::Vec3d previousEye;                       // in the root's frame, at previousFrame
    unsigned previousFrame = ~0u;
    core::VisibleSet seenAhead; // the prefetch's region answer (regionSeenAhead)
    core::Aabb bounds;          // of `scene`'s objects with finite bounds
    std::vector<ObjectBox> boxes; // `scene`'s live objects, compact, for keepNearTheEye
    std::vector<const osg::StateSet*> stateSets; // whyLeftToOsg's scratch space
};

namespace
{
// OSG matrices multiply row vectors but store the same 16 numbers as GL's column-major layout, which
// is GLM's layout for column vectors.
core::Mat4 toCore(const osg::Matrixd& m)
{
    return glm::make_mat4(m.ptr());
}

// For the prefetch: what some eye near the predicted path (eye to eye + ahead) may see, by the
// asynchronous worker's finished regions (the one the eye is in and the one ahead), or else by the
// chain's region query (a baked PVS of the cells ahead, for cellportal). Null when the chain answers
// no regions or its answer keeps everything, which says nothing about what lies ahead.
const core::VisibleSet* regionSeenAhead(core::ModuleChain& chain, const core::AsyncVisibility* async,
                                        const core::View& current, const osg::Vec3d& eye, const osg::Vec3d& ahead,
                                        std::size_t objects, core::VisibleSet& out)
{
    if (async)
        return async->regionsAhead(out) && out.count() != out.capacity() ? &out : nullptr;
    if (!chain.supportsRegions())
        return nullptr;
    core::ViewRegion region;
    region.eyes.expand(core::Vec3(eye.x(), eye.y(), eye.z()));
    region.eyes.expand(core::Vec3(eye.x() + ahead.x(), eye.y() + ahead.y(), eye.z() + ahead.z()));
    region.minNearDistance = core::nearDistance(current);
    region.maxNearReach = core::nearPlaneReach(current);
    out.reset(objects, true);
    chain.cullRegion(region, out);
    return out.count() == out.capacity() ? nullptr : &out;
}

// Objects and paged nodes known, and of them those `visible` holds: work grows with the visible ones.
void countVisible(const ExtractedScene& scene, std::size_t objects, const core::VisibleSet& visible,
                  CullStatistics& figures)
{
    figures.objects = static_cast<unsigned>(objects);
    figures.pagedNodes = static_cast<unsigned>(scene.pagedNodes.size());
    unsigned pagedVisible = 0;
    visible.forEach([&](core::ObjectId id) {
        if (id >= scene.refs.size() || scene.removed(id))
            return;
        if (scene.placeholder(id))
        {
            ++pagedVisible;
            return;
        }
        const core::SceneObject& object = scene.scene.objects[id];
        ++figures.visible;
        figures.trianglesVisible += object.triangleCount;
        if (object.group != core::InvalidObject)
            ++figures.clustersVisible;
    });
    figures.pagedNodesSkipped = figures.pagedNodes - pagedVisible; // deferred ones included
}

// Keeps the objects within the near plane's reach of the eye: the modules culled with a near plane no
// nearer than OSG's can be (projectionForModules), and OSG may draw them in front of it.
void keepNearTheEye(const std::vector<ObjectBox>& boxes, const core::View& view, core::VisibleSet& visible)
{
    const double reach = core::nearPlaneReach(view);
    const double reach2 = reach * reach;
    for (const ObjectBox& box : boxes)
    {
        double distance2 = 0.0;
        for (int axis = 0; axis < 3; ++axis)
        {
            const double e = view.eye[axis];
            const double d = e < box.min[axis] ? box.min[axis] - e : e > box.max[axis] ? e - box.max[axis] : 0.0;
            distance2 += d * d;
        }
        if (distance2 <= reach2)
            visible.set(box.id);
    }
}

// The live objects' boxes, in floats rounded outwards (never smaller than the box).
void compactBoxes(const ExtractedScene& scene, std::vector<ObjectBox>& out)
{
    out.clear();
    for (core::ObjectId id = 0; id < scene.scene.objects.size(); ++id)
    {
        const core::Aabb& box = scene.scene.objects[id].bounds;
        if (scene.removed(id) || box.empty())
            continue;
        ObjectBox compact{};
        compact.id = id;
        for (int axis = 0; axis < 3; ++axis)
        {
            compact.min[axis] = std::nextafter(float(box.min[axis]), -std::numeric_limits<float>::infinity());
            compact.max[axis] = std::nextafter(float(box.max[axis]), std::numeric_limits<float>::infinity());
        }
        out.push_back(compact);
    }
}

// A copy of a member taken under `mutex` (the getters: other threads cull while they are called).
template <class T> T lockedCopy(std::mutex& mutex, const T& member)
{
    std::lock_guard<std::mutex> lock(mutex);
    return member;
}

// The core scene of an extraction, kept alive (with the extraction) for as long as the pointer.
std::shared_ptr<const core::Scene> sharedScene(const osg::ref_ptr<const ExtractedScene>& extraction)
{
    return std::shared_ptr<const core::Scene>(&extraction->scene, [keep = extraction](const core::Scene*) {});
}
} // namespace

ViewCuller::ViewCuller(const std::string& modes) : _watch(std::make_unique<SceneWatch>())
{
    setModes(modes);
}

ViewCuller::~ViewCuller() = default;

void ViewCuller::setModes(const std::string& modes)
{
    core::createChain(modes); // validates: throws UnknownModeError
    std::lock_guard<std::mutex> lock(_mutex);
    _modes = modes;
    _views.clear();
}

void ViewCuller::setChain(const std::vector<core::StageSettings>& chain)
{
    setModes(core::formatChainSettings(chain));
}

std::vector<core::StageSettings> ViewCuller::getChain() const
{
    return core::parseChainSettings(getModes());
}

void ViewCuller::setBakedData(std::shared_ptr<const core::BakedData> baked)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _baked = std::move(baked);
    _views.clear();
}

std::shared_ptr<const core::BakedData> ViewCuller::getBakedData() const
{
    return lockedCopy(_mutex, _baked);
}

void ViewCuller::setAsync(bool on, const core::AsyncOptions& options)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _async = on;
    _asyncOptions = options;
    _views.clear();
}

void ViewCuller::setBackOff(const core::BackOffOptions& options)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _backOffOptions = options;
    _views.clear();
}

void ViewCuller::setPagingOptions(const PagingOptions& options)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _pagingOptions = options;
}

PagingOptions ViewCuller::getPagingOptions() const
{
    return lockedCopy(_mutex, _pagingOptions);
}

core::BackOffOptions ViewCuller::getBackOffOptions() const
{
    return lockedCopy(_mutex, _backOffOptions);
}

bool ViewCuller::getAsync() const
{
    return lockedCopy(_mutex, _async);
}

core::AsyncOptions ViewCuller::getAsyncOptions() const
{
    return lockedCopy(_mutex, _asyncOptions);
}

ExtractionOptions ViewCuller::getExtractionOptions() const
{
    return lockedCopy(_mutex, _extractionOptions);
}

std::string ViewCuller::getModes() const
{
    return lockedCopy(_mutex, _modes);
}

void ViewCuller::setExtractionOptions(const ExtractionOptions& options)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _extractionOptions = options;
    _scene = nullptr;
}

void ViewCuller::dirtyScene()
{
    std::lock_guard<std::mutex> lock(_mutex);
    _dirty = true;
}

std::shared_ptr<ViewCuller::PerView> ViewCuller::viewFor(const osg::Referenced* key)
{
    std::shared_ptr<PerView>& view = _views[key];
    if (!view)
    {
        core::SessionOptions options;
        options.modes = _modes;
        options.baked = _baked;
        options.async = _async;
        options.asyncOptions = _asyncOptions;
        options.backOff = _backOffOptions;
        view = std::make_shared<PerView>(options);
        view->key = key;
    }
    return view;
}

// The extraction this cull uses, brought up to date with what changed since the last one (under _mutex).
osg::ref_ptr<const ExtractedScene> ViewCuller::currentScene(osgUtil::CullVisitor& cv, osg::Node& root, bool& extracted)
{
    const bool extract = !_scene || _root.get() != &root;
    // note: every cull compares, not once a frame: an application may change the graph between two
    // culls of one frame (a cull callback, a second camera, two culls with one frame stamp)
    osg::ref_ptr<ExtractedScene> moved; // only matrices changed: the objects below them placed again
    if (!extract && !_dirty)
    {
        const SceneWatch::Difference& difference = _watch->compare();
        if (!difference.other && !difference.moved.empty())
            moved = moveObjects(*_scene, difference.moved, _extractionOptions);
        if (moved)
            _watch->acceptMatrices(difference);
        else
            _dirty = difference.any();
    }
    // note: a paged node whose child count changed was merged into or expired by the pager; only
    // its children are extracted again, unless the whole root is dirty anyway
    const bool paged = !extract && !_dirty && !moved && _scene->pagedNodesChanged();
    const bool reextract = !extract && (_dirty || paged);
    osg::ref_ptr<ExtractedScene> updated = paged ? updatePagedScene(*_scene, _extractionOptions) : nullptr;
    if (extract)
        _scene = extractScene(root, _extractionOptions);
    else if (moved)
        _scene = moved;
    else if (updated)
        _scene = updated;
    else if (reextract)
        _scene = reextractScene(root, *_scene, _extractionOptions);
    extracted = extract || reextract;
    if (extracted)
        _watch->record(root);
    _root = &root;
    _dirty = false;
    return _scene;
}

namespace
{
// Lets stock tools (osgviewer with OSG_NOTIFY_LEVEL=INFO) show that osgVis culls their scene.
void reportExtraction(const osg::Node& root, const ExtractedScene& scene, const std::string& modes)
{
    if (!osg::isNotifyEnabled(osg::INFO))
        return;
    std::size_t objects = 0, triangles = 0;
    for (const core::SceneObject& object : scene.scene.objects)
        if (!scene.removed(object.id) && !scene.placeholder(object.id))
        {
            ++objects;
            triangles += object.triangleCount;
        }
    OSG_INFO << "osgVis: " << root.getName() << ": extracted " << objects << " objects (" << triangles
             << " triangles), modes " << modes << std::endl;
}
} // namespace

// Hands the view's session the extraction, as a replacement where it can.
void ViewCuller::handOver(PerView& view, const osg::ref_ptr<const ExtractedScene>& scene)
{
    if (view.scene == scene)
        return;
    // note: view.scene holds the extraction it names, so a match with `replaces` (which is only
    // ever the extraction right before `scene`) cannot be an address reused by another one.
    if (view.scene && scene->replaces == view.scene.get())
        view.session.sceneReplaced(sharedScene(scene), scene->changes);
    else
    {
        view.session.setScene(sharedScene(scene));
        view.placeholderLastVisible.clear(); // new ids
    }
    view.scene = scene;
    view.objects = 0;
    for (core::ObjectId id = 0; id < scene->refs.size(); ++id)
        view.objects += !scene->removed(id) && !scene->placeholder(id);
    view.bounds = scene->scene.bounds();
    compactBoxes(*scene, view.boxes);
}

// After the cull: what the pager is asked for, kept fresh and fetched ahead (docs/paging.md).
void ViewCuller::drivePaging(PerView& view, osgUtil::CullVisitor& cv, const PagingOptions& paging,
                             const core::View& coreView, const osg::Matrixd& modelView,
                             const osg::Matrixd& projection, CullStatistics& figures)
{
    const ExtractedScene& scene = *view.scene;
    core::VisibleSet& visible = view.session.visible();
    const osg::FrameStamp* frameStamp = cv.getFrameStamp();
    const auto* pager = dynamic_cast<const osgDB::DatabasePager*>(cv.getDatabaseRequestHandler());
    const std::size_t residentBudget =
        pager ? pager->getTargetMaximumNumberOfPageLOD() : std::numeric_limits<std::size_t>::max();
    const PagingFigures pagingFigures = applyPagingPolicy(paging, scene, visible, modelView, projection,
                                                          frameStamp, residentBudget, view.placeholderLastVisible);
    figures.pagedNodesDeferred = pagingFigures.deferred;
    figures.pagedNodesKeptFresh = pagingFigures.keptFresh;
    // The eye's last step, per frame, extrapolated for the prefetch.
    const osg::Vec3d eye = osg::Matrixd::inverse(modelView).getTrans();
    const unsigned frame = frameStamp ? frameStamp->getFrameNumber() : 0u;
    if (osg::NodeVisitor::DatabaseRequestHandler* handler = cv.getDatabaseRequestHandler();
        handler && view.previousFrame != ~0u && frame > view.previousFrame && !scene.pagedNodes.empty())
    {
        const osg::Vec3d step = (eye - view.previousEye) / double(frame - view.previousFrame);
        const core::VisibleSet* seenAhead =
            paging.prefetchFrames != 0
                ? regionSeenAhead(view.session.chain(), view.session.async(), coreView, eye,
                                  step * double(paging.prefetchFrames), visible.capacity(), view.seenAhead)
                : nullptr;
        figures.pagedNodesPrefetched =
            prefetchAhead(scene, visible, eye, step, paging.prefetchFrames, seenAhead, *handler, frameStamp);
    }
    view.previousEye = eye;
    view.previousFrame = frame;
}

ViewCuller::Result ViewCuller::cull(osgUtil::CullVisitor& cv, osg::Node& root, const osg::Matrixd& modelView,
                                    const osg::Matrixd& projection)
{
    // note: getCurrentCamera() dereferences the render bin, which a bare visitor (tests, tools) lacks.
    osg::Camera* camera = cv.getCurrentRenderBin() ? cv.getCurrentCamera() : nullptr;
    const osg::Referenced* key = cv.getIdentifier();
    if (!key)
        key = camera;

    osg::ref_ptr<const ExtractedScene> scene;
    std::shared_ptr<PerView> view;
    bool extracted = false;
    std::string modes;
    PagingOptions paging;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        paging = _pagingOptions;
        scene = currentScene(cv, root, extracted);
        if (extracted)
            modes = _modes;
        view = viewFor(key);
    }
    if (extracted)
        reportExtraction(root, *scene, modes);

    std::unique_lock<std::mutex> debugLock(_debugMutex);
    core::DebugRecord* const record = _debugRecord;
    if (record)
        record->clear();
    else
        debugLock.unlock();
    view->session.setDebugRecord(record);

    const auto start = std::chrono::steady_clock::now();
    handOver(*view, scene);
    // OSG's rules first: where they break what the extraction assumed, OSG alone culls this view
    const char* leftToOsg = whyLeftToOsg(cv, *scene, view->stateSets);
    osg::Matrixd modulesProjection = projection;
    const ModulesProjection projected =
        leftToOsg ? ModulesProjection::AsDrawn : projectionForModules(cv, modelView, view->bounds, modulesProjection);
    if (projected == ModulesProjection::Unknown)
        leftToOsg = "near and far computed by OSG for a projection the kit cannot bound";
    const osg::Viewport* viewport = cv.getViewport();
    const osg::FrameStamp* frameStamp = cv.getFrameStamp();
    core::View coreView = core::makeView(
        toCore(modelView), toCore(modulesProjection), frameStamp ? frameStamp->getSimulationTime() : 0.0,
        viewport ? static_cast<std::uint32_t>(viewport->width()) : 1280u,
        viewport ? static_cast<std::uint32_t>(viewport->height()) : 1024u);
    coreView.depthBits = depthBitsOf(camera);
    CullStatistics figures;
    figures.leftToOsg = leftToOsg;
    if (leftToOsg)
        view->session.visible().reset(scene->refs.size(), true);
    else
    {
        view->session.cull(coreView, start);
        if (projected == ModulesProjection::Adjusted)
            keepNearTheEye(view->boxes, coreView, view->session.visible());
        const core::SessionFigures& answered = view->session.figures();
        figures.async = answered.async;
        figures.asyncFallback = answered.asyncFallback;
        figures.backOff = answered.backOff;
        figures.backedOff = answered.backedOff;
        if (!figures.backedOff)
            drivePaging(*view, cv, paging, coreView, modelView, projection, figures);
    }
    const auto end = std::chrono::steady_clock::now();
    if (debugLock.owns_lock())
        debugLock.unlock();

    countVisible(*scene, view->objects, view->session.visible(), figures);
    figures.clustered = scene->clusteredDrawables != 0;
    figures.cullMs = std::chrono::duration<double, std::milli>(end - start).count();
    if (frameStamp)
        recordStatistics(camera, frameStamp->getFrameNumber(), figures);
    OSG_DEBUG << "osgVis: " << root.getName() << ": frame " << (frameStamp ? frameStamp->getFrameNumber() : 0u) << ": "
              << figures.visible << " of " << figures.objects << " objects visible" << std::endl;
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _last = figures;
    }
    return {scene, &view->session.visible(), figures.backedOff || figures.leftToOsg};
}

CullStatistics ViewCuller::getLastStatistics() const
{
    return lockedCopy(_mutex, _last);
}

osg::ref_ptr<const ExtractedScene> ViewCuller::getScene() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _dirty ? nullptr : _scene;
}

void ViewCuller::setDebugRecord(core::DebugRecord* record)
{
    // Waits for a query writing the previous record; later queries hand the new one to their stages.
    std::lock_guard<std::mutex> lock(_debugMutex);
    _debugRecord = record;
}

core::DebugRecord ViewCuller::getDebugRecord() const
{
    std::lock_guard<std::mutex> lock(_debugMutex);
    return _debugRecord ? *_debugRecord : core::DebugRecord();
}
} // namespace osgVis
