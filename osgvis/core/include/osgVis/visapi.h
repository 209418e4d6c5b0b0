/* SPDX-License-Identifier: MIT */
/**
 * @file
 * The visibility API as C99: a renderer describes its scene, culls a view and reads the visible set
 * (renderer side); a visibility module implements a table of callbacks that sees the scene and the
 * view read-only (module side), in-process or as a plugin `osgvis_module_<name>.so`.
 * docs/visapi.md has the threading rules, ownership, and how to write a module or host osgVis.
 *
 * Every function that can fail returns an osgvis_status; on failure osgvis_last_error() names the
 * reason. No function lets a C++ exception out.
 */
#ifndef OSGVIS_VISAPI_H
#define OSGVIS_VISAPI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define OSGVIS_VISAPI_EXPORT __attribute__((visibility("default")))
#else
#define OSGVIS_VISAPI_EXPORT
#endif

/** The API version a program or module is compiled against: major changes break the ABI; a minor
 * one only adds. A host loads a module of the same major and a minor no newer than its own. */
#define OSGVIS_VISAPI_VERSION_MAJOR 1
#define OSGVIS_VISAPI_VERSION_MINOR 3
#define OSGVIS_VISAPI_VERSION ((OSGVIS_VISAPI_VERSION_MAJOR << 16) | OSGVIS_VISAPI_VERSION_MINOR)

/** Id of no object (an occluder without owner). */
#define OSGVIS_INVALID_OBJECT 0xFFFFFFFFu

typedef enum osgvis_status
{
    OSGVIS_OK = 0,
    OSGVIS_ERROR_INVALID_ARGUMENT = 1, /**< null pointer, unknown id, non-finite number, ... */
    OSGVIS_ERROR_UNKNOWN_MODE = 2,     /**< no built-in module and no plugin of that name */
    OSGVIS_ERROR_MODULE_LOAD = 3,      /**< a plugin was found but cannot be used */
    OSGVIS_ERROR_MODULE_FAILED = 4,    /**< a module callback reported failure */
    OSGVIS_ERROR_BAD_STATE = 5,        /**< a call out of order (cull before a mode was chosen) */
    OSGVIS_ERROR_UNSUPPORTED = 6,      /**< e.g. a region query on a chain without region answers */
    OSGVIS_ERROR_OUT_OF_MEMORY = 7,
    OSGVIS_ERROR_INTERNAL = 8 /**< an unexpected exception inside osgVis */
} osgvis_status;

/** Object flags (the values of osgVis::core::ObjectFlags, checked at compile time). */
enum
{
    OSGVIS_OBJECT_DYNAMIC = 1u << 0,
    OSGVIS_OBJECT_OCCLUDER = 1u << 1,
    OSGVIS_OBJECT_TRANSPARENT = 1u << 2,
    OSGVIS_OBJECT_ALWAYS_VISIBLE = 1u << 3,
    OSGVIS_OBJECT_NO_AUTO_OCCLUDER = 1u << 4,
    OSGVIS_OBJECT_CULL_BACK = 1u << 5,
    OSGVIS_OBJECT_CULL_FRONT = 1u << 6,
    /** Version 1.3. Has a sliver triangle (distinct corners on one line up to float storage): its
     * pixels may take any depth, so no occlusion hides it. osgvis_scene_add_object and
     * osgvis_scene_move_object set it themselves when the triangles they are given have one. */
    OSGVIS_OBJECT_SLIVERS = 1u << 7,
    /** Version 1.3. Drawn without a depth test nearer geometry could fail (depth test off, a depth
     * function other than LESS, LEQUAL or EQUAL, a depth range other than [0, 1]): no occlusion
     * hides it. */
    OSGVIS_OBJECT_UNOCCLUDABLE = 1u << 8
};

/** OSGVIS_VISAPI_VERSION of the library at run time. */
OSGVIS_VISAPI_EXPORT uint32_t osgvis_version(void);
/** "OSGVIS_OK", "OSGVIS_ERROR_INVALID_ARGUMENT", ...; "unknown status" otherwise. */
OSGVIS_VISAPI_EXPORT const char* osgvis_status_name(osgvis_status status);
/** Message of the last failed call on this thread ("" when none failed); valid until the next
 * failing call on this thread. */
