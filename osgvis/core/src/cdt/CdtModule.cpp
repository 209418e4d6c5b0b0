// SPDX-License-Identifier: MIT
// Luka, "Visibility culling with a constrained Delaunay triangulation": the front-to-back kd-tree
// traversal of §2.2.4 over the occlusion record of §2.2.1-§2.2.3 (cdt/CoverageTriangulation.h),
// with the rules of §2.3.1 for which occluders may count. docs/cdt.md says why each step is safe.
#include <osgVis/core/cdt/CdtModule.h>
#include <osgVis/core/cdt/CoverageTriangulation.h>
#include <osgVis/core/module/ChangedObjects.h>
#include <osgVis/core/occluders/OccluderBuilder.h>
#include <osgVis/core/occluders/OccluderDependents.h>

#include <osgVis/core/spatial/DisjointCellTree.h>
#include <osgVis/core/spatial/SceneHierarchyChoice.h>

#include "ScreenGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

namespace osgVis::core
{
namespace
{
struct EdgeKey
{
    Vec3 a, b;
    bool operator==(const EdgeKey& o) const { return a == o.a && b == o.b; }
};
struct EdgeKeyHash
{
    std::size_t operator()(const EdgeKey& k) const
    {
        std::size_t h = 1469598103934665603ull;
        for (double v : {k.a.x, k.a.y, k.a.z, k.b.x, k.b.y, k.b.z})
            h = (h ^ std::hash<double>()(v)) * 1099511628211ull;
        return h;
    }
};

enum class Drawn : std::uint8_t
{
    Untested,
    Visible,
    Hidden,
};

} // namespace

struct CdtModule::Impl
{
    DisjointCellTree ownTree;
    const TraversalHierarchy* hierarchy = nullptr; ///< ownTree or the scene's
    /// The renderer's hierarchy when taken; its index records whichever of the two is walked. The
    /// walk keeps front-to-back order: cover drawn in an earlier region hides later ones.
    SceneHierarchyChoice sceneHierarchy{true};
    std::vector<OccluderPolygon> polygons;
    std::vector<Aabb> polygonBounds;
    /// Per polygon, per edge: the polygons with exactly that edge (same end points, opposite
    /// direction); one lying across it on screen and drawn closes the edge without a crack.
    std::vector<std::vector<std::vector<std::uint32_t>>> twins;
    std::vector<std::vector<std::uint32_t>> polygonsOf; ///< per object
    /// Since setScene: changed objects are left out of the walk and tested after it, and no polygon
    /// resting on one is drawn.
    ChangedObjects changed;
    OccluderDependents dependents;
    std::vector<OccluderCandidate> statedFrom; ///< the stated occluders built from
    std::vector<std::uint32_t> statedPolygons;          ///< owner InvalidObject

    // Per frame.
    cdt::CoverageTriangulation record;
    ScreenGrid grid;
    View view;
    std::vector<Drawn> drawn;
    /// Per polygon this frame: the cover kinds it was drawn with (bit 1 << kind), and whether an
    /// edge was eroded only because its twin's object was not tested yet (drawn again once it is).
    std::vector<std::uint8_t> drawnKinds, waitsForTwin;
    std::vector<bool> keep;
    GridPolygon projected;
    std::vector<cdt::GridPoint> outline;
    /// Per tree depth (an inner node's list must outlive its children's): the node's objects by distance.
    std::vector<std::vector<std::pair<double, ObjectId>>> orderScratch = std::vector<std::vector<std::pair<double, ObjectId>>>(64);
    Statistics stats;
    std::uint32_t testsLeft = 0;
    bool unlimitedTests = true;

