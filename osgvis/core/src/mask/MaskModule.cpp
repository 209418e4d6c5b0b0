// SPDX-License-Identifier: MIT
#include "MaskImpl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_set>

namespace osgVis::core
{
namespace
{
using Clock = std::chrono::steady_clock;
// Halvings of an object's box when the whole box is covered but not deep enough (2^3 pieces at most).
constexpr int kObjectSplits = 4;
double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// True when the box lies more than `margin` outside one of the frustum's planes (unit normals).
bool outsideGrownFrustum(const Frustum& frustum, const Aabb& box, double margin)
{
    for (const Plane& plane : frustum.planes())
    {
        const Vec3 farthest(plane.normal.x >= 0.0 ? box.max.x : box.min.x, plane.normal.y >= 0.0 ? box.max.y : box.min.y,
                            plane.normal.z >= 0.0 ? box.max.z : box.min.z);
        if (plane.distance(farthest) < -margin * (1.0 + 1e-9) - 1e-12)
            return true;
    }
    return false;
}

bool sameOrientation(const View& a, const View& b)
{
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(a.viewMatrix[c][r] - b.viewMatrix[c][r]) > 1e-12)
                return false;
    return true;
}

bool sameProjection(const View& a, const View& b)
{
    return a.projectionMatrix == b.projectionMatrix && a.viewportWidth == b.viewportWidth &&
           a.viewportHeight == b.viewportHeight;
}

Vec3 viewDirection(const View& view)
{
    const Mat4 inverse = glm::inverse(view.viewMatrix);
    return glm::normalize(Vec3(inverse * Vec4(0.0, 0.0, -1.0, 0.0)));
}

// The polygon budget: the `budget` largest of `selected` by area-angle from `eye` (ties by index),
// in ascending index order so the groups come out the same every run.
void keepLargestPolygons(const std::vector<OccluderPolygon>& polygons, const Vec3& eye, std::uint32_t budget,
                         std::vector<std::uint32_t>& selected, std::vector<std::pair<double, std::uint32_t>>& ranked)
{
    if (budget == 0 || selected.size() <= budget)
        return;
    ranked.clear();
    for (std::uint32_t p : selected)
        ranked.push_back({-areaAngle(polygons[p], eye), p});
    std::nth_element(ranked.begin(), ranked.begin() + budget, ranked.end());
    selected.clear();
    for (std::size_t i = 0; i < budget; ++i)
        selected.push_back(ranked[i].second);
    std::sort(selected.begin(), selected.end());
}


// The mask's size and margins for a view, in mask pixels.
struct MaskLayout
{
    std::uint32_t width = 0, height = 0;
    double shift = 0.0; // Δ
    std::uint32_t border = 0;
    double clipMargin = 0.0;
};

MaskLayout maskLayoutFor(const View& view, const MaskOptions& options)
{
    MaskLayout layout;
    const double maskScale = double(options.maskDownscale == 0 ? 1 : options.maskDownscale);
    layout.width = std::max<std::uint32_t>(16, std::uint32_t(std::ceil(view.viewportWidth / maskScale)));
    layout.height = std::max<std::uint32_t>(16, std::uint32_t(std::ceil(view.viewportHeight / maskScale)));
    // Δ in mask pixels: the largest image shift allowed for points at the occluders' depth.
    layout.shift = options.shrinkPixels * double(layout.width) / std::max(1u, view.viewportWidth);
    // A border around the frame holds what an eye δ away may see at the frame's edges; occluders
    // are clipped farther out still, so their outline cannot sweep in from beyond what was
    // rasterized.
    layout.border = static_cast<std::uint32_t>(std::ceil(layout.shift)) + 1;
    layout.clipMargin = layout.border + 2.0 * layout.shift + 2.0;
    return layout;
}

// Depth first over `tree` from its root, a node's left subtree before its right one;
// visit(index, node) says whether to go below the node. `stack` is scratch.
template <class Visit> void visitPreorder(const MaskKdTree& tree, std::vector<std::uint32_t>& stack, Visit&& visit)
{
    stack.assign(1, tree.root());
    while (!stack.empty())
    {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        const MaskKdTree::Node& node = tree.node(index);
        if (visit(index, node))
        {
            stack.push_back(node.right);
            stack.push_back(node.left);
        }
    }
}
} // namespace