OSGVIS_VISAPI_EXPORT const char* osgvis_last_error(void);

/* ---- scene and view data (both sides) ---- */

/** An object as the renderer describes it. World space; matrices and bounds in double. */
typedef struct osgvis_object_desc
{
    double bounds_min[3], bounds_max[3];
    uint32_t flags;          /**< OSGVIS_OBJECT_* */
    uint32_t triangle_count; /**< triangles drawn (weights statistics), even when none are given */
    const float* triangles;  /**< NULL, or 9 * triangle_count floats: a b c per triangle, CCW front */
    const char* name;        /**< NULL or a name for reports; copied */
} osgvis_object_desc;

/** One view: the eye is taken from the view matrix. Matrices are column-major (OpenGL, GLM). */
typedef struct osgvis_view_desc
{
    double view_matrix[16];       /**< world to eye, looking down -z */
    double projection_matrix[16]; /**< eye to clip */
    double time;                  /**< walk time in seconds (never the wall clock) */
    uint32_t viewport_width, viewport_height;
} osgvis_view_desc;

/** Every eye in a box, looking anywhere, with near planes in the given bounds (core ViewRegion). */
typedef struct osgvis_region_desc
{
    double eyes_min[3], eyes_max[3];
    double min_near_distance; /**< nearest near plane of a view the answer holds for */
    double max_near_reach;    /**< farthest near-plane corner from the eye */
} osgvis_region_desc;

typedef enum osgvis_change_kind
{
    OSGVIS_CHANGE_INSERTED = 0, /**< objects appended */
    OSGVIS_CHANGE_MOVED = 1,    /**< bounds or triangles changed */
    OSGVIS_CHANGE_REMOVED = 2   /**< no longer drawn; ids stay valid and are never reported */
} osgvis_change_kind;

/** A renderer's hierarchy (version 1.1): how its nodes relate. */
typedef enum osgvis_hierarchy_layout
{
    /** kd-tree, BSP, octree cells: siblings do not overlap, a child lies in its parent, an object
     * lies in the node holding it; children are visited so that no later sibling lies in front of
     * an earlier one as seen from the eye. */
    OSGVIS_HIERARCHY_DISJOINT = 0,
    /** A BVH or a scene graph's bounding boxes: nodes may overlap. */
    OSGVIS_HIERARCHY_OVERLAPPING = 1
} osgvis_hierarchy_layout;

/** One node as a traversal hands it over (valid during the call it is passed to). */
typedef struct osgvis_hierarchy_node
{
    uint32_t id;                             /**< stable, below the hierarchy's node_count */
    double region_min[3], region_max[3];     /**< its region (disjoint) or bounding box (overlapping) */
    const uint32_t* objects;                 /**< the objects held at this node, not its children's */
    uint32_t object_count;
} osgvis_hierarchy_node;

/** What a traversal calls: enter returns nonzero to descend into the node's children; leave comes
 * after the children of a node whose enter returned nonzero. */
typedef struct osgvis_hierarchy_visitor
{
    void* state;
    int (*enter)(void* state, const osgvis_hierarchy_node* node);
    void (*leave)(void* state, const osgvis_hierarchy_node* node);
} osgvis_hierarchy_visitor;

/** A renderer's own hierarchy, walked front to back by callback. */
typedef struct osgvis_hierarchy_desc
{
    osgvis_hierarchy_layout layout;
    uint32_t node_count;
    void* user_data;
    /** Depth first from the root, the children nearest to `eye` first; the same nodes with the same
     * regions and objects every time (a module checks, and keeps everything when they differ). */
    void (*traverse)(void* user_data, const double eye[3], const osgvis_hierarchy_visitor* visitor);
    /** Optional: called once when osgVis no longer needs the hierarchy. */
    void (*destroy)(void* user_data);
} osgvis_hierarchy_desc;

/* ---- renderer side ---- */

/** A scene, a chosen mode (module chain) and the last answer. Owned by the caller. */
typedef struct osgvis_context osgvis_context;

OSGVIS_VISAPI_EXPORT osgvis_status osgvis_context_create(osgvis_context** context);
/** Destroys the context and its modules; NULL is allowed. */
OSGVIS_VISAPI_EXPORT void osgvis_context_destroy(osgvis_context* context);

