// SPDX-License-Identifier: MIT
// Object-space occlusion culling after Coorg & Teller. Per frame: pick the k best occluders for
// the eye (area-angle, from the eye's cell), drop those the renderer may not draw (in front of the
// near plane), then walk the kd-tree: frustum planes and occluders together, whole subtrees
// hidden at once, and only the occluders that partly hide a node passed on to its children.
// The top of the tree is walked serially; the subtrees below a fixed frontier run in parallel
// with an affinity partitioner, so a subtree tends to stay on the thread that has its caches.
// On a renderer's hierarchy (visibility API §3.3) the same tests run in its traversal's order,
// node by node, on the recorded tight boxes (HierarchyIndex), with one cache per node id.
#include "OctreeImpl.h"

#include <osgVis/core/occluders/CoplanarUnion.h>

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <tuple>

namespace osgVis::core
{
namespace
{
// Bits of a 24-bit depth buffer we trust: a hidden box must lie farther behind its occluder than
// 2^(24-3) depth steps' worth, or the two could z-fight and the box show through.
constexpr double DepthResolution = double(1u << 21);
// Angular safety margin (radians): a box must be hidden by about a tenth of a pixel at
// 1280×1024 and 60° so rasterization rounding on the occluder's edges cannot reveal it.
constexpr double AngularMargin = 1e-4;

Aabb boundsOf(const OccluderPolygon& polygon)
{
    Aabb bounds;
    for (const Vec3& v : polygon.vertices)
        bounds.expand(v);
    return bounds;
}
} // namespace

using octree_impl::Range;
using octree_impl::TraversalOutput;

void OctreeModule::Impl::build(const Scene& scene, const OctreeOptions& options)
{
    tree = KdTree();
    sceneHierarchy.choose(scene, options.sceneHierarchy);
    hierarchyCaches.assign(sceneHierarchy.walks() ? sceneHierarchy.hierarchy()->nodeCount() : 0, BoxOcclusionCache());
    if (!sceneHierarchy.walks())
    {
        std::vector<Aabb> boxes;
        boxes.reserve(scene.objects.size());
        for (const SceneObject& o : scene.objects)
            boxes.push_back(o.bounds);
        tree.build(boxes, options.maxLeafObjects);
    }

    polygons = buildOccluderPolygons(scene, options.occluderBuild);
    collectObjectPoints(scene);
    objectPolygons.assign(scene.objects.size(), {});
    statedPolygons.clear();
    for (std::uint32_t p = 0; p < polygons.size(); ++p)
    {
        // A union of several objects' faces joins the sweep's tree with whichever of them is kept
        // first (each is static; the others are drawn or hidden behind what is drawn).
        if (polygons[p].owner >= scene.objects.size())
            statedPolygons.push_back(p);
        else if (polygons[p].parts.empty())
            objectPolygons[polygons[p].owner].push_back(p);
        for (ObjectId part : polygons[p].parts)
            if (part < scene.objects.size())
                objectPolygons[part].push_back(p);
    }
    largestPolygonArea.assign(scene.objects.size(), 0.0);
    for (ObjectId id = 0; id < scene.objects.size(); ++id)
        for (std::uint32_t p : objectPolygons[id])
            largestPolygonArea[id] = std::max(largestPolygonArea[id], polygons[p].area);
    Aabb region = scene.bounds();
    if (region.empty() || !region.finite())
        region = Aabb(Vec3(-1.0), Vec3(1.0));
    sceneSize = std::max(glm::length(region.extent()), 1e-9);
    if (options.coplanarUnions)
        for (OccluderPolygon& joined : coplanarUnions(polygons, sceneSize))
            polygons.push_back(std::move(joined));
    const Vec3 grow(0.05 * sceneSize);
    region = Aabb(region.min - grow, region.max + grow);
    OccluderSelectorOptions selection;
    selection.threshold = options.areaAngleThreshold;
    selector.build(polygons, region, selection);
    threshold = options.areaAngleThreshold;
    polygonBounds.clear();
    for (const OccluderPolygon& polygon : polygons)
        polygonBounds.push_back(boundsOf(polygon));
    prepared.resize(polygons.size());
    for (std::size_t p = 0; p < polygons.size(); ++p)
        prepareOccluder(polygons[p], prepared[p]);

    nodeCaches.assign(tree.nodes().size(), BoxOcclusionCache());
    objectCaches.assign(scene.objects.size(), BoxOcclusionCache());
    margins.assign(polygons.size(), 0.0);
    insertedAs.assign(polygons.size(), 0);
    sweptIn.assign(polygons.size(), 0);
    insertStamp = 0;
    changed.reset(scene.objects.size());
    dependents.build(polygons, scene.objects.size());
    statedFrom = scene.occluders;
    chooseFrontier(tree.empty() || tree.root().itemCount < options.parallelMinObjects ? 0 : 64);
    const std::size_t depth = treeDepth();
    serial.prepare(depth);
    for (FrontierTask& task : frontier)
        task.output.prepare(depth);
    frame = 0;
}

// The sweep tests an object by the convex hull of its vertices, far tighter than its box for a
// tilted shape. Only static objects (a dynamic one's triangles may lag its bounds) with their
// triangles kept and at most MaxPoints distinct vertices; the others are tested by their box.
void OctreeModule::Impl::collectObjectPoints(const Scene& scene)
{
    constexpr std::size_t MaxPoints = 256;
    objectPoints.clear();
    pointsFirst.assign(1, 0);
    std::vector<Vec3> points;
    for (const SceneObject& object : scene.objects)
    {
        points.clear();
        const bool kept = std::size_t(object.firstTriangle) + object.triangleCount <= scene.triangles.size();
        if (kept && (object.flags & OBJECT_DYNAMIC) == 0)
            for (std::uint32_t t = object.firstTriangle; t < object.firstTriangle + object.triangleCount; ++t)
            {
                const Triangle& triangle = scene.triangles[t];
                for (const Vec3f& v : {triangle.a, triangle.b, triangle.c})
                    points.push_back(Vec3(v));
            }
        std::sort(points.begin(), points.end(),
                  [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
        points.erase(std::unique(points.begin(), points.end()), points.end());
        if (points.size() <= MaxPoints &&
            std::all_of(points.begin(), points.end(),
                        [](const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }))
            objectPoints.insert(objectPoints.end(), points.begin(), points.end());
        pointsFirst.push_back(std::uint32_t(objectPoints.size()));
    }
}

// The frontier: up to `wanted` subtrees found by splitting the largest first, fixed for the
// scene so each keeps its index (and so its thread affinity) from frame to frame.
void OctreeModule::Impl::chooseFrontier(std::size_t wanted)
{
    frontierSlot.assign(tree.nodes().size(), -1);
    frontier.clear();
    if (wanted == 0)
        return;
    const std::vector<KdTree::Node>& nodes = tree.nodes();
    std::vector<std::uint32_t> open{0};
    while (open.size() < wanted)
    {
        const auto largest =
            std::max_element(open.begin(), open.end(),
                             [&](std::uint32_t a, std::uint32_t b) { return nodes[a].itemCount < nodes[b].itemCount; });
        if (nodes[*largest].leaf())
            break;
        const KdTree::Node split = nodes[*largest];
        *largest = split.left;
        open.push_back(split.right);
    }
    std::sort(open.begin(), open.end());
    frontier.resize(open.size());
    for (std::size_t i = 0; i < open.size(); ++i)
    {
        frontier[i].node = open[i];
        frontierSlot[open[i]] = static_cast<std::int32_t>(i);
    }
}

// Connected occluders: each group of partial occluders linked through shared edges is tried as
// one. Only polygons the box lies wholly behind can take part; leaving the others out only makes
// their shared edges count as silhouettes, which is the cautious side.
bool OctreeModule::Impl::fusedHidden(const Aabb& box, const std::vector<std::uint32_t>& partial, TraversalOutput& out)
{
    std::vector<std::uint32_t>& candidates = out.fusedCandidates;
    std::vector<const BoxOccluderPlanes*>& candidatePlanes = out.fusedCandidatePlanes;
    candidates.clear();
    candidatePlanes.clear();
    for (std::size_t i = 0; i < partial.size(); ++i)
        if (out.partialPlanes[i]->boxSide != 0 && depthSeparated(polygons[partial[i]], box))
        {
            candidates.push_back(partial[i]);
            candidatePlanes.push_back(out.partialPlanes[i]);
        }

    std::vector<std::uint8_t>& taken = out.fusedTaken;
    taken.assign(candidates.size(), 0);
    for (std::size_t seed = 0; seed < candidates.size(); ++seed)
    {
        if (taken[seed])
            continue;
        // Grow the group of candidates reachable from `seed` through neighbour links.
        std::vector<std::uint32_t>& group = out.fusedGroup;
        std::vector<std::size_t>& members = out.fusedMembers;
        group.assign(1, candidates[seed]);
        members.assign(1, seed);
        taken[seed] = 1;
        for (std::size_t g = 0; g < members.size(); ++g)
            for (std::uint32_t neighbour : polygons[candidates[members[g]]].neighbours)
                for (std::size_t c = 0; c < candidates.size(); ++c)
                    if (!taken[c] && candidates[c] == neighbour)
                    {
                        taken[c] = 1;
                        members.push_back(c);
                        group.push_back(candidates[c]);
                    }
        if (group.size() < 2)
            continue;
        out.fusedPlanes.resize(members.size());
        double margin = 0.0;
        for (std::size_t g = 0; g < members.size(); ++g)
        {
            out.fusedPlanes[g] = *candidatePlanes[members[g]];
            margin = std::max(margin, margins[group[g]]);
        }
        if (fusedInvisible(polygons, group, out.fusedPlanes, eyes, margin))
            return true;
    }
    return false;
}

// The k best potential occluders of the eye's cell by area-angle, among those the renderer draws
// where they would hide something: inside the view frustum and wholly beyond the near plane (a
// polygon cut by the near plane is clipped away exactly where it would hide things).
void OctreeModule::Impl::chooseOccluders(const View& view, std::uint32_t k)
{
    const Plane& nearPlane = view.frustum.plane(Frustum::NEAR);
    chooseBest(k,
               [&](std::uint32_t o)
               {
                   const OccluderPolygon& polygon = polygons[o];
                   const bool beyondNear = std::all_of(polygon.vertices.begin(), polygon.vertices.end(),
                                                       [&](const Vec3& v) { return nearPlane.distance(v) > 0.0; });
                   return beyondNear && view.frustum.classify(polygonBounds[o]) != Containment::Outside;
               });
}

// Every direction counts, so no frustum test; a polygon is kept only when no eye of the region
// comes within the near plane's reach of its plane (a view may clip it wherever it looks).
void OctreeModule::Impl::chooseRegionOccluders(const ViewRegion& region, std::uint32_t k)
{
    chooseBest(k,
               [&](std::uint32_t o)
               {
                   const Plane& plane = polygons[o].plane;
                   return std::abs(plane.distance(eye)) - eyes.spread(plane.normal) > region.maxNearReach;
               });
}

// The k potential occluders of the eye's cell with the largest area-angle that `usable` accepts.
template <class Usable> void OctreeModule::Impl::chooseBest(std::uint32_t k, Usable usable)
{
    ranked.clear();
    const std::uint32_t leaf = selector.leafOf(eye);
    const std::vector<std::uint32_t>& candidates = selector.potentialOccluders(leaf);
    const std::vector<double>& bounds = selector.potentialOccluderBounds(leaf);
    for (std::size_t i = 0; i < candidates.size(); ++i)
    {
        // The list is ordered by a bound of the metric: nothing further down can enter the k best.
        if (!bounds.empty() &&
            (bounds[i] < threshold || (k > 0 && ranked.size() == k && bounds[i] < ranked.back().first)))
            break;
        const std::uint32_t o = candidates[i];
        const double metric = areaAngle(polygons[o], eye);
        // Worse than the k-th best (a larger metric, or an equal one and a lower index, is better).
        const bool worse = ranked.size() >= k && (k == 0 || metric < ranked.back().first ||
                                                  (metric == ranked.back().first && o > ranked.back().second));
        if (metric < threshold || worse || dependents.disabled(o) || !usable(o))
            continue;
        rank(o, metric, k);
    }
    activateRanked();
}

// Insertion into the best-first list; ties keep the lower index first.
void OctreeModule::Impl::rank(std::uint32_t o, double metric, std::uint32_t k)
{
    auto at = std::upper_bound(ranked.begin(), ranked.end(), std::make_pair(metric, o),
                               [](const auto& a, const auto& b)
                               { return a.first > b.first || (a.first == b.first && a.second < b.second); });
    ranked.insert(at, {metric, o});
    if (ranked.size() > k)
        ranked.pop_back();
}

void OctreeModule::Impl::activateRanked()
{
    for (const auto& [metric, o] : ranked)
    {
        margins[o] = marginOf(polygons[o]);
        active.push_back(o);
        if (eyes.halfExtent == Vec3(0.0))
            shadows.add(o, polygons[o], eye, margins[o]);
    }
}

// How far every deciding plane must clear the eyes: rasterization rounds the occluder's edges.
double OctreeModule::Impl::marginOf(const OccluderPolygon& polygon) const
{
    const double volumeReach = glm::length(eyes.halfExtent);
    double reach = 0.0;
    for (const Vec3& v : polygon.vertices)
        reach = std::max(reach, glm::length(v - eye) + volumeReach);
    return 1e-6 * sceneSize + AngularMargin * reach;
}

std::size_t OctreeModule::Impl::treeDepth() const
{
    if (tree.empty())
        return 0;
    std::size_t deepest = 0;
    std::vector<std::pair<std::uint32_t, std::size_t>> open{{0, 0}};
    while (!open.empty())
    {
        const auto [index, depth] = open.back();
        open.pop_back();
        deepest = std::max(deepest, depth);
        const KdTree::Node& node = tree.nodes()[index];
        if (!node.leaf())
        {
            open.push_back({node.left, depth + 1});
            open.push_back({node.right, depth + 1});
        }
    }
    return deepest;
}

bool OctreeModule::Impl::depthSeparated(const OccluderPolygon& polygon, const Aabb& box) const
{
    const double eyeSide = polygon.plane.distance(eye) > 0.0 ? 1.0 : -1.0;
    double behind = std::numeric_limits<double>::max();
    for (int c = 0; c < 8; ++c)
        behind = std::min(behind, -eyeSide * polygon.plane.distance(box.corner(c)));
    return behind > depthTolerance(box);
}

// How far behind an occluder a box must lie so that 24-bit depth cannot let it z-fight through.
double OctreeModule::Impl::depthTolerance(const Aabb& box) const
{
    double farthest = 0.0;
    for (int c = 0; c < 8; ++c)
        farthest = std::max(farthest, glm::length(box.corner(c) - eye));
    farthest += glm::length(eyes.halfExtent);
    return farthest * farthest / (nearDistance * DepthResolution) + 1e-6 * sceneSize;
}

Occlusion OctreeModule::Impl::testBox(BoxOcclusionCache& cache, const Aabb& box,
                                      const std::vector<std::uint32_t>& occluders, bool fuse,
                                      std::vector<std::uint32_t>& partial, TraversalOutput& out)
{
    partial.clear();
    out.partialPlanes.clear();
    bool computed = false;
    const auto hiddenBy = [&](std::uint32_t o, const BoxOccluderPlanes& planes)
    {
        ++out.statistics.planeTests;
        return classify(polygons[o], planes, eyes, margins[o]);
    };

    // Coherence: the occluder that hid this box last frame usually still does.
    if (cache.decidedBy != NoDecider && cache.decidedBy != FusedDecider &&
        std::find(occluders.begin(), occluders.end(), cache.decidedBy) != occluders.end())
    {
        const std::uint32_t o = cache.decidedBy;
        const BoxOccluderPlanes& planes = cache.planesFor(o, prepared[o], box, frame, computed);
        if (hiddenBy(o, planes) == Occlusion::Invisible && depthSeparated(polygons[o], box))
        {
            ++out.statistics.cachedDecisions;
            return Occlusion::Invisible;
        }
    }

    for (std::uint32_t o : occluders)
    {
        if (shadows.misses(o, box))
            continue; // hides none of the box: Visible, without its planes
        const BoxOccluderPlanes& planes = cache.planesFor(o, prepared[o], box, frame, computed);
        if (!computed)
            ++out.statistics.cachedDecisions;
        const Occlusion c = hiddenBy(o, planes);
        if (c == Occlusion::Invisible && depthSeparated(polygons[o], box))
        {
            cache.decidedBy = o;
            return Occlusion::Invisible;
        }
        if (c != Occlusion::Visible)
        {
            partial.push_back(o);
            out.partialPlanes.push_back(&planes);
        }
    }

    if (fuse && partial.size() >= 2 && fusedHidden(box, partial, out))
    {
        cache.decidedBy = FusedDecider;
        return Occlusion::Invisible;
    }
    cache.decidedBy = NoDecider;
    return partial.empty() ? Occlusion::Visible : Occlusion::Partial;
}

// The objects items[range] one by one, against the frustum and the occluders that partly hid their node.
void OctreeModule::Impl::testObjects(const Scene& scene, const OctreeOptions& options,
                                     const std::vector<std::uint32_t>& items, Range range, unsigned planeMask,
                                     const std::vector<std::uint32_t>& partial, std::vector<std::uint32_t>& objectPartial,
                                     std::uint32_t depth, TraversalOutput& out)
{
    for (std::uint32_t i = range.first; i < range.first + range.count; ++i)
    {
        if (changed.changed(items[i]))
            continue; // testMoved's
        const bool occludersDecide = !out.deciding(partial).empty();
        const Aabb& bounds = scene.objects[items[i]].bounds;
        unsigned objectMask = planeMask;
        NodeState state = NodeState::Visible;
        if (frustum->classify(bounds, objectMask) == Containment::Outside)
            state = NodeState::OutsideFrustum;
        else if (occludersDecide && testBox(objectCaches[items[i]], bounds, partial, options.fuseConnected,
                                             objectPartial, out) == Occlusion::Invisible)
            state = NodeState::Invisible;
        if (state != NodeState::Visible)
            out.culled.push_back({i, 1});
        if (debug) // objects show the finest decisions made
            out.debugNodes.push_back({bounds, state, depth});
    }
}

void OctreeModule::Impl::traverse(const Scene& scene, const OctreeOptions& options, std::uint32_t nodeIndex,
                                  std::uint32_t depth, unsigned planeMask, const std::vector<std::uint32_t>& candidates,
                                  TraversalOutput& out, bool stopAtFrontier)
{
    const KdTree::Node& node = tree.nodes()[nodeIndex];
    if (stopAtFrontier && frontierSlot[nodeIndex] >= 0)
    {
        FrontierTask& task = frontier[std::size_t(frontierSlot[nodeIndex])];
        task.active = true;
        task.depth = depth;
        task.planeMask = planeMask;
        task.occluders = candidates;
        return;
    }
    const std::vector<std::uint32_t>& occluders = out.deciding(candidates);
    ++out.statistics.nodesVisited;
    const auto record = [&](NodeState state)
    {
        if (debug)
            out.debugNodes.push_back({node.bounds, state, depth});
    };

    // Lazy frustum culling: a node outside is dropped with its caches untouched.
    const Containment inFrustum = frustum->classify(node.bounds, planeMask);
    if (inFrustum == Containment::Outside)
    {
        ++out.statistics.nodesOutsideFrustum;
        out.culled.push_back({node.firstItem, node.itemCount});
        record(NodeState::OutsideFrustum);
        return;
    }

    std::vector<std::uint32_t>& partial = out.list(depth);
    if (!occluders.empty() && testBox(nodeCaches[nodeIndex], node.bounds, occluders, options.fuseConnected, partial,
                                      out) == Occlusion::Invisible)
    {
        ++out.statistics.nodesInvisible;
        out.culled.push_back({node.firstItem, node.itemCount});
        record(NodeState::Invisible);
        return;
    }
    if (occluders.empty())
        partial.clear();
    if (partial.empty() && inFrustum == Containment::Inside)
    {
        record(NodeState::Visible); // nothing below can be culled any more
        return;
    }

    if (node.leaf())
    {
        testObjects(scene, options, tree.items(), {node.firstItem, node.itemCount}, planeMask, partial,
                    out.list(depth + 1), depth + 1, out);
        return;
    }
    traverse(scene, options, node.left, depth + 1, planeMask, partial, out, stopAtFrontier);
    traverse(scene, options, node.right, depth + 1, planeMask, out.list(depth), out, stopAtFrontier);
}

OctreeModule::OctreeModule(const OctreeOptions& options) : _options(options), _impl(std::make_unique<Impl>())
{
    _options.occluders = std::min<std::uint32_t>(_options.occluders, std::uint32_t(BoxOcclusionCache::MaxRelations));
}

OctreeModule::~OctreeModule() = default;

const char* OctreeModule::name() const
{
    if (!_options.fuseConnected)
        return "octree-single";
    return _options.fuseDisjoint ? "octree" : "octree-paper";
}

void OctreeModule::setScene(const Scene& scene)
{
    _scene = &scene;
    _impl->build(scene, _options);
}

void OctreeModule::setDebugRecord(DebugRecord* record)
{
    _impl->debug = record;
}

OctreeModule::Statistics OctreeModule::lastStatistics() const
{
    return _impl->statistics;
}

bool OctreeModule::walksSceneHierarchy() const
{
    return _impl->sceneHierarchy.walks();
}

const std::string& OctreeModule::hierarchyProblem() const
{
    return _impl->sceneHierarchy.problem();
}

void OctreeModule::Impl::beginQuery(const OctreeOptions& options, const Vec3& center, const Vec3& halfExtent)
{
    ++frame;
    eye = center;
    eyes = EyeVolume{center, halfExtent};
    statistics = Statistics();
    if (debug)
        debug->clear();
    if (!options.temporalCoherence)
    {
        for (BoxOcclusionCache& cache : nodeCaches)
            cache.clear();
        for (BoxOcclusionCache& cache : objectCaches)
            cache.clear();
        for (BoxOcclusionCache& cache : hierarchyCaches)
            cache.clear();
    }
    active.clear();
    shadows.begin(polygons.size());
}

void OctreeModule::cull(const View& view, VisibleSet& visible)
{
    Impl& m = *_impl;
    if (!_scene || !m.hasObjects())
        return;
    m.beginQuery(_options, view.eye, Vec3(0.0));
    m.frustum = &view.frustum;
    m.rootPlaneMask = 0x3Fu;

    // Occluders need a point eye: orthographic views and a broken eye get frustum culling only.
    const bool pointEye =
        !view.orthographic && std::isfinite(m.eye.x) && std::isfinite(m.eye.y) && std::isfinite(m.eye.z);
    m.nearDistance = nearDistance(view);
    if (pointEye && m.nearDistance > 0.0 && !m.polygons.empty())
        m.chooseOccluders(view, _options.occluders);
    m.traverseAll(*_scene, _options, visible);
    m.testMoved(*_scene, _options, visible);
    if (_options.fuseDisjoint && pointEye && m.nearDistance > 0.0 && !m.polygons.empty())
        m.sweep(*_scene, view, _options, visible);

    if (m.debug)
    {
        m.debug->nodes = m.serial.debugNodes;
        for (std::uint32_t o : m.active)
            m.debug->activeOccluders.push_back(m.polygons[o].vertices);
        m.debug->eyeCell = m.selector.leafBounds(m.selector.leafOf(m.eye));
    }
}

void OctreeModule::cullRegion(const ViewRegion& region, VisibleSet& visible)
{
    Impl& m = *_impl;
    if (!_scene || !m.hasObjects())
        return;
    const Vec3 center = region.center();
    m.beginQuery(_options, center, region.halfExtent());
    static const Frustum everywhere; // never consulted: the root plane mask is empty
    m.frustum = &everywhere;
    m.rootPlaneMask = 0u;
    m.nearDistance = region.minNearDistance;
    const bool finite = !region.eyes.empty() && region.eyes.finite();
    if (finite && m.nearDistance > 0.0 && !m.polygons.empty())
    {
        // Looking every way, a region spends the most occluders a box's cache can relate to.
        m.chooseRegionOccluders(region, std::uint32_t(BoxOcclusionCache::MaxRelations));
    }
    m.traverseAll(*_scene, _options, visible);
    m.testMoved(*_scene, _options, visible);
    if (m.debug)
        m.debug->nodes = m.serial.debugNodes;
}

// Serial top, parallel frontier subtrees, each with its own output; merged in slot order.
void OctreeModule::Impl::traverseAll(const Scene& scene, const OctreeOptions& options, VisibleSet& visible)
{
    statistics.activeOccluders = static_cast<std::uint32_t>(active.size());
    for (FrontierTask& task : frontier)
        task.active = false;
    serial.culled.clear();
    serial.debugNodes.clear();
    serial.statistics = Statistics();
    serial.work = 0;
    serial.budget = options.workBudget == 0 ? ~std::uint64_t(0) : options.workBudget / 5 * 3;
    if (sceneHierarchy.walks())
    {
        traverseHierarchy(scene, options);
        applyCulled(serial, sceneHierarchy.index().objects(), visible);
        return;
    }
    // A budget is spent in one fixed order, so that the same objects stay undecided at every
    // thread count.
    const bool parallel = !frontier.empty() && !debug && options.workBudget == 0;
    traverse(scene, options, 0, 0, rootPlaneMask, active, serial, parallel);
    if (parallel)
    {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, frontier.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range)
            {
                for (std::size_t i = range.begin(); i != range.end(); ++i)
                {
                    FrontierTask& task = frontier[i];
                    task.output.culled.clear();
                    task.output.statistics = Statistics();
                    task.output.work = 0;
                    if (task.active)
                        traverse(scene, options, task.node, task.depth, task.planeMask, task.occluders, task.output,
                                 false);
                }
            },
            affinity);
    }

    applyCulled(serial, tree.items(), visible);
    if (parallel)
        for (FrontierTask& task : frontier)
            if (task.active)
                applyCulled(task.output, tree.items(), visible);
}

void OctreeModule::Impl::applyCulled(const TraversalOutput& out, const std::vector<std::uint32_t>& items,
                                     VisibleSet& visible)
{
    for (const Range& r : out.culled)
        for (std::uint32_t i = r.first; i < r.first + r.count; ++i)
            if (visible.test(items[i]) && !changed.changed(items[i])) // changed: testMoved's
                visible.clear(items[i]);
    const Statistics& s = out.statistics;
    statistics.nodesVisited += s.nodesVisited;
    statistics.nodesInvisible += s.nodesInvisible;
    statistics.nodesOutsideFrustum += s.nodesOutsideFrustum;
    statistics.planeTests += s.planeTests;
    statistics.cachedDecisions += s.cachedDecisions;
    statistics.nodesStrayed += s.nodesStrayed;
    statistics.traversalWork += out.work;
    statistics.overBudget = statistics.overBudget || s.overBudget;
}

// The renderer's traversal, with the tests of `traverse` on the recorded nodes. Its order does not
// matter (each box is tested on its own), so siblings are accepted in any order; a node that
// differs from the recorded one is kept with everything below it. Ranges index the hierarchy
// index's objects(), where a node's held objects come first and its subtree's follow.
void OctreeModule::Impl::traverseHierarchy(const Scene& scene, const OctreeOptions& options)
{
    TraversalOutput& out = serial;
    const std::vector<ObjectId>& items = sceneHierarchy.index().objects();
    std::vector<unsigned>& planeMasks = hierarchyPlaneMasks; // kept between culls: no allocation once warm
    hierarchyDepth = 0;
    // Returns whether to go below the node.
    auto visit = [&](const HierarchyNode& node, const HierarchyIndex::Node& n, std::size_t walkDepth) -> bool
    {
        const std::uint32_t depth = std::uint32_t(walkDepth);
        if (n.contents.empty())
            return false;
        hierarchyDepth = std::max(hierarchyDepth, depth);
        if (out.lists.size() < depth + 2)
            out.lists.resize(depth + 2);
        if (planeMasks.size() < depth + 1)
            planeMasks.resize(depth + 1);
        const std::vector<std::uint32_t>& candidates = depth == 0 ? active : out.lists[depth - 1];
        unsigned planeMask = depth == 0 ? rootPlaneMask : planeMasks[depth - 1];
        const std::vector<std::uint32_t>& occluders = out.deciding(candidates);
        ++out.statistics.nodesVisited;
        const auto record = [&](const Aabb& box, NodeState state, std::uint32_t at)
        {
            if (debug)
                out.debugNodes.push_back({box, state, at});
        };
        const Range subtree{n.firstObject, n.subtreeEnd - n.firstObject};
        const Containment inFrustum = frustum->classify(n.contents, planeMask);
        if (inFrustum == Containment::Outside)
        {
            ++out.statistics.nodesOutsideFrustum;
            out.culled.push_back(subtree);
            record(n.contents, NodeState::OutsideFrustum, depth);
            return false;
        }
        std::vector<std::uint32_t>& partial = out.lists[depth];
        if (!occluders.empty() && testBox(hierarchyCaches[node.id], n.contents, occluders, options.fuseConnected,
                                          partial, out) == Occlusion::Invisible)
        {
            ++out.statistics.nodesInvisible;
            out.culled.push_back(subtree);
            record(n.contents, NodeState::Invisible, depth);
            return false;
        }
        if (occluders.empty())
            partial.clear();
        if (partial.empty() && inFrustum == Containment::Inside)
        {
            record(n.contents, NodeState::Visible, depth); // nothing below can be culled any more
            return false;
        }
        // lists[depth + 1] is scratch here, before the children use it.
        testObjects(scene, options, items, {n.firstObject, n.heldCount}, planeMask, partial, out.lists[depth + 1],
                    depth + 1, out);
        if (n.subtreeEnd == n.firstObject + n.heldCount)
            return false; // nothing held below
        planeMasks[depth] = planeMask;
        return true;
    };
    sceneHierarchy.traverse(eye, visit, [&]() { ++out.statistics.nodesStrayed; });
}
} // namespace osgVis::core
