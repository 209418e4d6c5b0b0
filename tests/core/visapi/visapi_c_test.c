/* SPDX-License-Identifier: MIT */
/*
 * The C interface from C99 (compiled with -std=c99 -pedantic -Werror): a line of boxes culled
 * through osgVis/visapi.h by the built-in `frustum`, by the plugin `cfrustum` and by a module this
 * program registers itself, each answer checked id by id; and (version 1.1) the program's own
 * hierarchy handed over by callback and walked by a module of the program.
 *
 *      eye at the origin, looking down -z (60 degree field of view, far 100)
 *      ids 0..9: unit boxes at z = -5, -6, ... -14   (in view)
 *      ids 10..19: unit boxes at z = 5, 6, ... 14    (behind the eye)
 */
#include <osgVis/visapi.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

#define CHECK(condition)                                                                                           \
    do                                                                                                             \
    {                                                                                                              \
        if (!(condition))                                                                                          \
        {                                                                                                          \
            fprintf(stderr, "%s:%d: CHECK(%s) failed; last error: %s\n", __FILE__, __LINE__, #condition,          \
                    osgvis_last_error());                                                                          \
            ++failures;                                                                                            \
        }                                                                                                          \
    } while (0)

/* A module of this program: culls the odd ids among the candidates. */
static int odd_state;
static void* odd_create(void* user_data)
{
    return user_data;
}
static void odd_destroy(void* state)
{
    (void)state;
}
static osgvis_status odd_set_scene(void* state, const osgvis_scene* scene)
{
    (void)state;
    return osgvis_scene_object_count(scene) == 20 ? OSGVIS_OK : OSGVIS_ERROR_INVALID_ARGUMENT;
}
static osgvis_status odd_cull(void* state, const osgvis_view* view, osgvis_visible* visible)
{
    uint32_t id;
    (void)state;
    (void)view;
    for (id = 1; id < osgvis_visible_capacity(visible); id += 2)
        osgvis_visible_clear(visible, id);
    return OSGVIS_OK;
}

/* The program's hierarchy: a root box holding nothing and one leaf per box (disjoint), the leaves
 * nearest the eye first. */
static uint32_t leaf_objects[20];
static int traversals = 0;
static void box_hierarchy_traverse(void* user_data, const double eye[3], const osgvis_hierarchy_visitor* visitor)
{
    osgvis_hierarchy_node root, leaf;
    int order[20], i, j;
    (void)user_data;
    ++traversals;
    memset(&root, 0, sizeof root);
    root.id = 0;
    root.region_min[0] = root.region_min[1] = -0.5;
    root.region_max[0] = root.region_max[1] = 0.5;
    root.region_min[2] = -14.5;
    root.region_max[2] = 14.5;
    if (!visitor->enter(visitor->state, &root))
        return;
    for (i = 0; i < 20; ++i)
        order[i] = i;
    for (i = 1; i < 20; ++i) /* insertion sort by distance of the box centre to the eye's z */
        for (j = i; j > 0; --j)
        {
            const double zj = order[j] < 10 ? -5.0 - order[j] : 5.0 + (order[j] - 10);
            const double zk = order[j - 1] < 10 ? -5.0 - order[j - 1] : 5.0 + (order[j - 1] - 10);
            if (fabs(zj - eye[2]) < fabs(zk - eye[2]))
            {
                const int t = order[j];
                order[j] = order[j - 1];
                order[j - 1] = t;
            }
        }
    for (i = 0; i < 20; ++i)
    {
        const double z = order[i] < 10 ? -5.0 - order[i] : 5.0 + (order[i] - 10);
        leaf = root;
        leaf.id = (uint32_t)(1 + order[i]);
        leaf.region_min[2] = z - 0.5;
        leaf.region_max[2] = z + 0.5;
        leaf_objects[order[i]] = (uint32_t)order[i];
        leaf.objects = &leaf_objects[order[i]];
        leaf.object_count = 1;
        if (visitor->enter(visitor->state, &leaf))
            visitor->leave(visitor->state, &leaf);
    }
    visitor->leave(visitor->state, &root);
}

/* A module of this program that walks the renderer's hierarchy: it culls the objects of every node
 * lying wholly behind the eye (z > 0 here) and does not descend below such a node. */
static osgvis_visible* walk_visible;
static int walk_enter(void* state, const osgvis_hierarchy_node* node)
{
    uint32_t i;
    (void)state;
    if (node->region_min[2] <= 0.0)
        return 1;
    for (i = 0; i < node->object_count; ++i)
        osgvis_visible_clear(walk_visible, node->objects[i]);
    return 0;
}
static const osgvis_scene* walk_scene;
static osgvis_status walk_set_scene(void* state, const osgvis_scene* scene)
{
    (void)state;
    walk_scene = scene;
    return OSGVIS_OK;
}
static osgvis_status walk_cull(void* state, const osgvis_view* view, osgvis_visible* visible)
{
    osgvis_view_info info;
    osgvis_hierarchy_visitor visitor;
    osgvis_hierarchy_layout layout;
    uint32_t nodes = 0;
    (void)state;
    if (!osgvis_scene_hierarchy(walk_scene, &layout, &nodes) || layout != OSGVIS_HIERARCHY_DISJOINT || nodes != 21)
        return OSGVIS_ERROR_BAD_STATE;
    osgvis_view_get(view, &info);
    walk_visible = visible;
    visitor.state = NULL;
    visitor.enter = walk_enter;
    visitor.leave = NULL;
    return osgvis_scene_traverse(walk_scene, info.eye, &visitor);
}