/** Appends an object; *id (may be NULL) receives its id, which is its index (0, 1, ...). After a mode
 * is chosen this notifies the modules (an insertion). */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_add_object(osgvis_context* context, const osgvis_object_desc* object,
                                                           uint32_t* id);
/** A convex occluder polygon of point_count points (xyz each, CCW seen from its front), owned by
 * object `owner` or OSGVIS_INVALID_OBJECT. Occluders are part of the build phase: add them before
 * choosing a mode (afterwards they reach the modules at the next osgvis_context_set_mode). */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_add_occluder(osgvis_context* context, const double* points,
                                                             uint32_t point_count, uint32_t owner);
/** A cell of the modeller's cell structure (build phase, like occluders); *id receives its id. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_add_cell(osgvis_context* context, const double bounds_min[3],
                                                         const double bounds_max[3], uint32_t* id);
/** A portal between two cells (build phase). */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_add_portal(osgvis_context* context, const double* points,
                                                           uint32_t point_count, uint32_t cell_a, uint32_t cell_b);
/** Version 1.1. Hands the renderer's hierarchy to the modules (build phase, like occluders:
 * it reaches them at the next osgvis_context_set_mode); NULL removes it. Modules that walk a
 * hierarchy (cdt) walk it instead of their own, after checking it (docs/visapi.md); traverse is
 * then called from osgvis_cull, on the calling thread. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_set_hierarchy(osgvis_context* context,
                                                              const osgvis_hierarchy_desc* hierarchy);
/** Version 1.1. Attaches `size` bytes (copied) under `name` to object `object`, or to the scene
 * when object is OSGVIS_INVALID_OBJECT: data osgVis does not know, for modules that do. A second
 * call with the same name replaces the bytes; size 0 removes them. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_set_attribute(osgvis_context* context, uint32_t object,
                                                              const char* name, const void* data, size_t size);
/** Version 1.1. The object's connectivity: vertex_count positions (xyz floats, world space) and
 * triangle_count triangles of 3 indices, counter-clockwise seen from the front (copied). Nothing
 * trusts it: osgvis_scene_silhouette answers only for a mesh that is closed. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_set_mesh(osgvis_context* context, uint32_t object,
                                                         const float* positions, uint32_t vertex_count,
                                                         const uint32_t* indices, uint32_t triangle_count);
/** New bounds (and triangles, when `triangles` is not NULL) for an object; notifies the modules. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_move_object(osgvis_context* context, uint32_t id,
                                                            const double bounds_min[3], const double bounds_max[3],
                                                            const float* triangles, uint32_t triangle_count);
/** The object is no longer drawn; its id stays taken and is never reported visible. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_remove_object(osgvis_context* context, uint32_t id);

/** Chooses the modules by name: "frustum", "frustum+octree", "frustum,mymodule" (a name no module
 * of the library has is looked for as a plugin). Builds them on the scene (may take long). */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_context_set_mode(osgvis_context* context, const char* modes);

/** Version 1.2. How osgvis_cull answers, as the OSG adapter's views do (docs/visapi.md): `async`
 * nonzero gives the context a worker thread that answers regions of viewpoints ahead of the eye
 * (modes with region answers; the others stay synchronous), so a cull only cuts a finished region's
 * answer to its frustum, and culls with the chain when no region holds the view; `back_off` nonzero
 * times the interval between osgvis_cull calls (a frame) with and without the chain, on synchronous
 * culls, and skips the chain where it costs more than it saves (every object is visible then). Both
 * 0 by default; takes effect at the next osgvis_context_set_mode. With `async`, each osgvis_cull after
 * scene changes hands the worker a copy of the scene. */
typedef struct osgvis_session_desc
{
    int async;
    int back_off;
} osgvis_session_desc;
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_context_set_session(osgvis_context* context,
                                                              const osgvis_session_desc* session);
/** Version 1.2. How the last osgvis_cull was answered (1 or 0 each): by the worker's region answer,
 * by the chain although a worker runs (no region held the view), or with every object visible (the
 * chain skipped by back-off). */
typedef struct osgvis_answer_info
{
    int from_region, region_missed, backed_off;
} osgvis_answer_info;
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_answer_info_get(const osgvis_context* context, osgvis_answer_info* info);

