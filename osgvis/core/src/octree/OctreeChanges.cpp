// SPDX-License-Identifier: MIT
// The octree module's answer to a changing scene, in time that grows with what changed (Coorg &
// Teller's structures are built once, for a static model): a moved or inserted object leaves the
// kd-tree's answer, whose boxes no longer hold it, and is tested on its own against the frustum and
// the frame's occluders; every polygon resting on a moved or removed object (its own, and coplanar
// unions it is part of) stops occluding. The tree is rebuilt only once a quarter of the objects
// have changed. docs/octree.md, "Changes".
#include "OctreeImpl.h"

#include <algorithm>

namespace osgVis::core
{
// False when the change asks for a rebuild: other stated occluders, fewer objects, or too many changed.
bool OctreeModule::Impl::applyChanges(const Scene& scene, const std::vector<SceneChange>& changes)
{
    if (!sameOccluderCandidates(scene.occluders, statedFrom))
        return false;
    // Objects inserted since the build own no polygon and no points.
    const std::size_t count = scene.objects.size();
    objectCaches.resize(std::max(count, objectCaches.size()));
    objectPolygons.resize(std::max(count, objectPolygons.size()));
    largestPolygonArea.resize(std::max(count, largestPolygonArea.size()), 0.0);
    pointsFirst.resize(std::max(count + 1, pointsFirst.size()), pointsFirst.back());
    return changed.apply(
        count, changes, [&](ObjectId id) { dependents.disableAll(id); },
        [&](ObjectId id) { objectCaches[id].clear(); }); // its planes were those of its old box
}

// The moved objects still candidates, one by one, as a leaf's objects are tested but against every
// occluder of the frame (no node passed a shorter list down to them).
void OctreeModule::Impl::testMoved(const Scene& scene, const OctreeOptions& options, VisibleSet& visible)
{
    const std::uint32_t depth = debug ? std::uint32_t(treeDepth() + 1) : 0; // below every node
    for (ObjectId id : changed.moved())
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