static void perspective(double fovy_degrees, double aspect, double near_distance, double far_distance,
                        double out[16])
{
    const double f = 1.0 / tan(fovy_degrees * 3.14159265358979323846 / 360.0);
    memset(out, 0, 16 * sizeof(double));
    out[0] = f / aspect;
    out[5] = f;
    out[10] = (far_distance + near_distance) / (near_distance - far_distance);
    out[11] = -1.0;
    out[14] = 2.0 * far_distance * near_distance / (near_distance - far_distance);
}

/* Culls with `modes` and checks the answer is exactly `expected` (count ids, ascending). */
static void check_answer(osgvis_context* context, const char* modes, const uint32_t* expected, size_t count)
{
    osgvis_view_desc view;
    uint32_t ids[20];
    size_t written = 0, total = 0, i;
    memset(&view, 0, sizeof view);
    for (i = 0; i < 4; ++i)
        view.view_matrix[5 * i] = 1.0; /* identity: eye at the origin looking down -z */
    perspective(60.0, 1.0, 0.1, 100.0, view.projection_matrix);
    view.viewport_width = 640;
    view.viewport_height = 480;
    CHECK(osgvis_context_set_mode(context, modes) == OSGVIS_OK);
    CHECK(osgvis_cull(context, &view) == OSGVIS_OK);
    CHECK(osgvis_visible_ids(context, ids, 20, &written, &total) == OSGVIS_OK);
    CHECK(written == count && total == count);
    for (i = 0; i < count && i < written; ++i)
        CHECK(ids[i] == expected[i]);
    if (written != count)
        fprintf(stderr, "mode %s: %u visible, expected %u\n", modes, (unsigned)written, (unsigned)count);
}

int main(void)
{
    static const uint32_t in_view[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    static const uint32_t even_in_view[5] = {0, 2, 4, 6, 8};
    osgvis_module_callbacks odd;
    osgvis_context* context = NULL;
    osgvis_statistics statistics;
    int i;

    CHECK(osgvis_version() == OSGVIS_VISAPI_VERSION);
    CHECK(osgvis_context_create(&context) == OSGVIS_OK);
    for (i = 0; i < 20; ++i)
    {
        const double z = i < 10 ? -5.0 - i : 5.0 + (i - 10);
        osgvis_object_desc box;
        uint32_t id = 0;
        memset(&box, 0, sizeof box);
        box.bounds_min[0] = box.bounds_min[1] = -0.5;
        box.bounds_max[0] = box.bounds_max[1] = 0.5;
        box.bounds_min[2] = z - 0.5;
        box.bounds_max[2] = z + 0.5;
        box.triangle_count = 12;
        CHECK(osgvis_scene_add_object(context, &box, &id) == OSGVIS_OK);
        CHECK(id == (uint32_t)i);
    }

    check_answer(context, "frustum", in_view, 10);
    CHECK(osgvis_statistics_get(context, &statistics) == OSGVIS_OK);
    CHECK(statistics.object_count == 20 && statistics.visible_count == 10);
    CHECK(statistics.triangle_count == 240 && statistics.visible_triangle_count == 120);
    CHECK(statistics.stage_count == 1);
    check_answer(context, "cfrustum", in_view, 10);

    memset(&odd, 0, sizeof odd);
    odd.api_version = OSGVIS_VISAPI_VERSION;
    odd.name = "codd";
    odd.create = odd_create;
    odd.destroy = odd_destroy;
    odd.set_scene = odd_set_scene;
    odd.cull = odd_cull;
    CHECK(osgvis_register_module("codd", &odd, &odd_state) == OSGVIS_OK);
    check_answer(context, "frustum+codd", even_in_view, 5);
    check_answer(context, "cfrustum,codd", even_in_view, 5);

    CHECK(osgvis_context_set_mode(context, "frustum+no-such-module") == OSGVIS_ERROR_UNKNOWN_MODE);
    CHECK(strncmp(osgvis_last_error(), "osgvis_context_set_mode: unknown mode 'no-such-module'", 54) == 0);
    odd.cull = NULL;
    CHECK(osgvis_register_module("codd-incomplete", &odd, NULL) == OSGVIS_ERROR_MODULE_LOAD);
    CHECK(strcmp(osgvis_last_error(), "osgvis_register_module: module registered as 'codd-incomplete': the callback "
                                      "table has no cull") == 0);

    {
        osgvis_hierarchy_desc hierarchy;
        osgvis_module_callbacks walk;
        memset(&hierarchy, 0, sizeof hierarchy);
        hierarchy.layout = OSGVIS_HIERARCHY_DISJOINT;
        hierarchy.node_count = 21;
        hierarchy.traverse = box_hierarchy_traverse;
        CHECK(osgvis_scene_set_hierarchy(context, &hierarchy) == OSGVIS_OK);
        memset(&walk, 0, sizeof walk);
        walk.api_version = OSGVIS_VISAPI_VERSION;
        walk.name = "cwalk";
        walk.create = odd_create;
        walk.destroy = odd_destroy;
        walk.set_scene = walk_set_scene;
        walk.cull = walk_cull;
        CHECK(osgvis_register_module("cwalk", &walk, &odd_state) == OSGVIS_OK);
        traversals = 0;
        check_answer(context, "cwalk", in_view, 10);
        CHECK(traversals == 1);
        check_answer(context, "cdt", in_view, 10); /* cdt checks the hierarchy, then walks it */
        CHECK(traversals >= 3);
    }

    osgvis_context_destroy(context);
    if (failures == 0)
        printf("visapi C99 test: ok\n");
    return failures == 0 ? 0 : 1;
}