MaskModule::MaskModule(const MaskOptions& options) : _options(options), _impl(std::make_unique<Impl>()) {}
MaskModule::~MaskModule() = default;

const char* MaskModule::name() const
{
    if (_options.shrink == MaskShrink::FusedUnion)
        return "mask-approx";
    return _options.measure == OccluderMeasure::Distance ? "mask-distance" : "mask";
}

void MaskModule::setDebugRecord(DebugRecord* record)
{
    _impl->debug = record;
}

MaskModule::Statistics MaskModule::lastStatistics() const
{
    // Counted when asked, not in the frame: a full pass over the mask is 6 % of a critical frame's
    // instructions on a real level, and only the benchmark and the tests read it.
    Statistics stats = _impl->statistics;
    if (stats.critical != CriticalReason::None)
        stats.coveredPixels = _impl->mask.coveredPixels();
    return stats;
}

const OcclusionMask& MaskModule::mask() const
{
    return _impl->mask;
}

bool MaskModule::walksSceneHierarchy() const
{
    return _impl->sceneHierarchy.walks();
}

const std::string& MaskModule::hierarchyProblem() const
{
    return _impl->sceneHierarchy.problem();
}

void MaskModule::cull(const View& view, VisibleSet& visible)
{
    Impl& m = *_impl;
    m.statistics = Statistics();
    Statistics& stats = m.statistics;
    if (!_scene || !m.hasObjects())
        return;
    if (m.debug)
        m.debug->clear();

    const CriticalReason reason = criticalReasonFor(view);
    if (reason != CriticalReason::None && !runCriticalFrame(view, reason))
        return;
    stats.maskWidth = m.mask.width();
    stats.maskHeight = m.mask.height();
    stats.delta = m.delta;
    stats.validUntil = m.validUntil;
    stats.criticalAfter = m.criticalAfter;
    if (!m.haveMask)
        return;

    // Stamped subtrees and objects drop out; moving objects are tested against the mask, which
    // holds for every eye of the current ball.
    const double t = view.time;
    std::uint32_t culled = m.sceneHierarchy.walks() ? applyHierarchyMarks(t, visible) : applyTreeMarks(t, visible);
    culled += cullMovingObjects(view.eye, visible);
    stats.culled = culled;
}

bool MaskModule::aliveMarksHold(double t, const Vec3& eye)
{
    Impl& m = *_impl;
    // Stamps are sound only while the eye stays inside the ball of the critical frame that wrote
    // them; the speed bound V guarantees that, but an eye faster than V (or time running
    // backwards) must not trust them.
    const double speed = _options.maxEyeSpeed;
    while (!m.alive.empty() && t >= m.alive.front().time + m.alive.front().deltaMax / speed)
        m.alive.popFront();
    bool trusted = true;
    for (const Impl::CriticalFrame& frame : m.alive)
    {
        // Each stamp t_k + δ/V holds while the eye is within its δ of the critical eye: surely so
        // inside the smallest δ, and otherwise as long as the eye kept to the speed V.
        const double moved = glm::length(eye - frame.eye);
        trusted = trusted && t >= frame.time &&
                  (moved <= frame.deltaMin || moved <= speed * (t - frame.time) * (1.0 - 1e-12));
    }
    return trusted;
}