/** Culls one view. Never culls a visible object unless a stage of the mode is approximate. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_cull(osgvis_context* context, const osgvis_view_desc* view);
/** Culls for a whole region of views (OSGVIS_ERROR_UNSUPPORTED when a stage cannot). */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_cull_region(osgvis_context* context, const osgvis_region_desc* region);

/** The last answer: number of visible objects, and their ids ascending into `ids` (up to `capacity`;
 * *written, may be NULL, says how many). ids may be NULL to ask only for the count. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_visible_ids(const osgvis_context* context, uint32_t* ids, size_t capacity,
                                                      size_t* written, size_t* count);
/** 1 when object `id` is in the last answer, else 0. */
OSGVIS_VISAPI_EXPORT int osgvis_is_visible(const osgvis_context* context, uint32_t id);

typedef struct osgvis_statistics
{
    uint32_t object_count, visible_count;
    uint64_t triangle_count, visible_triangle_count;
    double cull_milliseconds; /**< the whole last query, every stage */
    uint32_t stage_count;
} osgvis_statistics;

OSGVIS_VISAPI_EXPORT osgvis_status osgvis_statistics_get(const osgvis_context* context, osgvis_statistics* statistics);
/** Stage `index` of the last query: its module name (valid until the next set_mode), its time and
 * how many objects it kept. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_stage_statistics(const osgvis_context* context, uint32_t index,
                                                           const char** name, double* milliseconds,
                                                           uint32_t* visible_after);

/* ---- module side: what a module sees (read-only, valid during the callback) ---- */

typedef struct osgvis_scene osgvis_scene;
typedef struct osgvis_view osgvis_view;
typedef struct osgvis_region osgvis_region;
/** The candidates of a query: a module may only remove objects from it. */
typedef struct osgvis_visible osgvis_visible;

typedef struct osgvis_object_info
{
    double bounds_min[3], bounds_max[3];
    uint32_t flags, triangle_count;
    const float* triangles;  /**< 9 floats per triangle, or NULL when the renderer kept none */
    uint32_t triangles_kept; /**< how many `triangles` holds */
} osgvis_object_info;

OSGVIS_VISAPI_EXPORT uint32_t osgvis_scene_object_count(const osgvis_scene* scene);
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_object(const osgvis_scene* scene, uint32_t id,
                                                       osgvis_object_info* info);
OSGVIS_VISAPI_EXPORT uint32_t osgvis_scene_occluder_count(const osgvis_scene* scene);
/** Occluder `index`: its owner, and its points (xyz) into `points` (3 * capacity doubles). *point_count
 * receives the polygon's number of points even when capacity is smaller. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_occluder(const osgvis_scene* scene, uint32_t index, uint32_t* owner,
                                                         double* points, uint32_t capacity, uint32_t* point_count);
OSGVIS_VISAPI_EXPORT uint32_t osgvis_scene_cell_count(const osgvis_scene* scene);
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_cell(const osgvis_scene* scene, uint32_t index, double bounds_min[3],
                                                     double bounds_max[3]);

OSGVIS_VISAPI_EXPORT uint32_t osgvis_scene_portal_count(const osgvis_scene* scene);
/** Portal `index` (version 1.1): its cells and its points, as osgvis_scene_occluder gives them. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_portal(const osgvis_scene* scene, uint32_t index, uint32_t* cell_a,
                                                       uint32_t* cell_b, double* points, uint32_t capacity,
                                                       uint32_t* point_count);
/** Version 1.1: 1 when the renderer handed over a hierarchy (its layout and node count then go to
 * the outputs that are not NULL), else 0. */
OSGVIS_VISAPI_EXPORT int osgvis_scene_hierarchy(const osgvis_scene* scene, osgvis_hierarchy_layout* layout,
                                                uint32_t* node_count);
/** Version 1.1: walks the renderer's hierarchy front to back from `eye` with `visitor`. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_traverse(const osgvis_scene* scene, const double eye[3],
                                                         const osgvis_hierarchy_visitor* visitor);
/** Version 1.1: 1 and the bytes (valid as long as the scene handle) when `name` is attached to
 * `object` (OSGVIS_INVALID_OBJECT: the scene), else 0 with *data NULL and *size 0. */