    /// Clears the per-frame state for a new view (grid set already).
    void beginFrame(const CdtOptions& options);
    struct Frame;
};

CdtModule::CdtModule(const CdtOptions& options) : _options(options), _impl(std::make_unique<Impl>()) {}
CdtModule::~CdtModule() = default;

const char* CdtModule::name() const
{
    switch (_options.rule)
    {
    case CdtOptions::Rule::DepthFree:
        return "cdt-depthfree";
    case CdtOptions::Rule::DepthOnly:
        return "cdt-depth";
    default:
        return "cdt";
    }
}

void CdtModule::setScene(const Scene& scene)
{
    _scene = &scene;
    Impl& m = *_impl;
    std::vector<Aabb> bounds(scene.objects.size());
    std::vector<bool> present(scene.objects.size(), true);
    for (const SceneObject& object : scene.objects)
    {
        bounds[object.id] = object.bounds;
        present[object.id] = !(object.flags & OBJECT_ALWAYS_VISIBLE);
    }
    // The renderer's hierarchy when it passes the checks, else a kd-tree of our own.
    m.sceneHierarchy.choose(scene, _options.sceneHierarchy);
    m.hierarchy = m.sceneHierarchy.hierarchy();
    m.ownTree = {};
    if (!m.hierarchy)
    {
        m.ownTree.build(bounds, present, _options.maxLeafObjects);
        m.sceneHierarchy.indexOwnTree(m.ownTree, scene);
        m.hierarchy = &m.ownTree;
    }

    m.polygons = buildOccluderPolygons(scene);
    m.polygonBounds.assign(m.polygons.size(), Aabb{});
    m.twins.assign(m.polygons.size(), {});
    std::unordered_multimap<EdgeKey, std::uint32_t, EdgeKeyHash> edges;
    m.polygonsOf.assign(scene.objects.size(), {});
    m.statedPolygons.clear();
    for (std::uint32_t i = 0; i < m.polygons.size(); ++i)
    {
        const OccluderPolygon& p = m.polygons[i];
        for (const Vec3& v : p.vertices)
            m.polygonBounds[i].expand(v);
        for (std::size_t e = 0; e < p.vertices.size(); ++e)
            edges.emplace(EdgeKey{p.vertices[e], p.vertices[(e + 1) % p.vertices.size()]}, i);
        if (p.owner == InvalidObject)
            m.statedPolygons.push_back(i);
        else if (p.owner < m.polygonsOf.size())
            m.polygonsOf[p.owner].push_back(i);
    }
    // Twins: every polygon that has the same edge in the opposite direction (a face's back-side
    // copy has it in the same direction, a neighbour across a fold too: which of them may stand
    // for the sliver along the edge is decided per view).
    for (std::uint32_t i = 0; i < m.polygons.size(); ++i)
    {
        const OccluderPolygon& p = m.polygons[i];
        const std::size_t n = p.vertices.size();
        m.twins[i].assign(n, {});
        if (p.insideSolid)
            continue;
        for (std::size_t e = 0; e < n; ++e)
        {
            const auto [first, last] = edges.equal_range(EdgeKey{p.vertices[(e + 1) % n], p.vertices[e]});
            for (auto it = first; it != last; ++it)
                if (it->second != i && !m.polygons[it->second].insideSolid)
                    m.twins[i][e].push_back(it->second);
        }
    }
    m.drawn.assign(scene.objects.size(), Drawn::Untested);
    m.changed.reset(scene.objects.size());
    m.dependents.build(m.polygons, scene.objects.size());
    m.statedFrom = scene.occluders;
}

void CdtModule::sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes)
{
    Impl& m = *_impl;
    const auto nothing = [](ObjectId) {};
    if (!_scene || !sameOccluderCandidates(scene.occluders, m.statedFrom) ||
        !m.changed.apply(scene.objects.size(), changes, [&](ObjectId id) { m.dependents.disableAll(id); }, nothing))
    {
        setScene(scene);
        return;
    }
    _scene = &scene;
    // Objects inserted since setScene own no polygon.
    m.drawn.resize(std::max(m.drawn.size(), scene.objects.size()), Drawn::Untested);
    m.polygonsOf.resize(std::max(m.polygonsOf.size(), scene.objects.size()));
}

namespace
{
/// True when the GPU draws the polygon for this eye (face culling) and it may stand for what it
/// covers (a section inside a solid hides only from outside that solid).
bool facesEye(const OccluderPolygon& p, const Scene& scene, const Vec3& eye)
{
    if (p.oneSided && p.plane.distance(eye) <= 0.0)
        return false;
    if (p.insideSolid && p.owner < scene.objects.size() && scene.objects[p.owner].bounds.contains(eye))
        return false;
    return true;
}
} // namespace