MaskModule::CriticalReason MaskModule::criticalReasonFor(const View& view)
{
    Impl& m = *_impl;
    CriticalReason reason = CriticalReason::None;
    if (!aliveMarksHold(view.time, view.eye))
    {
        m.forgetMarks();
        reason = CriticalReason::LeftRegion;
    }
    else if (m.occluderGone)
        reason = CriticalReason::OccluderGone;
    else if (!m.haveMask)
        reason = CriticalReason::First;
    else if (!sameProjection(view, m.criticalView))
    {
        // The near plane decides which occluder parts are drawn at all.
        m.forgetMarks();
        reason = CriticalReason::ViewChanged;
    }
    else if (!sameOrientation(view, m.criticalView))
    {
        // Marks cover the critical frame (grown by Δ) only: objects partly outside it were
        // judged by their part inside. Checked before expiry: a turn must forget the marks
        // whatever else is due.
        m.forgetMarks();
        reason = CriticalReason::Turned;
    }
    else if (view.time >= m.criticalAfter)
        reason = CriticalReason::StampExpired;
    m.occluderGone = false;
    return reason;
}

bool MaskModule::runCriticalFrame(const View& view, CriticalReason reason)
{
    Impl& m = *_impl;
    Statistics& stats = m.statistics;
    const MaskLayout layout = maskLayoutFor(view, _options);
    if (!m.projection.set(view, layout.width, layout.height, layout.border, layout.clipMargin))
    {
        // Orthographic or unusual projections: no occlusion from this module.
        m.forgetMarks();
        return false;
    }
    stats.critical = reason;
    Clock::time_point start = Clock::now();
    const double nearDepth = std::max(_options.minOccluderDistance, 2.0 * m.projection.nearPlane());
    selectOccluders(view);
    stats.selectMs = millisecondsSince(start);

    start = Clock::now();
    rasterizeOccluders(nearDepth, layout.shift, stats);
    stats.rasterizeMs = millisecondsSince(start);

    start = Clock::now();
    m.mask.buildPyramid();
    stats.pyramidMs = millisecondsSince(start);

    m.haveMask = true;
    m.criticalView = view;
    m.criticalDirection = viewDirection(view);
    m.shift = layout.shift;
    m.maskShift = _options.shrink == MaskShrink::PerOccluder ? layout.shift : 0.0;

    start = Clock::now();
    m.stamps.clear();
    markHidden(stats);
    stats.markMs = millisecondsSince(start);

    recordCriticalFrame(view.time, view.eye);
    stats.occluderObjects = static_cast<std::uint32_t>(m.occluders.size());
    stats.occluderPolygons = static_cast<std::uint32_t>(m.groups.polygonCount());
    stats.groups = static_cast<std::uint32_t>(m.groups.groupCount());
    if (m.debug)
        for (std::uint32_t index : m.selected)
            m.debug->activeOccluders.push_back(m.polygons[index].vertices);
    return true;
}

void MaskModule::selectOccluders(const View& view)
{
    Impl& m = *_impl;
    MaskSelectionInput input;
    input.tree = &m.tree;
    input.hierarchy = m.sceneHierarchy.walks() ? &m.sceneHierarchy.index() : nullptr;
    input.objects = &_scene->objects;
    input.usable = &m.usable;
    input.view = &view;
    input.projection = &m.projection;
    input.eye = view.eye;
    input.minDistance = _options.minOccluderDistance;
    input.sampleRadius = m.delta;
    input.count = _options.occluders;
    input.measure = _options.measure;
    std::vector<ObjectId>& occluders = m.occluders;
    selectMaskOccluders(input, m.selection, occluders);
    std::vector<std::uint32_t>& selected = m.selected;
    selected.assign(m.statedPolygons.begin(), m.statedPolygons.end());
    // A union of several objects' faces serves while every one of them stands still, and the
    // marks rest on all of them (removing or moving any forgets the marks).
    std::vector<ObjectId>& restingOn = m.restingOn;
    restingOn.assign(occluders.begin(), occluders.end());
    ++m.criticalCount;
    for (ObjectId id : occluders)
        for (std::uint32_t p : m.polygonsOf[id])
        {
            if (m.selectedIn[p] == m.criticalCount)
                continue;
            const std::vector<ObjectId>& parts = m.polygons[p].parts;
            if (!std::all_of(parts.begin(), parts.end(),
                             [&](ObjectId part)
                             { return part < m.present.size() && m.present[part] && !m.moving[part]; }))
                continue;
            m.selectedIn[p] = m.criticalCount;
            selected.push_back(p);
            restingOn.insert(restingOn.end(), parts.begin(), parts.end());
        }
    std::sort(restingOn.begin(), restingOn.end());
    restingOn.erase(std::unique(restingOn.begin(), restingOn.end()), restingOn.end());
    keepLargestPolygons(m.polygons, view.eye, _options.maxOccluderPolygons, selected, m.rankedPolygons);
}

