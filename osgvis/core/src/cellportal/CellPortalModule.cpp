// SPDX-License-Identifier: MIT
#include <osgVis/core/cellportal/CellPortalModule.h>

#include <osgVis/core/module/BakedDataStore.h>

#include <osgVis/core/cellportal/PortalStabbing.h>

#include "CellObjects.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace osgVis::core
{
namespace
{
const char* stageName(CellPortalStage stage)
{
    switch (stage)
    {
    case CellPortalStage::CellToCell: return "cellportal-cells";
    case CellPortalStage::CellToObject: return "cellportal-pvs";
    case CellPortalStage::EyeToCell: return "cellportal-eyecells";
    case CellPortalStage::EyeToObject: break;
    }
    return "cellportal";
}

// A root file's objects alone fingerprint like a scene of those objects (nothing paged in), whose
// own bake is stored by that fingerprint: the store keeps whole-database bakes apart.
std::uint64_t tiledStoreKey(std::uint64_t rootFingerprint) { return rootFingerprint ^ 0x74696c656b657973ull; }
} // namespace

void registerBakedCellPortalData(std::shared_ptr<const CellPortalData> data)
{
    if (!data)
        return;
    const std::uint64_t fingerprint = data->fingerprint; // read before the move below
    // A bake of a whole paged database is also found by its root file's objects, which every
    // load state of the database shares (CellPortalModule::setScene maps the rest).
    if (data->tiles)
        BakedDataStore<CellPortalData>::instance().put(tiledStoreKey(data->tiles->rootFingerprint), data);
    BakedDataStore<CellPortalData>::instance().put(fingerprint, std::move(data));
}

std::shared_ptr<const CellPortalData> findBakedCellPortalData(std::uint64_t fingerprint)
{
    return BakedDataStore<CellPortalData>::instance().find(fingerprint);
}

std::shared_ptr<const CellPortalData> findBakedCellPortalDataOfDatabase(std::uint64_t rootFingerprint)
{
    return BakedDataStore<CellPortalData>::instance().find(tiledStoreKey(rootFingerprint));
}

struct CellPortalModule::Impl
{
    CellPortalStage stage;
    BakeOptions bake;
    std::shared_ptr<const CellPortalData> given;
    std::shared_ptr<const CellPortalData> data;
    bool bakedOnTheSpot = false;
    // With data baked on a whole paged database and a scene with some of its tiles: each cell's
    // PVS in this scene's ids (data's own sets index the bake's objects).
    bool tiled = false;
    std::vector<VisibleSet> tiledPvs;
    std::string tiledRefusal;
    CellObjects objects;
    std::vector<Aabb> objectBounds;
    double tolerance = 0.0;
    Aabb subdivided; // union of the cells: outside it an eye is in no cell
    // Whether the cells leave gaps inside the subdivided box (solid space: kd leaves naming no
    // cell): then the eye's reach must lie wholly in cells, or it may look out of solid space.
    bool gaps = false;

    // Whether `box` lies in the union of `cells` (disjoint boxes): their overlaps fill its volume.
    bool covered(const Aabb& box, const std::vector<std::uint32_t>& cells) const
    {
        const Vec3 size = box.extent();
        const double volume = size.x * size.y * size.z;
        double inCells = 0.0;
        for (std::uint32_t c : cells)
        {
            const Vec3 overlap = glm::max(glm::min(box.max, data->graph.cells[c].max) -
                                              glm::max(box.min, data->graph.cells[c].min),
                                          Vec3(0.0));
            inCells += overlap.x * overlap.y * overlap.z;
        }
        return inCells >= volume * (1.0 - 1e-9);
    }
    DebugRecord* record = nullptr;

    // The eye's source cell, cached while the eye stays in it: each stab-tree node's portal as it
    // is crossed and the node's depth, so a query walks the tree without touching the graph.
    struct SourceCache
    {
        std::uint32_t cell = NoCell;
        std::vector<OrientedPortal> portals;
        std::vector<std::uint32_t> depths;
    };
    std::vector<SourceCache> caches; // one per cell the eye touches (several on a boundary)

    // Per-query scratch.
    VisibleSet kept;
    std::vector<std::uint32_t> eyeCells;
    std::vector<OrientedPortal> sequence;
    std::vector<Plane> viewPlanes;

    bool usable(const CellPortalData& candidate, const Scene& scene, std::uint64_t fingerprint) const
    {
        return candidate.fingerprint == fingerprint && candidate.objectCount == scene.objects.size() &&
               candidate.sources.size() == candidate.graph.cells.size();
    }

    // Data baked on the whole database serve a scene with any of its tiles loaded when the root's
    // objects and every loaded tile's equal the bake's: the bake's sets, moved to this scene's ids.
    bool mapTiled(const CellPortalData& candidate, const Scene& scene)
    {
        if (!candidate.tiles || !scene.tiles || candidate.sources.size() != candidate.graph.cells.size())
            return false;
        std::vector<ObjectId> bakedOf;
        if (!mapToBakedObjects(*candidate.tiles, *scene.tiles, bakedOf, tiledRefusal))
            return false;
        std::vector<ObjectId> currentOf(candidate.objectCount, InvalidObject);
        for (ObjectId id = 0; id < bakedOf.size(); ++id)
            if (bakedOf[id] < currentOf.size())
                currentOf[bakedOf[id]] = id;
        tiledPvs.resize(candidate.sources.size());
        for (std::size_t cell = 0; cell < candidate.sources.size(); ++cell)
        {
            tiledPvs[cell].reset(scene.objects.size());
            for (ObjectId baked : candidate.sources[cell].cellToObject.ids())
                if (baked < currentOf.size() && currentOf[baked] != InvalidObject)
                    tiledPvs[cell].set(currentOf[baked]);
        }
        return true;
    }

    const VisibleSet& pvsOf(std::uint32_t cell) const
    {
        return tiled ? tiledPvs[cell] : data->sources[cell].cellToObject;
    }

    const SourceCache& cacheFor(std::uint32_t cell, std::size_t slot)
    {
        if (caches.size() <= slot)
            caches.resize(slot + 1);
        SourceCache& cache = caches[slot];
        if (cache.cell == cell)
            return cache;
        cache.cell = cell;
        const std::vector<StabNode>& tree = data->sources[cell].stabTree;
        cache.portals.resize(tree.size());
        cache.depths.resize(tree.size());
        for (std::size_t i = 0; i < tree.size(); ++i)
        {
            const StabNode& node = tree[i];
            const CellPortal& portal = data->graph.portals[node.portal];
            cache.portals[i] = {portal.rect, node.cell == portal.highCell};
            cache.depths[i] = node.parent == NoStabParent ? 1u : cache.depths[node.parent] + 1u;
        }
        return cache;
    }

    void keepCellObjects(std::uint32_t cell)
    {
        for (ObjectId id : objects.perCell[cell])
            kept.set(id);
    }

    // Objects of `cell` in the source's PVS that a sightline from the eye through `sequence` reaches.
    void keepSeenObjects(const Vec3& eye, std::uint32_t cell, const VisibleSet& pvs)
    {
        for (ObjectId id : objects.perCell[cell])
        {
            if (kept.test(id) || !pvs.test(id))
                continue;
            const Aabb part = clippedToCell(objectBounds[id], data->graph.cells[cell], tolerance);
            if (eyeSeesBoxThroughPortals(eye, sequence.data(), sequence.size(), viewPlanes, part, tolerance))
                kept.set(id);
        }
    }

    void recordCell(std::uint32_t cell, NodeState state, std::uint32_t depth)
    {
        if (record)
            record->nodes.push_back({data->graph.cells[cell], state, depth});
    }

    // Eye-to-cell: the source's stab tree walked depth first, a subtree skipped as soon as no
    // sightline through the eye passes its sequence.
    void walkStabTree(const Vec3& eye, std::uint32_t source, std::size_t slot)
    {
        const SourceCellVisibility& visibility = data->sources[source];
        const SourceCache& cache = cacheFor(source, slot);
        const bool objectsToo = stage == CellPortalStage::EyeToObject;
        sequence.clear();
        if (objectsToo)
            keepSeenObjects(eye, source, pvsOf(source));
        else
            keepCellObjects(source);
        recordCell(source, NodeState::Visible, 0);
        const std::vector<StabNode>& tree = visibility.stabTree;
        for (std::size_t i = 0; i < tree.size();)
        {
            const std::uint32_t depth = cache.depths[i];
            sequence.resize(depth - 1);
            sequence.push_back(cache.portals[i]);
            if (!eyeSeesThroughPortals(eye, sequence.data(), sequence.size(), viewPlanes, tolerance))
            {
                i = tree[i].subtreeEnd;
                continue;
            }
            if (record)
                record->activeOccluders.push_back({cache.portals[i].rect.corner(0), cache.portals[i].rect.corner(1),
                                                   cache.portals[i].rect.corner(2), cache.portals[i].rect.corner(3)});
            recordCell(tree[i].cell, NodeState::Visible, depth);
            if (objectsToo)
                keepSeenObjects(eye, tree[i].cell, pvsOf(source));
            else
                keepCellObjects(tree[i].cell);
            ++i;
        }
    }

    void cullFromCell(const Vec3& eye, std::uint32_t source, std::size_t slot)
    {
        const SourceCellVisibility& visibility = data->sources[source];
        const bool eyeStage = stage == CellPortalStage::EyeToCell || stage == CellPortalStage::EyeToObject;
        if (eyeStage && !visibility.budgetExceeded)
        {
            walkStabTree(eye, source, slot);
            return;
        }
        if (stage == CellPortalStage::CellToCell)
        {
            for (std::uint32_t cell = 0; cell < data->graph.cells.size(); ++cell)
                if (visibility.cellToCell.test(cell))
                    keepCellObjects(cell);
            return;
        }
        // The PVS, also where the stab tree is incomplete (the search hit its budget).
        for (ObjectId id : pvsOf(source).ids())
            kept.set(id);
    }
};

CellPortalModule::CellPortalModule(CellPortalStage stage, const BakeOptions& bake) : _impl(std::make_unique<Impl>())
{
    _impl->stage = stage;
    _impl->bake = bake;
}

CellPortalModule::~CellPortalModule() = default;

const char* CellPortalModule::name() const { return stageName(_impl->stage); }

void CellPortalModule::setBakedData(std::shared_ptr<const CellPortalData> data) { _impl->given = std::move(data); }

std::shared_ptr<const CellPortalData> CellPortalModule::bakedData() const { return _impl->data; }

bool CellPortalModule::bakedOnTheSpot() const { return _impl->bakedOnTheSpot; }

bool CellPortalModule::usesTiledBake() const { return _impl->tiled; }

const std::string& CellPortalModule::tiledBakeRefusal() const { return _impl->tiledRefusal; }

void CellPortalModule::setDebugRecord(DebugRecord* record) { _impl->record = record; }

void CellPortalModule::setScene(const Scene& scene)
{
    _scene = &scene;
    Impl& impl = *_impl;
    const std::uint64_t fingerprint = sceneFingerprint(scene);
    impl.data = nullptr;
    impl.tiled = false;
    impl.tiledPvs.clear();
    impl.tiledRefusal.clear();
    if (impl.given && impl.usable(*impl.given, scene, fingerprint))
        impl.data = impl.given;
    else if (auto registered = findBakedCellPortalData(fingerprint); registered && impl.usable(*registered, scene, fingerprint))
        impl.data = std::move(registered);
    else if (impl.given && impl.mapTiled(*impl.given, scene))
        impl.data = impl.given;
    else if (auto whole = scene.tiles ? findBakedCellPortalDataOfDatabase(scene.tiles->rootFingerprint) : nullptr;
             whole && impl.mapTiled(*whole, scene))
        impl.data = std::move(whole);
    impl.tiled = !impl.tiledPvs.empty();
    impl.bakedOnTheSpot = !impl.data;
    if (!impl.data)
    {
        impl.data = std::make_shared<const CellPortalData>(bakeCellPortal(scene, impl.bake));
        // Other modules given the same scene (the stages of a progressive table, one module per
        // view) reuse this bake instead of repeating it.
        registerBakedCellPortalData(impl.data);
    }
    impl.tolerance = cellPortalTolerance(impl.data->graph);
    impl.subdivided = Aabb();
    for (const Aabb& cell : impl.data->graph.cells)
        impl.subdivided.expand(cell);
    impl.gaps = std::any_of(impl.data->graph.nodes.begin(), impl.data->graph.nodes.end(),
                            [](const CellGraph::KdNode& node) { return node.axis > 2 && node.children[0] == NoCell; });
    impl.objects = assignObjectsToCells(scene, impl.data->graph, impl.tolerance);
    impl.objectBounds.resize(scene.objects.size());
    for (const SceneObject& object : scene.objects)
        impl.objectBounds[object.id] = object.bounds;
    impl.caches.clear();
}

void CellPortalModule::cull(const View& view, VisibleSet& visible)
{
    Impl& impl = *_impl;
    if (impl.record)
        impl.record->clear();
    // Sightlines of a parallel projection do not start at the eye: no eye cell to start from, so the
    // module keeps everything rather than guess.
    if (!impl.data || impl.data->graph.cells.empty() || view.orthographic)
        return;
    impl.eyeCells.clear();
    // Geometry closer than the near plane is clipped away, so the eye sees through a wall it
    // almost touches: every cell within the near plane's reach counts as an eye cell.
    const double reach = std::max(impl.tolerance, nearPlaneReach(view));
    impl.data->graph.locate(view.eye, reach, impl.eyeCells);
    if (impl.eyeCells.empty())
        return; // outside the subdivided space: everything may be seen
    if (impl.gaps && !impl.covered({view.eye - Vec3(reach), view.eye + Vec3(reach)}, impl.eyeCells))
        return; // the near plane may reach into solid space and look out of it anywhere
    impl.viewPlanes.assign({view.frustum.plane(Frustum::LEFT), view.frustum.plane(Frustum::RIGHT),
                            view.frustum.plane(Frustum::BOTTOM), view.frustum.plane(Frustum::TOP)});
    impl.kept.reset(visible.capacity());
    for (ObjectId id : impl.objects.everywhere)
        impl.kept.set(id);
    for (std::size_t slot = 0; slot < impl.eyeCells.size(); ++slot)
        impl.cullFromCell(view.eye, impl.eyeCells[slot], slot);
    if (impl.record && !impl.eyeCells.empty())
        impl.record->eyeCell = impl.data->graph.cells[impl.eyeCells.front()];
    visible.intersectWith(impl.kept);
}

// Any eye of the region stands in one of the cells its box meets (grown by the near plane's
// reach, as for a single eye), so the union of those cells' PVS holds for all of them. A box that
// leaves the subdivided space may hold eyes outside every cell: then everything may be seen. So
// may one among stated cells (markers), which need not fill their bounds.
void CellPortalModule::cullRegion(const ViewRegion& region, VisibleSet& visible)
{
    Impl& impl = *_impl;
    if (!impl.data || impl.data->graph.cells.empty() || impl.data->graph.nodes.empty() || region.eyes.empty() ||
        !region.eyes.finite())
        return;
    if (!impl.subdivided.contains(region.eyes.min) || !impl.subdivided.contains(region.eyes.max))
        return;
    impl.eyeCells.clear();
    const double reach = std::max(impl.tolerance, region.maxNearReach);
    impl.data->graph.cellsOverlapping(region.eyes, reach, impl.eyeCells);
    if (impl.eyeCells.empty())
        return;
    if (impl.gaps && !impl.covered({region.eyes.min - Vec3(reach), region.eyes.max + Vec3(reach)}, impl.eyeCells))
        return;
    impl.kept.reset(visible.capacity());
    for (ObjectId id : impl.objects.everywhere)
        impl.kept.set(id);
    for (std::uint32_t cell : impl.eyeCells)
        for (ObjectId id : impl.pvsOf(cell).ids())
            impl.kept.set(id);
    visible.intersectWith(impl.kept);
}
} // namespace osgVis::core