void CdtModule::Impl::beginFrame(const CdtOptions& options)
{
    const std::int32_t limit = grid.limit();
    record.reset(-limit, -limit, limit, limit);
    record.setConstraintBudget(0); // budgeted here, whole occluders at a time
    std::fill(drawn.begin(), drawn.end(), Drawn::Untested);
    drawnKinds.assign(polygons.size(), 0);
    waitsForTwin.assign(polygons.size(), 0);
    unlimitedTests = options.testBudget == 0;
    testsLeft = options.testBudget;
}

/// One call of cull: the state its phases share, and the phases. It is the traversal's visitor.
struct CdtModule::Impl::Frame final : HierarchyVisitor
{
    Frame(Impl& module, const CdtOptions& cullOptions, DebugRecord* debugRecord, const Scene& frameScene,
          const View& frameView, VisibleSet& frameVisible)
        : m(module), options(cullOptions), debug(debugRecord), scene(frameScene), view(frameView),
          visible(frameVisible), margin(module.grid.depthMargin()),
          depthOnly(cullOptions.rule == CdtOptions::Rule::DepthOnly ||
                    module.sceneHierarchy.index().layout() == HierarchyLayout::Overlapping),
          index(module.sceneHierarchy.index()), walk(module.sceneHierarchy.walk(frameView.eye))
    {
    }

    Impl& m;
    const CdtOptions& options;
    DebugRecord* debug;
    const Scene& scene;
    const View& view;
    VisibleSet& visible;
    const double margin;
    // Over overlapping nodes front to back orders nothing along rays: depth is all that separates.
    const bool depthOnly;
    // The index of the hierarchy walked (the renderer's or ownTree) and the module's walk over it,
    // whose buffers last from frame to frame.
    const HierarchyIndex& index;
    HierarchyIndex::Walk& walk;
    bool stopped = false; // the test budget ran out, or the traversal strayed: nothing more is culled
    // Per depth of the walk: the node entered there and its objects by distance (an inner node's
    // list must outlive its children's).
    std::vector<const HierarchyIndex::Node*> entered;

    void debugNode(const Aabb& bounds, NodeState state, std::size_t depth);
    bool allowTest();
    bool boxHidden(const Aabb& box, cdt::QueryMode mode = cdt::QueryMode::DepthFree);
    void drawPolygon(std::uint32_t index, cdt::CoverKind kind);
    bool keepSharedEdges(std::uint32_t index);
    void insertProjected(std::uint32_t index, cdt::CoverKind kind, bool waits);
    void redrawTwinsOf(ObjectId id);
    void drawObject(ObjectId id, const Aabb* cell);
    void cullSubtree(const HierarchyIndex::Node& n);
    bool enter(const HierarchyNode& node) override;
    void leave(const HierarchyNode& node) override;
    bool skip();
    bool nodeCulled(const HierarchyIndex::Node& n, std::size_t depth);
    std::vector<std::pair<double, ObjectId>>& heldObjectsByDistance(const HierarchyIndex::Node& n, std::size_t depth);
    bool testHeldObjects(const HierarchyIndex::Node& n, const std::vector<std::pair<double, ObjectId>>& order);
    void testObject(ObjectId id, const HierarchyIndex::Node& n);
    void testMoved();
};

// Objects moved or inserted since setScene, after the walk: against the frustum and what was drawn
// with a depth bound. Depth-free cover says only that what the walk meets later lies behind it,
// and a moved object may lie anywhere. They are never drawn themselves.
void CdtModule::Impl::Frame::testMoved()
{
    for (ObjectId id : m.changed.moved())
    {
        if (stopped || !visible.test(id) || (scene.objects[id].flags & OBJECT_ALWAYS_VISIBLE) != 0)
            continue;
        if (!allowTest())
            return;
        ++m.stats.changedTested;
        const Aabb& b = scene.objects[id].bounds;
        if (view.frustum.classify(b) == Containment::Outside || boxHidden(b, cdt::QueryMode::DepthOnly))
            visible.clear(id);
    }
}

void CdtModule::Impl::Frame::debugNode(const Aabb& bounds, NodeState state, std::size_t depth)
{
    if (debug)
        debug->nodes.push_back({bounds, state, std::uint32_t(depth)});
}