void MaskModule::rasterizeOccluders(double nearDepth, double shift, Statistics& stats)
{
    Impl& m = *_impl;
    buildMaskGroups(m.polygons, m.selected, m.projection, nearDepth, shift, m.groups);
    fillTileDeltas(shift);
    m.mask.reset(m.projection.width(), m.projection.height());
    const bool perOccluder = _options.shrink == MaskShrink::PerOccluder;
    // A group left out only hides less (its δ still bounds the tiles it reaches: smaller is safe).
    const std::uint64_t budget =
        _options.workBudget == 0 ? std::numeric_limits<std::uint64_t>::max() : _options.workBudget;
    const std::uint64_t rasterBudget = budget == std::numeric_limits<std::uint64_t>::max() ? budget : budget / 5 * 3;
    // Largest groups first (most tiles: they hide the most), ties by index: deterministic.
    std::vector<std::uint32_t>& order = m.groupOrder;
    order.resize(m.groups.groupCount());
    for (std::uint32_t g = 0; g < order.size(); ++g)
        order[g] = g;
    if (_options.workBudget != 0)
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t wa = m.groups.groupWork[a], wb = m.groups.groupWork[b];
            return wa > wb || (wa == wb && a < b);
        });
    for (const std::uint32_t g : order)
    {
        if (m.groups.groupWork[g] > rasterBudget - stats.rasterWork)
        {
            ++stats.groupsSkipped;
            stats.overBudget = true;
            continue;
        }
        stats.rasterWork += m.groups.groupWork[g];
        rasterizeOccluderGroup(m.mask, m.groups.polygons.data() + m.groups.groupStart[g],
                               m.groups.groupStart[g + 1] - m.groups.groupStart[g], perOccluder ? shift : 0.0,
                               m.scratch);
    }
    m.markBudget = budget - stats.rasterWork;
    if (!perOccluder && shift > 0.0)
        m.mask.shrinkUnion(static_cast<std::uint32_t>(std::ceil(shift)));
}

void MaskModule::recordCriticalFrame(double t, const Vec3& eye)
{
    Impl& m = *_impl;
    const double speed = _options.maxEyeSpeed;
    // Stamps run out one by one; the next critical frame comes when the marks of half the
    // hidden objects have expired (or at once when nothing was marked).
    double deltaMin = std::numeric_limits<double>::max(), deltaMax = 0.0;
    std::uint64_t marked = 0;
    for (const auto& [until, objects] : m.stamps)
    {
        const double delta = (until - t) * speed;
        deltaMin = std::min(deltaMin, delta);
        deltaMax = std::max(deltaMax, delta);
        marked += objects;
    }
    std::sort(m.stamps.begin(), m.stamps.end());
    m.criticalAfter = t;
    std::uint64_t sum = 0;
    for (const auto& [until, objects] : m.stamps)
        if ((sum += objects) * 2 >= marked)
        {
            m.criticalAfter = until;
            break;
        }
    if (m.stamps.empty())
        deltaMin = 0.0;
    m.delta = deltaMin;
    m.validUntil = t + deltaMin / speed;
    Impl::CriticalFrame& frame = m.alive.pushBack();
    frame.eye = eye;
    frame.time = t;
    frame.deltaMin = deltaMin;
    frame.deltaMax = deltaMax;
    frame.occluders.assign(m.restingOn.begin(), m.restingOn.end());
}

