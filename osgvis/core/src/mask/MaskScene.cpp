// SPDX-License-Identifier: MIT
// Occlusion masks after Wang, Agarwal & Har-Peled, the module's scene: what setScene builds (the
// occluder polygons and the stamped kd-tree) and how a change is taken without a rebuild (moved
// objects tested every frame, never occluding again; docs/mask.md, "Dynamic scenes").
#include "MaskImpl.h"

#include <algorithm>
#include <unordered_set>

namespace osgVis::core
{
namespace
{
// Polygons of a few objects (inserted during the walk), built on a scene of just those objects,
// then renumbered into the module's polygon list.
void appendObjectPolygons(const Scene& scene, const std::vector<ObjectId>& ids, const OccluderBuildOptions& options,
                          std::vector<OccluderPolygon>& polygons)
{
    Scene part;
    for (ObjectId id : ids)
    {
        const SceneObject& source = scene.objects[id];
        SceneObject object = source;
        object.id = static_cast<ObjectId>(part.objects.size());
        object.firstTriangle = static_cast<std::uint32_t>(part.triangles.size());
        if (std::size_t(source.firstTriangle) + source.triangleCount <= scene.triangles.size())
            part.triangles.insert(part.triangles.end(), scene.triangles.begin() + source.firstTriangle,
                                  scene.triangles.begin() + source.firstTriangle + source.triangleCount);
        else
            object.triangleCount = 0;
        part.objects.push_back(std::move(object));
    }
    std::vector<OccluderPolygon> built = buildOccluderPolygons(part, options);
    const std::uint32_t base = static_cast<std::uint32_t>(polygons.size());
    for (OccluderPolygon& polygon : built)
    {
        polygon.owner = polygon.owner == InvalidObject ? InvalidObject : ids[polygon.owner];
        for (ObjectId& part : polygon.parts)
            part = ids[part];
        for (std::uint32_t& n : polygon.neighbours)
            n = n == NoNeighbour ? NoNeighbour : n + base;
        polygons.push_back(std::move(polygon));
    }
}
} // namespace

void MaskModule::setScene(const Scene& scene)
{
    _scene = &scene;
    Impl& m = *_impl;
    const std::vector<SceneObject>& objects = scene.objects;
    m.scene = &scene;
    m.polygons = buildOccluderPolygons(scene);
    m.polygonsOf.assign(objects.size(), {});
    m.statedPolygons.clear();
    for (std::uint32_t i = 0; i < m.polygons.size(); ++i)
    {
        if (m.polygons[i].owner == InvalidObject)
            m.statedPolygons.push_back(i);
        else
            m.addToOwners(i);
    }
    m.selectedIn.assign(m.polygons.size(), 0);
    m.usable.assign(objects.size(), 0);
    m.moving.assign(objects.size(), 0);
    m.present.assign(objects.size(), 1);
    m.movingIds.clear();
    std::vector<Aabb> bounds(objects.size());
    std::vector<bool> inTree(objects.size(), false);
    for (const SceneObject& object : objects)
    {
        bounds[object.id] = object.bounds;
        const bool dynamic = (object.flags & OBJECT_DYNAMIC) != 0;
        m.moving[object.id] = dynamic;
        if (dynamic)
            m.movingIds.push_back(object.id);
        inTree[object.id] = !dynamic && (object.flags & OBJECT_ALWAYS_VISIBLE) == 0;
        m.usable[object.id] = !dynamic && !m.polygonsOf[object.id].empty();
    }
    // 2.5-D input (a city: flat compared with its footprint) gets the paper's 2-D tree.
    MaskKdTree::Split split = MaskKdTree::Split::Full;
    if (_options.tree == MaskOptions::Tree::Planar)
        split = MaskKdTree::Split::Planar;
    else if (_options.tree == MaskOptions::Tree::Auto)
    {
        const Vec3 extent = scene.bounds().extent();
        const double smallest = std::min({extent.x, extent.y, extent.z});
        const double largest = std::max({extent.x, extent.y, extent.z});
        if (largest > 0.0 && smallest < 0.25 * largest)
            split = MaskKdTree::Split::Planar;
    }
    m.tree = MaskKdTree();
    m.sceneHierarchy.choose(scene, _options.sceneHierarchy);
    if (!m.sceneHierarchy.walks())
        m.tree.build(bounds, inTree, split, _options.maxLeafObjects);
    m.forgetMarks();
    m.statistics = Statistics();
}

void MaskModule::sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes)
{
    Impl& m = *_impl;
    if (!_scene)
    {
        setScene(scene);
        return;
    }
    _scene = &scene;
    m.scene = &scene;
    const std::size_t count = scene.objects.size();
    m.polygonsOf.resize(count);
    m.usable.resize(count, 0);
    m.moving.resize(count, 0);
    m.present.resize(count, 0);

    // Every occluder that alive stamps may rest on.
    std::unordered_set<ObjectId> occluding;
    for (const Impl::CriticalFrame& frame : m.alive)
        occluding.insert(frame.occluders.begin(), frame.occluders.end());

    const auto makeMoving = [&](ObjectId id)
    {
        if (!m.moving[id])
            m.movingIds.push_back(id);
        m.moving[id] = 1;
        m.usable[id] = 0;
        m.tree.remove(id);
    };
    for (const SceneChange& change : changes)
    {
        std::vector<ObjectId> newStatic;
        for (ObjectId id : change.objects)
        {
            if (id >= count)
                continue;
            const SceneObject& object = scene.objects[id];
            switch (change.kind)
            {
            case SceneChange::Kind::Removed:
                if (occluding.count(id))
                    m.occluderGone = true;
                m.present[id] = 0;
                m.usable[id] = 0;
                m.tree.remove(id);
                break;
            case SceneChange::Kind::Moved:
                // Rule: a moved object never occludes again and is tested against the mask every
                // frame instead of carrying stamps; moving an occluder invalidates the marks.
                if (occluding.count(id))
                    m.occluderGone = true;
                m.present[id] = 1;
                makeMoving(id);
                break;
            case SceneChange::Kind::Inserted:
                m.present[id] = 1;
                // The recorded hierarchy's boxes do not hold what comes in later.
                if ((object.flags & OBJECT_DYNAMIC) != 0 || m.sceneHierarchy.walks())
                {
                    makeMoving(id);
                    break;
                }
                m.moving[id] = 0;
                if ((object.flags & OBJECT_ALWAYS_VISIBLE) == 0)
                    m.tree.insert(id, object.bounds); // clears the stamps on its way down
                if (m.polygonsOf[id].empty())
                    newStatic.push_back(id);
                else
                    m.usable[id] = 1;
                break;
            }
        }
        if (!newStatic.empty())
        {
            const std::size_t before = m.polygons.size();
            appendObjectPolygons(scene, newStatic, OccluderBuildOptions(), m.polygons);
            for (std::size_t i = before; i < m.polygons.size(); ++i)
                m.addToOwners(static_cast<std::uint32_t>(i));
            m.selectedIn.resize(m.polygons.size(), 0);
            for (ObjectId id : newStatic)
                m.usable[id] = !m.polygonsOf[id].empty();
        }
    }
    m.movingIds.erase(std::remove_if(m.movingIds.begin(), m.movingIds.end(),
                                     [&](ObjectId id) { return !m.present[id]; }),
                      m.movingIds.end());
    if (m.occluderGone)
        m.forgetMarks();
    // Lazy updates leave loose boxes behind; rebuild once they pile up (marks go with it).
    if (m.tree.updatesSinceBuild() > std::max<std::size_t>(64, count / 4))
    {
        m.tree.rebuild();
        m.forgetMarks();
    }
}
} // namespace osgVis::core
