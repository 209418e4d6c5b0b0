/* SPDX-License-Identifier: MIT */
/*
 * Mode `cfrustum`: every candidate whose box lies wholly outside one plane of the view frustum is
 * culled (the p-vertex test of Assarsson & Moeller, 2000, per object without a hierarchy). It sees
 * the scene and the view only through osgVis/visapi.h, so it is the worked example of a module
 * built as a plugin. Never culls a visible object; may keep hidden ones (those the frustum test
 * cannot reject). It answers exactly what the built-in `frustum` module answers.
 */
#include <osgVis/visapi.h>

#include <stdlib.h>

typedef struct cfrustum_state
{
    const osgvis_scene* scene; /* valid until the next set_scene or destroy */
} cfrustum_state;

static void* cfrustum_create(void* user_data)
{
    (void)user_data;
    return calloc(1, sizeof(cfrustum_state));
}

static void cfrustum_destroy(void* state)
{
    free(state);
}

static osgvis_status cfrustum_set_scene(void* state, const osgvis_scene* scene)
{
    ((cfrustum_state*)state)->scene = scene;
    return OSGVIS_OK;
}

/* The box's corner farthest along the plane's normal is behind the plane. Written so that a NaN
 * distance never culls. */
static int outside_plane(const double plane[4], const double lo[3], const double hi[3])
{
    double distance = plane[3];
    int axis;
    for (axis = 0; axis < 3; ++axis)
        distance += plane[axis] * (plane[axis] >= 0.0 ? hi[axis] : lo[axis]);
    return distance < 0.0;
}

static osgvis_status cfrustum_cull(void* state, const osgvis_view* view, osgvis_visible* visible)
{
    const osgvis_scene* scene = ((cfrustum_state*)state)->scene;
    osgvis_view_info info;
    osgvis_object_info object;
    uint32_t id, count = osgvis_visible_capacity(visible);
    int plane;
    osgvis_status status = osgvis_view_get(view, &info);
    if (status != OSGVIS_OK)
        return status;
    if (count > osgvis_scene_object_count(scene))
        count = osgvis_scene_object_count(scene);
    for (id = 0; id < count; ++id)
    {
        if (!osgvis_visible_test(visible, id))
            continue;
        status = osgvis_scene_object(scene, id, &object);
        if (status != OSGVIS_OK)
            return status;
        for (plane = 0; plane < 6; ++plane)
        {
            /* note: the same plane order and test as the built-in module, so the two agree exactly */
            if (outside_plane(info.frustum_planes[plane], object.bounds_min, object.bounds_max))
            {
                osgvis_visible_clear(visible, id);
                break;
            }
        }
    }
    return OSGVIS_OK;
}

static const osgvis_module_callbacks cfrustum_callbacks = {
    OSGVIS_VISAPI_VERSION, "cfrustum", 0,   cfrustum_create, cfrustum_destroy, cfrustum_set_scene,
    NULL /* scene_changed: set_scene again */,  cfrustum_cull, NULL /* no region answers */, NULL};

OSGVIS_VISAPI_EXPORT const osgvis_module_callbacks* osgvis_module_entry(uint32_t host_version)
{
    (void)host_version; /* the host checks our api_version against its own */
    return &cfrustum_callbacks;
}