bool CdtModule::Impl::Frame::allowTest()
{
    if (m.unlimitedTests)
        return true;
    if (m.testsLeft == 0)
    {
        m.stats.testBudgetReached = true;
        return false;
    }
    --m.testsLeft;
    return true;
}

// Hidden behind what the record holds (Outside the frustum counts as hidden too).
bool CdtModule::Impl::Frame::boxHidden(const Aabb& box, cdt::QueryMode mode)
{
    if (view.frustum.classify(box) == Containment::Outside)
        return true;
    double nearestW = 0.0;
    if (!m.grid.projectBox(box, m.outline, nearestW))
        return false;

    return m.record.hidden(m.outline.data(), m.outline.size(), mode, nearestW + margin);
}

void CdtModule::Impl::Frame::drawPolygon(std::uint32_t index, cdt::CoverKind kind)
{
    const OccluderPolygon& p = m.polygons[index];
    if (m.dependents.disabled(index) || !facesEye(p, scene, view.eye))
        return;
    for (ObjectId part : p.parts)
        if (part >= m.drawn.size() || m.drawn[part] != Drawn::Visible)
            return;
    const bool waits = keepSharedEdges(index);
    if (!m.grid.projectOccluder(p.vertices, &m.keep, m.projected))
        return;
    if (kind == cdt::CoverKind::DepthOnly && !m.projected.nearness.valid)
        return;
    // Where cover that needs no depth already lies, another occluder adds nothing: every query
    // there is answered hidden already (queries in this traversal all accept depth-free cover).
    if (m.record.hidden(m.projected.points.data(), m.projected.points.size(), cdt::QueryMode::DepthFree))
    {
        ++m.stats.occludersAlreadyCovered;
        return;
    }
    insertProjected(index, kind, waits);
}

/// Sets m.keep: per edge of the polygon, whether a drawn twin closes it. True when an edge is
/// eroded only because its twin's object was not tested yet.
bool CdtModule::Impl::Frame::keepSharedEdges(std::uint32_t index)
{
    const OccluderPolygon& p = m.polygons[index];
    const std::size_t n = p.vertices.size();
    m.keep.assign(n, false);
    bool waits = false;
    for (std::size_t e = 0; e < n; ++e)
    {
        // The pair draws watertight only where the twin lies across the edge on screen; one
        // folded onto this side leaves the snapping sliver along the edge uncovered.
        const Vec3& a = p.vertices[e];
        const Vec3& b = p.vertices[(e + 1) % n];
        const int mine = m.twins[index][e].empty() ? 0 : m.grid.sideOf(a, b, p.centroid);
        for (std::uint32_t twin : m.twins[index][e])
        {
            if (mine == 0 || m.keep[e])
                break;
            const OccluderPolygon& other = m.polygons[twin];
            if (m.dependents.disabled(twin))
                continue; // rests on a changed object: never drawn
            if (m.grid.sideOf(a, b, other.centroid) != -mine || !facesEye(other, scene, view.eye))
                continue;
            bool drawnNow = other.owner < m.drawn.size() && m.drawn[other.owner] == Drawn::Visible;
            bool untested = other.owner < m.drawn.size() && m.drawn[other.owner] == Drawn::Untested;
            for (ObjectId part : other.parts)
            {
                drawnNow = drawnNow && part < m.drawn.size() && m.drawn[part] == Drawn::Visible;
                untested = untested || (part < m.drawn.size() && m.drawn[part] == Drawn::Untested);
            }
            m.keep[e] = drawnNow;
            waits = waits || (!drawnNow && untested);
        }
    }
    return waits;
}

/// Inserts m.projected, the projection of polygon `index`, into the record unless it would pass
/// the constraint budget.
void CdtModule::Impl::Frame::insertProjected(std::uint32_t index, cdt::CoverKind kind, bool waits)
{
    const std::uint32_t edges = std::uint32_t(m.projected.points.size());
    if (options.constraintBudget != 0 && m.stats.constraintEdges + edges > options.constraintBudget)
    {
        ++m.stats.occludersOverBudget;
        return;
    }
    if (m.record.insertOccluder(m.projected.points.data(), m.projected.points.size(), kind, m.projected.nearness))
    {
        ++m.stats.occludersDrawn;
        m.drawnKinds[index] |= std::uint8_t(1u << unsigned(kind));
        m.waitsForTwin[index] = waits;
        if (debug)
            debug->activeOccluders.push_back(m.polygons[index].vertices);
        m.stats.constraintEdges += edges;
        for (bool k : m.keep)
            m.stats.sharedEdgesKept += k ? 1u : 0u;
    }
}