std::uint32_t MaskModule::cullMovingObjects(const Vec3& eye, VisibleSet& visible) const
{
    const Impl& m = *_impl;
    std::uint32_t culled = 0;
    for (ObjectId id : m.movingIds)
    {
        if (!visible.test(id))
            continue;
        double delta = 0.0;
        if (objectBehindMask(_scene->objects[id].bounds, kObjectSplits, delta) &&
            glm::length(eye - m.criticalView.eye) <= delta)
            visible.clear(id), ++culled;
    }
    return culled;
}

bool MaskModule::objectBehindMask(const Aabb& box, int splits, double& delta) const
{
    const Impl& m = *_impl;
    if (!m.haveMask || box.empty() || !box.finite())
        return false;
    const std::optional<MaskRect> rect = m.projection.project(box);
    if (!rect)
        return false;
    // Only what an eye of the ball can see in this frame matters: its image lies within Δ of the
    // frame. A box entirely beyond that is out of view for the whole ball. The target's own image
    // moves by up to Δ too: its rectangle grows by that much.
    const double g = m.maskShift;
    const double b = m.projection.border();
    const double x0 = std::max(rect->x0 - g, b - g), x1 = std::min(rect->x1 + g, b + m.projection.frameWidth() + g);
    const double y0 = std::max(rect->y0 - g, b - g), y1 = std::min(rect->y1 + g, b + m.projection.frameHeight() + g);
    if (x0 > x1 || y0 > y1)
    {
        // Out of view: stays so while the box's own image moves by less than Δ.
        delta = m.projection.deltaFor(m.shift, rect->nearestDepth);
        return true;
    }
    delta = tileDeltaOver(x0, y0, x1, y1);
    if (!(delta < std::numeric_limits<double>::max()))
        return false; // no occluder anywhere near
    // Depth: from an eye δ away, the occluder's point is at most δ farther and the target's at most
    // δ nearer. Float storage of the mask may round a depth down: keep a relative margin for it.
    const double nearest = rect->nearestDepth - 2.0 * delta;
    const float limit = static_cast<float>(nearest * (1.0 - 1e-5));
    if (!(limit > 0.0f))
        return false;
    if (m.mask.rectHidden(x0, y0, x1, y1, limit))
        return true;
    // One nearest depth for a whole box is weak where occluders recede (a street's side walls):
    // halves along the axis where the box's view depth varies most have nearer-to-true depths.
    if (splits <= 0 || !m.mask.rectHidden(x0, y0, x1, y1, std::numeric_limits<float>::infinity()))
        return false;
    const Vec3 spread = box.extent() * glm::abs(m.criticalDirection);
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
    Aabb lower = box, upper = box;
    lower.max[axis] = upper.min[axis] = box.center()[axis];
    double lowerDelta = 0.0, upperDelta = 0.0;
    if (!objectBehindMask(lower, splits - 1, lowerDelta) || !objectBehindMask(upper, splits - 1, upperDelta))
        return false;
    delta = std::min(lowerDelta, upperDelta);
    return true;
}

double MaskModule::tileDeltaOver(double x0, double y0, double x1, double y1) const
{
    const Impl& m = *_impl;
    const auto tile = [](double v, std::uint32_t count)
    { return std::min<std::uint32_t>(count - 1, static_cast<std::uint32_t>(std::max(0.0, v) / Impl::kTile)); };
    double delta = std::numeric_limits<double>::max();
    for (std::uint32_t ty = tile(y0, m.tilesY); ty <= tile(y1, m.tilesY); ++ty)
        for (std::uint32_t tx = tile(x0, m.tilesX); tx <= tile(x1, m.tilesX); ++tx)
            delta = std::min(delta, m.tileDelta[ty * m.tilesX + tx]);
    return delta;
}