OSGVIS_VISAPI_EXPORT int osgvis_scene_attribute(const osgvis_scene* scene, uint32_t object, const char* name,
                                                const void** data, size_t* size);
/** Version 1.1: the edges of the object's mesh where a face turned to `eye` meets one turned away,
 * as vertex index pairs into `edges` (2 * capacity); *edge_count receives how many there are.
 * OSGVIS_ERROR_UNSUPPORTED (the reason in osgvis_last_error) when the object has no mesh or its mesh
 * is not closed: an edge used by other than exactly two faces, two faces using an edge in the same
 * direction, an index out of range, a degenerate face. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_scene_silhouette(const osgvis_scene* scene, uint32_t object,
                                                           const double eye[3], uint32_t* edges, uint32_t capacity,
                                                           uint32_t* edge_count);

typedef struct osgvis_view_info
{
    double eye[3];
    double view_matrix[16], projection_matrix[16];
    double frustum_planes[6][4]; /**< left right bottom top near far: n.p + d >= 0 inside, unit n */
    double time;
    uint32_t viewport_width, viewport_height;
    int orthographic;
} osgvis_view_info;

OSGVIS_VISAPI_EXPORT osgvis_status osgvis_view_get(const osgvis_view* view, osgvis_view_info* info);
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_region_get(const osgvis_region* region, osgvis_region_desc* info);

OSGVIS_VISAPI_EXPORT uint32_t osgvis_visible_capacity(const osgvis_visible* visible);
OSGVIS_VISAPI_EXPORT int osgvis_visible_test(const osgvis_visible* visible, uint32_t id);
/** Removes `id` from the candidates (OSGVIS_ERROR_INVALID_ARGUMENT past the capacity). */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_visible_clear(osgvis_visible* visible, uint32_t id);

/* ---- module side: what a module implements ---- */

/** The callbacks of one module. `state` is what create returned. A callback returns OSGVIS_OK or a
 * failure status; after a failure the host asks error_message (when set) for the reason. A failed
 * cull leaves every candidate visible; a failed set_scene or scene_changed leaves every candidate
 * visible until the next successful set_scene. */
typedef struct osgvis_module_callbacks
{
    uint32_t api_version; /**< OSGVIS_VISAPI_VERSION the module was built against */
    const char* name;     /**< the stage name reports show */
    int approximate;      /**< nonzero when the module may cull visible objects (name it `approx`) */
    /** New state, or NULL on failure; `user_data` is what osgvis_register_module was given (NULL
     * for plugins). */
    void* (*create)(void* user_data);
    void (*destroy)(void* state);
    /** Build phase: may take long. The scene handle stays valid until the next set_scene or destroy. */
    osgvis_status (*set_scene)(void* state, const osgvis_scene* scene);
    /** Optional (NULL: set_scene is called again). */
    osgvis_status (*scene_changed)(void* state, const osgvis_scene* scene, osgvis_change_kind kind,
                                   const uint32_t* ids, size_t id_count);
    /** Query phase: remove from `visible` what cannot be seen from `view`. */
    osgvis_status (*cull)(void* state, const osgvis_view* view, osgvis_visible* visible);
    /** Optional (NULL: no region answers): the same for every view of `region`. */
    osgvis_status (*cull_region)(void* state, const osgvis_region* region, osgvis_visible* visible);
    /** Optional: why the last callback failed (valid until the next callback). */
    const char* (*error_message)(void* state);
} osgvis_module_callbacks;

/** The one symbol a plugin `osgvis_module_<name>.so` exports. It receives the host's
 * OSGVIS_VISAPI_VERSION and returns its callback table (static storage), or NULL to refuse. */
#define OSGVIS_MODULE_ENTRY_SYMBOL "osgvis_module_entry"
typedef const osgvis_module_callbacks* (*osgvis_module_entry_fn)(uint32_t host_version);

/** Makes a module implemented in this process available under `name` to every mode string (and to
 * the C++ createModule/createChain). The table must outlive every module made from it. */
OSGVIS_VISAPI_EXPORT osgvis_status osgvis_register_module(const char* name, const osgvis_module_callbacks* callbacks,
                                                          void* user_data);

#ifdef __cplusplus
}
#endif

#endif /* OSGVIS_VISAPI_H */