// A polygon drawn before this object was found visible eroded the edge it shares with it:
// drawn again with the same covers, the edge now closes.
void CdtModule::Impl::Frame::redrawTwinsOf(ObjectId id)
{
    for (std::uint32_t index : m.polygonsOf[id])
        for (const std::vector<std::uint32_t>& edgeTwins : m.twins[index])
            for (std::uint32_t twin : edgeTwins)
                if (m.waitsForTwin[twin])
                {
                    m.waitsForTwin[twin] = 0;
                    ++m.stats.redrawn;
                    for (unsigned kind = 0; kind < 2; ++kind)
                        if (m.drawnKinds[twin] & (1u << kind))
                            drawPolygon(twin, cdt::CoverKind(kind));
                }
}

// The polygons of a visible object; without depth only when they lie inside `cell` (a cell
// every later one is behind) by more than the depth buffer resolves there, by depth otherwise:
// a later object may touch the cell's faces, and where it touches a polygon lying on one (a
// floor on a split plane) the two tie in depth and either may be drawn (docs/cdt.md).
void CdtModule::Impl::Frame::drawObject(ObjectId id, const Aabb* cell)
{
    for (std::uint32_t index : m.polygonsOf[id])
    {
        const Aabb& bounds = m.polygonBounds[index];
        bool inside = false;
        if (cell)
        {
            // note: every point of the polygon lies within |far| of the eye, and whatever lies outside
            // the cell is farther along its ray by at least the clearance (docs/cdt.md)
            const Vec3 far = glm::max(glm::abs(bounds.min - view.eye), glm::abs(bounds.max - view.eye));
            const Vec3 clearance(m.grid.depthSeparation(glm::length(far)));
            inside = std::isfinite(clearance.x) && cell->contains(bounds.min - clearance) &&
                     cell->contains(bounds.max + clearance);
        }
        drawPolygon(index, inside ? cdt::CoverKind::DepthFree : cdt::CoverKind::DepthOnly);
    }
}

void CdtModule::Impl::Frame::cullSubtree(const HierarchyIndex::Node& n)
{
    for (std::uint32_t i = n.firstObject; i < n.subtreeEnd; ++i)
        if (!m.changed.changed(index.objects()[i])) // testMoved's
            visible.clear(index.objects()[i]);
}

bool CdtModule::Impl::Frame::enter(const HierarchyNode& node)
{
    if (stopped)
        return false;
    const HierarchyIndex::Node* found = walk.enter(node);
    if (!found)
    {
        m.stats.traversalStrayed = stopped = true;
        return false;
    }
    const HierarchyIndex::Node& n = *found;
    const std::size_t depth = walk.depth() - 1;
    if (n.contents.empty())
        return skip();
    if (!allowTest())
    {
        stopped = true;
        return skip();
    }
    ++m.stats.nodesVisited;
    if (nodeCulled(n, depth))
        return skip();
    if (!testHeldObjects(n, heldObjectsByDistance(n, depth)))
        return skip();
    if (n.leaf())
        debugNode(n.contents, NodeState::Visible, depth);
    entered.resize(depth + 1);
    entered[depth] = &n;
    return true;
}

// Once the node's region is finished, its objects hide every later region without depth.
void CdtModule::Impl::Frame::leave(const HierarchyNode&)
{
    const std::size_t depth = walk.depth() - 1;
    if (!stopped && !depthOnly)
        for (const auto& entry : m.orderScratch[depth])
            if (m.drawn[entry.second] == Drawn::Visible)
                drawObject(entry.second, &entered[depth]->region);
    walk.leave();
}

/// Leaves a node entered into the walk whose children are not visited.
bool CdtModule::Impl::Frame::skip()
{
    walk.leave();
    return false;
}

