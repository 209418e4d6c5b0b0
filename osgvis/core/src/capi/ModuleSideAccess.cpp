// SPDX-License-Identifier: MIT
// The module side's read-only accessors of osgVis/visapi.h over the core's Scene, View, ViewRegion
// and VisibleSet. Only the traversal (the renderer's code runs inside it) and the silhouette (it
// allocates) can fail by exception; they catch what they may meet, the rest cannot throw.
#include <osgVis/core/capi/LastError.h>
#include <osgVis/core/capi/HierarchyNodes.h>
#include <osgVis/core/capi/ModuleSideHandles.h>

#include <new>

using namespace osgVis::core;
using osgVis::core::capi::failuref;

namespace
{
void copyVec3(const Vec3& v, double out[3])
{
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

void copyMat4(const Mat4& m, double out[16])
{
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            out[column * 4 + row] = m[column][row];
}

osgvis_status nullHandle(const char* function)
{
    return failuref(OSGVIS_ERROR_INVALID_ARGUMENT, "%s: null handle or output", function);
}
} // namespace

static_assert(sizeof(Triangle) == 9 * sizeof(float), "visapi.h hands out triangles as 9 floats each");

// note: C linkage comes from the declarations in osgVis/visapi.h.
uint32_t osgvis_scene_object_count(const osgvis_scene* scene)
{
    return scene && scene->scene ? static_cast<uint32_t>(scene->scene->objects.size()) : 0;
}

osgvis_status osgvis_scene_object(const osgvis_scene* scene, uint32_t id, osgvis_object_info* info)
{
    if (!scene || !scene->scene || !info)
        return nullHandle("osgvis_scene_object");
    if (id >= scene->scene->objects.size())
        return failuref(OSGVIS_ERROR_INVALID_ARGUMENT, "osgvis_scene_object: no object %u", id);
    const SceneObject& object = scene->scene->objects[id];
    copyVec3(object.bounds.min, info->bounds_min);
    copyVec3(object.bounds.max, info->bounds_max);
    info->flags = object.flags;
    info->triangle_count = object.triangleCount;
    const auto [first, end] = scene->scene->trianglesOf(object);
    info->triangles_kept = static_cast<uint32_t>(end - first);
    info->triangles = end > first ? &scene->scene->triangles[first].a.x : nullptr;
    return OSGVIS_OK;
}

uint32_t osgvis_scene_occluder_count(const osgvis_scene* scene)
{
    return scene && scene->scene ? static_cast<uint32_t>(scene->scene->occluders.size()) : 0;
}

osgvis_status osgvis_scene_occluder(const osgvis_scene* scene, uint32_t index, uint32_t* owner, double* points,
                                    uint32_t capacity, uint32_t* point_count)
{
    if (!scene || !scene->scene || !point_count || (capacity > 0 && !points))
        return nullHandle("osgvis_scene_occluder");
    if (index >= scene->scene->occluders.size())
        return failuref(OSGVIS_ERROR_INVALID_ARGUMENT, "osgvis_scene_occluder: no occluder %u", index);
    const OccluderCandidate& occluder = scene->scene->occluders[index];
    const std::vector<Vec3>& vertices = occluder.polygon.vertices();
    if (owner)
        *owner = occluder.owner;
    *point_count = static_cast<uint32_t>(vertices.size());
    for (std::size_t i = 0; i < vertices.size() && i < capacity; ++i)
        copyVec3(vertices[i], points + 3 * i);
    return OSGVIS_OK;
}

uint32_t osgvis_scene_cell_count(const osgvis_scene* scene)
{
    return scene && scene->scene ? static_cast<uint32_t>(scene->scene->cells.size()) : 0;
}

osgvis_status osgvis_scene_cell(const osgvis_scene* scene, uint32_t index, double bounds_min[3], double bounds_max[3])
{
    if (!scene || !scene->scene || !bounds_min || !bounds_max)
        return nullHandle("osgvis_scene_cell");
    if (index >= scene->scene->cells.size())
        return failuref(OSGVIS_ERROR_INVALID_ARGUMENT, "osgvis_scene_cell: no cell %u", index);
    copyVec3(scene->scene->cells[index].bounds.min, bounds_min);
    copyVec3(scene->scene->cells[index].bounds.max, bounds_max);
    return OSGVIS_OK;
}

osgvis_status osgvis_view_get(const osgvis_view* view, osgvis_view_info* info)
{
    if (!view || !view->view || !info)
        return nullHandle("osgvis_view_get");
    const View& v = *view->view;
    copyVec3(v.eye, info->eye);
    copyMat4(v.viewMatrix, info->view_matrix);
    copyMat4(v.projectionMatrix, info->projection_matrix);
    for (int i = 0; i < 6; ++i)
    {
        const Plane& plane = v.frustum.plane(i);
        copyVec3(plane.normal, info->frustum_planes[i]);
        info->frustum_planes[i][3] = plane.d;
    }
    info->time = v.time;
    info->viewport_width = v.viewportWidth;
    info->viewport_height = v.viewportHeight;
    info->orthographic = v.orthographic ? 1 : 0;
    return OSGVIS_OK;
}

osgvis_status osgvis_region_get(const osgvis_region* region, osgvis_region_desc* info)
{
    if (!region || !region->region || !info)
        return nullHandle("osgvis_region_get");
    copyVec3(region->region->eyes.min, info->eyes_min);
    copyVec3(region->region->eyes.max, info->eyes_max);
    info->min_near_distance = region->region->minNearDistance;
    info->max_near_reach = region->region->maxNearReach;
    return OSGVIS_OK;
}

uint32_t osgvis_visible_capacity(const osgvis_visible* visible)
{
    return visible && visible->set ? static_cast<uint32_t>(visible->set->capacity()) : 0;
}

int osgvis_visible_test(const osgvis_visible* visible, uint32_t id)
{
    return visible && visible->set && visible->set->test(id) ? 1 : 0;
}

osgvis_status osgvis_visible_clear(osgvis_visible* visible, uint32_t id)
{
    if (!visible || !visible->set)
        return nullHandle("osgvis_visible_clear");
    if (id >= visible->set->capacity())
        return failuref(OSGVIS_ERROR_INVALID_ARGUMENT, "osgvis_visible_clear: no object %u", id);
    visible->set->clear(id);
    return OSGVIS_OK;
}

uint32_t osgvis_scene_portal_count(const osgvis_scene* scene)
{
    return scene && scene->scene ? static_cast<uint32_t>(scene->scene->portals.size()) : 0;
}

osgvis_status osgvis_scene_portal(const osgvis_scene* scene, uint32_t index, uint32_t* cell_a, uint32_t* cell_b,
                                  double* points, uint32_t capacity, uint32_t* point_count)
{
    if (!scene || !scene->scene || !point_count || (capacity > 0 && !points))
        return nullHandle("osgvis_scene_portal");
    if (index >= scene->scene->portals.size())
        return failuref(OSGVIS_ERROR_INVALID_ARGUMENT, "osgvis_scene_portal: no portal %u", index);
    const Portal& portal = scene->scene->portals[index];
    if (cell_a)
        *cell_a = portal.cellA;
    if (cell_b)
        *cell_b = portal.cellB;
    const std::vector<Vec3>& vertices = portal.polygon.vertices();
    *point_count = static_cast<uint32_t>(vertices.size());
    for (std::size_t i = 0; i < vertices.size() && i < capacity; ++i)
        copyVec3(vertices[i], points + 3 * i);
    return OSGVIS_OK;
}

int osgvis_scene_hierarchy(const osgvis_scene* scene, osgvis_hierarchy_layout* layout, uint32_t* node_count)
{
    if (!scene || !scene->scene || !scene->scene->hierarchy)
        return 0;
    const TraversalHierarchy& hierarchy = *scene->scene->hierarchy;
    if (layout)
        *layout = hierarchy.layout() == HierarchyLayout::Disjoint ? OSGVIS_HIERARCHY_DISJOINT : OSGVIS_HIERARCHY_OVERLAPPING;
    if (node_count)
        *node_count = hierarchy.nodeCount();
    return 1;
}

namespace
{
// A module's C visitor as the core's.
struct CVisitor : HierarchyVisitor
{
    const osgvis_hierarchy_visitor& visitor;
    explicit CVisitor(const osgvis_hierarchy_visitor& v) : visitor(v) {}
    bool enter(const HierarchyNode& node) override
    {
        const osgvis_hierarchy_node c = osgVis::core::capi::cNode(node);
        return visitor.enter(visitor.state, &c) != 0;
    }
    void leave(const HierarchyNode& node) override
    {
        const osgvis_hierarchy_node c = osgVis::core::capi::cNode(node);
        if (visitor.leave)
            visitor.leave(visitor.state, &c);
    }
};
} // namespace

osgvis_status osgvis_scene_traverse(const osgvis_scene* scene, const double eye[3], const osgvis_hierarchy_visitor* visitor)
{
    if (!scene || !scene->scene || !eye || !visitor || !visitor->enter)
        return nullHandle("osgvis_scene_traverse");
    if (!scene->scene->hierarchy)
        return failuref(OSGVIS_ERROR_BAD_STATE, "osgvis_scene_traverse: the renderer handed over no hierarchy");
    // note: the renderer's traversal runs here; what it throws (through osgVis's own callbacks)
    // must not reach the module's C code.
    try
    {
        CVisitor adapter(*visitor);
        scene->scene->hierarchy->traverse({eye[0], eye[1], eye[2]}, adapter);
        return OSGVIS_OK;
    }
    catch (const std::exception& e)
    {
        return failuref(OSGVIS_ERROR_INTERNAL, "osgvis_scene_traverse: %s", e.what());
    }
    catch (...)
    {
        return failuref(OSGVIS_ERROR_INTERNAL, "osgvis_scene_traverse: a non-standard exception");
    }
}

int osgvis_scene_attribute(const osgvis_scene* scene, uint32_t object, const char* name, const void** data, size_t* size)
{
    if (data)
        *data = nullptr;
    if (size)
        *size = 0;
    if (!scene || !scene->scene || !name)
        return 0;
    const std::vector<std::uint8_t>* bytes = scene->scene->attributes.find(object, name);
    if (!bytes)
        return 0;
    if (data)
        *data = bytes->data();
    if (size)
        *size = bytes->size();
    return 1;
}

osgvis_status osgvis_scene_silhouette(const osgvis_scene* scene, uint32_t object, const double eye[3], uint32_t* edges,
                                      uint32_t capacity, uint32_t* edge_count)
{
    if (!scene || !scene->scene || !eye || !edge_count || (capacity > 0 && !edges))
        return nullHandle("osgvis_scene_silhouette");
    const auto it = scene->scene->meshes.find(object);
    if (it == scene->scene->meshes.end())
        return failuref(OSGVIS_ERROR_UNSUPPORTED, "osgvis_scene_silhouette: object %u has no mesh", object);
    if (!it->second.closed())
        return failuref(OSGVIS_ERROR_UNSUPPORTED, "osgvis_scene_silhouette: the mesh of object %u is not closed: %s",
                        object, it->second.problem().c_str());
    try
    {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
        it->second.silhouette({eye[0], eye[1], eye[2]}, found);
        *edge_count = static_cast<uint32_t>(found.size());
        for (std::size_t i = 0; i < found.size() && i < capacity; ++i)
        {
            edges[2 * i] = found[i].first;
            edges[2 * i + 1] = found[i].second;
        }
        return OSGVIS_OK;
    }
    catch (const std::bad_alloc&)
    {
        return failuref(OSGVIS_ERROR_OUT_OF_MEMORY, "osgvis_scene_silhouette: out of memory");
    }
}