void MaskModule::fillTileDeltas(double shift)
{
    Impl& m = *_impl;
    m.tilesX = (m.projection.width() + Impl::kTile - 1) / Impl::kTile;
    m.tilesY = (m.projection.height() + Impl::kTile - 1) / Impl::kTile;
    m.tileDelta.assign(std::size_t(m.tilesX) * m.tilesY, std::numeric_limits<double>::max());
    const auto tile = [](double v, std::uint32_t count)
    { return std::min<std::uint32_t>(count - 1, static_cast<std::uint32_t>(std::max(0.0, v) / Impl::kTile)); };
    for (std::size_t g = 0; g < m.groups.groupCount(); ++g)
    {
        const glm::dvec4& r = m.groups.groupRect[g];
        if (r.x > r.z || r.y > r.w)
            continue;
        const double delta = m.groups.groupDelta[g];
        // Pixels the group covers lie within its rectangle grown by the shrink and one pixel.
        const double grow = shift + 1.0;
        for (std::uint32_t ty = tile(r.y - grow, m.tilesY); ty <= tile(r.w + grow, m.tilesY); ++ty)
            for (std::uint32_t tx = tile(r.x - grow, m.tilesX); tx <= tile(r.z + grow, m.tilesX); ++tx)
                m.tileDelta[ty * m.tilesX + tx] = std::min(m.tileDelta[ty * m.tilesX + tx], delta);
    }
}

// One marking pass of a critical frame: the stamps it gives, its budget and the box tests that the
// walk over the kd-tree and the one over the renderer's traversal share.
struct MaskModule::MarkPass
{
    MaskModule& module;
    Impl& m;
    const MaskOptions& options;
    Statistics& stats;
    const View& view;      // the critical frame's
    double outOfViewDelta; // the largest δ of the groups

    // A stamp hides while it is later than the walk time; with δ = 0 it still has to hide in the
    // critical frame itself.
    double stampFor(double delta) const
    {
        const double now = view.time;
        return std::max(now + delta / options.maxEyeSpeed,
                        std::nextafter(now, std::numeric_limits<double>::infinity()));
    }

    bool chargeBoxTest()
    {
        if (options.boxTestWork > m.markBudget - stats.markWork)
        {
            stats.overBudget = true;
            return false;
        }
        stats.markWork += options.boxTestWork;
        return true;
    }

    // A node whose whole box is decided: out of view for every eye within outOfViewDelta (the
    // frustum's planes move with the eye, its orientation kept), or behind the mask. Out-of-view
    // marks do not decide when the next critical frame comes (weight 0). markNode(until) marks it.
    template <typename MarkNode> bool nodeDecided(const Aabb& box, std::uint32_t objects, MarkNode&& markNode)
    {
        if (view.frustum.classify(box) == Containment::Outside)
        {
            if (outsideGrownFrustum(view.frustum, box, outOfViewDelta))
            {
                const double until = stampFor(outOfViewDelta);
                markNode(until);
                m.stamps.push_back({until, 0u});
            }
            return true;
        }
        if (!chargeBoxTest())
            return true; // out of budget: left unmarked, so visible, and not descended into
        ++stats.nodesTested;
        double delta = 0.0;
        if (!module.objectBehindMask(box, 0, delta))
            return false;
        const double until = stampFor(delta);
        markNode(until);
        m.stamps.push_back({until, objects});
        ++stats.nodesMarked;
        if (m.debug)
            m.debug->nodes.push_back({box, NodeState::Invisible, 0});
        return true;
    }

    // Below ρ objects (or at a leaf) they are tested one by one.
    template <typename MarkObject> void testObject(ObjectId id, MarkObject&& markObject)
    {
        double delta = 0.0;
        if (m.moving[id] || !chargeBoxTest() ||
            !module.objectBehindMask(module._scene->objects[id].bounds, kObjectSplits, delta))
            return;
        const double until = stampFor(delta);
        markObject(until);
        m.stamps.push_back({until, 1u});
        ++stats.objectsMarked;
    }

    void recordTested(const Aabb& box)
    {
        if (m.debug)
            m.debug->nodes.push_back({box, NodeState::Visible, 0});
    }

    void markHierarchy();
    void markTree();
};

