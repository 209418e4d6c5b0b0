// SPDX-License-Identifier: MIT
// The octree module's answer to a changing scene, in time that grows with what changed (Coorg &
// Teller build once for a static model; their §6 leaves moving objects to a separate test, which
// this is). A moved or inserted object leaves the kd-tree's answer, whose boxes no longer hold it,
// and is tested on its own against the frustum and the frame's occluders; every polygon resting on
// a moved or removed object (its own, and coplanar unions it is part of) stops occluding. The tree
// is rebuilt only once a quarter of the objects have changed. docs/octree.md, "Changes".
#include "OctreeImpl.h"

#include <algorithm>

namespace osgVis::core
{
namespace
{
bool sameStatedOccluders(const std::vector<OccluderCandidate>& a, const std::vector<OccluderCandidate>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const OccluderCandidate& x, const OccluderCandidate& y)
                      { return x.owner == y.owner && x.polygon.vertices() == y.polygon.vertices(); });
}
} // namespace

// Per object, the polygons resting on it (it owns them or is one of their parts), in one array.
void OctreeModule::Impl::indexDependents(const Scene& scene)
{
    const std::size_t count = scene.objects.size();
    dependentsFirst.assign(count + 1, 0);
    const auto forEachRest = [&](auto visit)
    {
        for (std::uint32_t p = 0; p < polygons.size(); ++p)
        {
            if (polygons[p].owner < count)
                visit(polygons[p].owner, p);
            for (ObjectId part : polygons[p].parts)
                if (part < count && part != polygons[p].owner)
                    visit(part, p);
        }
    };
    forEachRest([&](ObjectId id, std::uint32_t) { ++dependentsFirst[id + 1]; });
    for (std::size_t id = 0; id < count; ++id)
        dependentsFirst[id + 1] += dependentsFirst[id];
    dependents.resize(dependentsFirst[count]);
    std::vector<std::uint32_t> next(dependentsFirst.begin(), dependentsFirst.end() - 1);
    forEachRest([&](ObjectId id, std::uint32_t p) { dependents[next[id]++] = p; });

    changed.assign(count, Unchanged);
    movedIds.clear();
    changedCount = 0;
    polygonDisabled.assign(polygons.size(), 0);
    statedFrom = scene.occluders;
}

// False when the change asks for a rebuild: other stated occluders, fewer objects, or too many changed.
bool OctreeModule::Impl::applyChanges(const Scene& scene, const std::vector<SceneChange>& changes)
{
    const std::size_t count = scene.objects.size();
    if (count < changed.size() || !sameStatedOccluders(scene.occluders, statedFrom))
        return false;
    // Objects inserted since the build own no polygon and no points; they are tested as moved.
    changed.resize(count, Unchanged);
    objectCaches.resize(count);
    objectPolygons.resize(count);
    largestPolygonArea.resize(count, 0.0);
    pointsFirst.resize(count + 1, pointsFirst.back());
    dependentsFirst.resize(count + 1, dependentsFirst.back());
    for (const SceneChange& change : changes)
        for (ObjectId id : change.objects)
        {
            if (id >= count)
                continue;
            if (changed[id] == Unchanged)
            {
                ++changedCount;
                for (std::uint32_t d = dependentsFirst[id]; d < dependentsFirst[id + 1]; ++d)
                    polygonDisabled[dependents[d]] = 1;
            }
            if (change.kind != SceneChange::Kind::Removed && changed[id] != Moved)
                movedIds.push_back(id);
            changed[id] = change.kind == SceneChange::Kind::Removed ? Removed : Moved;
            objectCaches[id].clear(); // its planes were those of its old box
        }
    movedIds.erase(std::remove_if(movedIds.begin(), movedIds.end(), [&](ObjectId id) { return changed[id] != Moved; }),
                   movedIds.end());
    return changedCount <= std::max<std::size_t>(64, count / 4);
}

// The moved objects still candidates, one by one, as a leaf's objects are tested but against every
// occluder of the frame (no node passed a shorter list down to them).
void OctreeModule::Impl::testMoved(const Scene& scene, const OctreeOptions& options, VisibleSet& visible)
{
    const std::uint32_t depth = debug ? std::uint32_t(treeDepth() + 1) : 0; // below every node
    for (ObjectId id : movedIds)
    {
        const SceneObject& object = scene.objects[id];
        if (!visible.test(id) || (object.flags & OBJECT_ALWAYS_VISIBLE) != 0)
            continue;
        ++statistics.changedTested;
        unsigned planeMask = rootPlaneMask;
        NodeState state = NodeState::Visible;
        if (frustum->classify(object.bounds, planeMask) == Containment::Outside)
            state = NodeState::OutsideFrustum;
        else if (!active.empty() && testBox(objectCaches[id], object.bounds, active, options.fuseConnected,
                                            movedPartial, movedScratch) == Occlusion::Invisible)
            state = NodeState::Invisible;
        if (state != NodeState::Visible)
            visible.clear(id);
        if (debug)
            serial.debugNodes.push_back({object.bounds, state, depth});
    }
    statistics.planeTests += movedScratch.statistics.planeTests;
    statistics.cachedDecisions += movedScratch.statistics.cachedDecisions;
    movedScratch.statistics = Statistics();
}

void OctreeModule::sceneChanged(const SceneChange& change)
{
    if (_scene)
        sceneReplaced(*_scene, {change});
}

void OctreeModule::sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes)
{
    if (!_scene || !_impl->applyChanges(scene, changes))
    {
        setScene(scene);
        return;
    }
    _scene = &scene;
}
} // namespace osgVis::core
