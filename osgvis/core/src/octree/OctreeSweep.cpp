// SPDX-License-Identifier: MIT
// The octree module's second pass (an extension of Coorg & Teller's method, which fuses only
// occluders that share edges): objects the kd-tree walk left visible are swept front to back
// through an occlusion tree (Bittner, Havran & Slavík) of the polygons of those kept before them.
#include "OctreeImpl.h"

#include <algorithm>

namespace osgVis::core
{
// Occluder fusion without shared edges: objects the traversal left visible, nearest first, are
// tested against an occlusion tree of the polygons of the objects kept before them; a kept
// object's polygons then join the tree. Only drawn objects' polygons (and stated occluders)
// occlude, and the order is fixed (distance, then id), so the answer is the same at every thread
// count.
void OctreeModule::Impl::sweep(const Scene& scene, const View& view, const OctreeOptions& options, VisibleSet& visible)
{
    occlusionTree.reset(eye, view.frustum.plane(Frustum::NEAR).normal, sceneSize);
    // The budget's rest after the traversal; the objects the sweep does not reach stay visible.
    sweepBudget = options.workBudget == 0 ? ~std::uint64_t(0)
                                          : options.workBudget - std::min(options.workBudget, statistics.traversalWork);
    sweepOrder.clear();
    for (ObjectId id = 0; id < scene.objects.size(); ++id)
        if (visible.test(id) && (scene.objects[id].flags & OBJECT_ALWAYS_VISIBLE) == 0)
            sweepOrder.push_back({scene.objects[id].bounds.distance(eye), id});
    std::sort(sweepOrder.begin(), sweepOrder.end());
    insertPolygons(statedPolygons, view, options, false);
    // Below every tree node.
    const std::uint32_t debugDepth = debug ? std::uint32_t(std::max<std::size_t>(treeDepth(), hierarchyDepth) + 1) : 0;
    for (const auto& [distance, id] : sweepOrder)
    {
        if (occlusionTree.work() >= sweepBudget)
        {
            statistics.overBudget = true;
            break;
        }
        const Aabb& bounds = scene.objects[id].bounds;
        // A changed object's points are those of its old place: its box stands for it.
        const std::uint32_t first = pointsFirst[id], count = changed.changed(id) ? 0 : pointsFirst[id + 1] - first;
        const bool hidden = count > 0
                                ? occlusionTree.hidden(&objectPoints[first], count, bounds, depthTolerance(bounds))
                                : occlusionTree.hidden(bounds, depthTolerance(bounds));
        if (hidden)
        {
            visible.clear(id);
            ++statistics.sweptHidden;
            if (debug)
                serial.debugNodes.push_back({bounds, NodeState::Invisible, debugDepth});
            continue;
        }
        // A polygon's area-angle is at most its area over the squared distance to the object's box:
        // an object whose largest polygon falls short from here has nothing for the tree.
        const double threshold = options.sweepAreaAngleThreshold;
        if (occlusionTree.nodeCount() < options.occlusionTreeMaxNodes &&
            !(largestPolygonArea[id] < threshold * distance * distance))
            insertPolygons(objectPolygons[id], view, options, true);
    }
    statistics.sweepWork = occlusionTree.work();
    statistics.sweptTreeNodes = std::uint32_t(occlusionTree.nodeCount());
    statistics.sweptOccluders = std::uint32_t(occlusionTree.occluderCount());
}

// One object's polygons (or the stated ones). An object seen from outside hides with the faces
// turned to the eye; its two-sided faces turned away count (flipped) only when it shows the eye no
// face, as a lone wall seen from behind. Stated polygons are each their own occluder and count
// from either side. An edge shared with a polygon of the same batch facing the same way needs no
// margin: the renderer rasterizes the shared edge without a crack. Polygons the near plane could
// clip, and those outside the frustum, are left out.
void OctreeModule::Impl::insertPolygons(const std::vector<std::uint32_t>& batch, const View& view,
                                        const OctreeOptions& options, bool oneObject)
{
    const double minAreaAngle = oneObject ? options.sweepAreaAngleThreshold : 0.0;
    const Plane& nearPlane = view.frustum.plane(Frustum::NEAR);
    ++insertStamp;
    bool facesEye = false;
    for (std::uint32_t p : batch)
    {
        const OccluderPolygon& polygon = polygons[p];
        const double side = polygon.plane.distance(eye);
        const bool usable = !dependents.disabled(p) && sweptIn[p] != frame && (side > 0.0 || (!polygon.oneSided && side < 0.0)) &&
                            areaAngle(polygon, eye) >= minAreaAngle &&
                            std::all_of(polygon.vertices.begin(), polygon.vertices.end(),
                                        [&](const Vec3& v) { return nearPlane.distance(v) > 0.0; }) &&
                            view.frustum.classify(polygonBounds[p]) != Containment::Outside;
        insertedAs[p] = usable ? 2 * insertStamp + (side < 0.0 ? 1 : 0) : 0;
        facesEye = facesEye || (usable && side > 0.0);
    }
    if (oneObject && facesEye)
        for (std::uint32_t p : batch)
            if ((insertedAs[p] & 1u) != 0)
                insertedAs[p] = 0;
    for (std::uint32_t p : batch)
    {
        if (insertedAs[p] == 0)
            continue;
        if (occlusionTree.work() >= sweepBudget)
            break; // out of budget: fewer occluders only hide less
        const OccluderPolygon& polygon = polygons[p];
        const bool flipped = (insertedAs[p] & 1u) != 0;
        sweptIn[p] = frame;
        const double margin = marginOf(polygon);
        const std::size_t n = polygon.vertices.size();
        insertVertices.resize(n);
        insertMargins.resize(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            // Flipped, vertex i is the original n-1-i and edge i the original edge n-2-i reversed.
            const std::size_t vertex = flipped ? n - 1 - i : i;
            const std::size_t edge = flipped ? (2 * n - 2 - i) % n : i;
            insertVertices[i] = polygon.vertices[vertex];
            const std::uint32_t neighbour = polygon.neighbours.empty() ? NoNeighbour : polygon.neighbours[edge];
            insertMargins[i] = neighbour != NoNeighbour && insertedAs[neighbour] == insertedAs[p] ? 0.0 : margin;
        }
        const Plane plane = flipped ? Plane(-polygon.plane.normal, -polygon.plane.d) : polygon.plane;
        occlusionTree.insert(insertVertices, plane, insertMargins);
        if (occlusionTree.nodeCount() >= options.occlusionTreeMaxNodes)
            break;
    }
}
} // namespace osgVis::core