/// True when the node lies outside the frustum or hidden: its whole subtree is culled.
bool CdtModule::Impl::Frame::nodeCulled(const HierarchyIndex::Node& n, std::size_t depth)
{
    if (view.frustum.classify(n.contents) == Containment::Outside)
    {
        debugNode(n.contents, NodeState::OutsideFrustum, depth);
        cullSubtree(n);
        return true;
    }
    if (boxHidden(n.contents))
    {
        ++m.stats.nodesHidden;
        debugNode(n.contents, NodeState::Invisible, depth);
        cullSubtree(n);
        return true;
    }
    return false;
}

// The objects held here, nearest first. Each is tested against the record as it stood
// when the node was entered plus, by depth only, what nearer objects here added: objects
// of one node are not ordered along rays, so depth is all that may separate them.
std::vector<std::pair<double, ObjectId>>& CdtModule::Impl::Frame::heldObjectsByDistance(const HierarchyIndex::Node& n,
                                                                                        std::size_t depth)
{
    if (depth >= m.orderScratch.size())
        m.orderScratch.resize(depth + 1);
    std::vector<std::pair<double, ObjectId>>& order = m.orderScratch[depth];
    order.clear();
    for (std::uint32_t i = n.firstObject; i < n.firstObject + n.heldCount; ++i)
    {
        const ObjectId id = index.objects()[i];
        if (!visible.test(id) || m.changed.changed(id))
            continue;
        const Aabb& b = scene.objects[id].bounds;
        const Vec3 nearest = glm::clamp(view.eye, b.min, b.max);
        order.emplace_back(glm::length(nearest - view.eye), id);
    }
    std::sort(order.begin(), order.end());
    return order;
}

/// Tests the node's objects in `order`; false when the test budget ran out (the walk stops).
bool CdtModule::Impl::Frame::testHeldObjects(const HierarchyIndex::Node& n,
                                             const std::vector<std::pair<double, ObjectId>>& order)
{
    for (const auto& [distance, id] : order)
    {
        if (!allowTest())
        {
            stopped = true;
            return false;
        }
        testObject(id, n);
    }
    return true;
}

void CdtModule::Impl::Frame::testObject(ObjectId id, const HierarchyIndex::Node& n)
{
    ++m.stats.objectsTested;
    const Aabb& b = scene.objects[id].bounds;
    if (view.frustum.classify(b) == Containment::Outside)
    {
        ++m.stats.outsideFrustum;
        m.drawn[id] = Drawn::Hidden;
        visible.clear(id);
    }
    else if (boxHidden(b))
    {
        ++m.stats.objectsHidden;
        m.drawn[id] = Drawn::Hidden;
        visible.clear(id);
    }
    else
    {
        m.drawn[id] = Drawn::Visible;
        redrawTwinsOf(id);
        // By depth at once: every object under cdt-depth; under cdt the straddling ones,
        // which may not hide the rest of their subtree otherwise (a leaf's few objects
        // rarely hide each other, and the leaf's cover comes a moment later anyway).
        if (depthOnly || (options.rule == CdtOptions::Rule::Combined && !n.leaf()))
            drawObject(id, nullptr);
    }
}

void CdtModule::cull(const View& view, VisibleSet& visible)
{
    Impl& m = *_impl;
    const auto start = std::chrono::steady_clock::now();
    m.stats = {};
    if (!_scene || !m.hierarchy || m.sceneHierarchy.index().objects().empty() ||
        !m.grid.set(view, _options.tolerancePixels))
        return;
    m.view = view;
    if (_debug)
        _debug->clear();
    m.beginFrame(_options);
    Impl::Frame frame(m, _options, _debug, *_scene, view, visible);
    for (std::uint32_t index : m.statedPolygons)
        frame.drawPolygon(index, cdt::CoverKind::DepthOnly);

    const VisibleSet candidates = visible;
    m.hierarchy->traverse(view.eye, frame);
    frame.testMoved();
    if (m.stats.traversalStrayed)
        visible = candidates;
    m.stats.triangles = m.record.statistics().triangles;
    m.stats.cullMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

CdtModule::Statistics CdtModule::lastStatistics() const { return _impl->stats; }
bool CdtModule::walksSceneHierarchy() const { return _impl->sceneHierarchy.walks(); }
HierarchyLayout CdtModule::walkedLayout() const { return _impl->sceneHierarchy.index().layout(); }
const std::string& CdtModule::hierarchyProblem() const { return _impl->sceneHierarchy.problem(); }
} // namespace osgVis::core