void MaskModule::markHidden(Statistics& stats)
{
    Impl& m = *_impl;
    double outOfViewDelta = 0.0;
    for (double delta : m.groups.groupDelta)
        outOfViewDelta = std::max(outOfViewDelta, delta);
    MarkPass pass{*this, m, _options, stats, m.criticalView, outOfViewDelta};
    if (m.sceneHierarchy.walks())
        pass.markHierarchy();
    else
        pass.markTree();
}

void MaskModule::MarkPass::markHierarchy()
{
    // The renderer's traversal; its order does not matter (each box is judged on its own).
    const std::vector<ObjectId>& objects = m.sceneHierarchy.index().objects();
    // Returns whether to go below the node.
    auto visit = [&](const HierarchyNode&, const HierarchyIndex::Node& n, std::size_t) -> bool
    {
        const std::uint32_t count = n.subtreeEnd - n.firstObject;
        if (count == 0 || nodeDecided(n.contents, count, [&](double until)
                                      { m.rangeMarks.push_back({n.firstObject, n.subtreeEnd, until}); }))
            return false;
        const bool oneByOne = n.leaf() || count < options.stopObjects;
        const std::uint32_t end = oneByOne ? n.subtreeEnd : n.firstObject + n.heldCount;
        for (std::uint32_t i = n.firstObject; i < end; ++i)
            testObject(objects[i], [&](double until) { m.rangeMarks.push_back({i, i + 1, until}); });
        if (!oneByOne)
            return true;
        recordTested(n.contents);
        return false;
    };
    // A refused node gets no mark: its objects stay as they are.
    m.sceneHierarchy.traverse(view.eye, visit, [&]() { ++stats.nodesStrayed; });
}

void MaskModule::MarkPass::markTree()
{
    visitPreorder(
        m.tree, m.nodeStack,
        [&](std::uint32_t index, const MaskKdTree::Node& node)
        {
            if (node.objectCount == 0 || node.bounds.empty() ||
                nodeDecided(node.bounds, node.objectCount, [&](double until) { m.tree.markNode(index, until); }))
                return false;
            if (!node.leaf() && node.objectCount >= options.stopObjects)
                return true;
            m.tree.forEachObjectBelow(index, [&](ObjectId id)
                                      { testObject(id, [&](double until) { m.tree.markObject(id, until); }); });
            recordTested(node.bounds);
            return false;
        });
}

std::uint32_t MaskModule::applyTreeMarks(double t, VisibleSet& visible)
{
    Impl& m = *_impl;
    std::uint32_t culled = 0;
    visitPreorder(m.tree, m.nodeStack,
                  [&](std::uint32_t index, const MaskKdTree::Node& node)
                  {
                      if (node.objectCount == 0)
                          return false;
                      const bool nodeHidden = node.stamp > t;
                      if (!nodeHidden && !node.leaf())
                          return true;
                      if (nodeHidden)
                      {
                          m.tree.forEachObjectBelow(index,
                                                    [&](ObjectId id)
                                                    {
                                                        if (visible.test(id))
                                                            visible.clear(id), ++culled;
                                                    });
                          return false;
                      }
                      for (ObjectId id : node.objects)
                          if (m.tree.objectStamp(id) > t && visible.test(id))
                              visible.clear(id), ++culled;
                      return false;
                  });
    return culled;
}

std::uint32_t MaskModule::applyHierarchyMarks(double t, VisibleSet& visible)
{
    Impl& m = *_impl;
    // Expired marks go; moving objects were judged by boxes they have left and are tested below.
    m.rangeMarks.erase(std::remove_if(m.rangeMarks.begin(), m.rangeMarks.end(),
                                      [&](const Impl::RangeMark& mark) { return !(mark.until > t); }),
                       m.rangeMarks.end());
    const std::vector<ObjectId>& objects = m.sceneHierarchy.index().objects();
    std::uint32_t culled = 0;
    for (const Impl::RangeMark& mark : m.rangeMarks)
        for (std::uint32_t i = mark.first; i < mark.end; ++i)
        {
            const ObjectId id = objects[i];
            if (!m.moving[id] && visible.test(id))
                visible.clear(id), ++culled;
        }
    return culled;
}
} // namespace osgVis::core
