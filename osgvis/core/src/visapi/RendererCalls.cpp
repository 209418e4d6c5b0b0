// SPDX-License-Identifier: MIT
// The renderer side of osgVis/visapi.h: a context holds a core Scene, the cull session (the module
// chain the mode names, async and back-off as the OSG adapter's views have them), and the last
// answer. Each call checks its arguments and runs behind the exception boundary; an object handed
// with a sliver triangle is flagged here, as the OSG adapter flags its own.
#include <osgVis/visapi.h>

#include "CallbackHierarchy.h"
#include "ErrorBoundary.h"

#include <osgVis/core/session/CullSession.h>

#include <chrono>
#include <cmath>
#include <memory>

using namespace osgVis::core;
using osgVis::core::capi::ApiFailure;
using osgVis::core::capi::CallbackHierarchy;
using osgVis::core::capi::guarded;

struct osgvis_context
{
    Scene scene;
    SessionOptions sessionOptions;
    std::unique_ptr<CullSession> session; ///< null until a mode is chosen
    /// Changes the worker's copy of the scene lacks (async sessions only): handed over at the next cull.
    std::vector<SceneChange> pending;
    VisibleSet visible;
    osgvis_answer_info answer{};
    bool answered = false;
    double cullMilliseconds = 0.0;
};

// A renderer's flags go into the core unchanged: the C list must be the core's, bit for bit, and
// hold every core flag.
static_assert(OSGVIS_OBJECT_DYNAMIC == std::uint32_t(OBJECT_DYNAMIC), "OSGVIS_OBJECT_DYNAMIC");
static_assert(OSGVIS_OBJECT_OCCLUDER == std::uint32_t(OBJECT_OCCLUDER), "OSGVIS_OBJECT_OCCLUDER");
static_assert(OSGVIS_OBJECT_TRANSPARENT == std::uint32_t(OBJECT_TRANSPARENT), "OSGVIS_OBJECT_TRANSPARENT");
static_assert(OSGVIS_OBJECT_ALWAYS_VISIBLE == std::uint32_t(OBJECT_ALWAYS_VISIBLE), "OSGVIS_OBJECT_ALWAYS_VISIBLE");
static_assert(OSGVIS_OBJECT_NO_AUTO_OCCLUDER == std::uint32_t(OBJECT_NO_AUTO_OCCLUDER), "OSGVIS_OBJECT_NO_AUTO_OCCLUDER");
static_assert(OSGVIS_OBJECT_CULL_BACK == std::uint32_t(OBJECT_CULL_BACK), "OSGVIS_OBJECT_CULL_BACK");
static_assert(OSGVIS_OBJECT_CULL_FRONT == std::uint32_t(OBJECT_CULL_FRONT), "OSGVIS_OBJECT_CULL_FRONT");
static_assert(OSGVIS_OBJECT_SLIVERS == std::uint32_t(OBJECT_SLIVERS), "OSGVIS_OBJECT_SLIVERS");
static_assert(OSGVIS_OBJECT_UNOCCLUDABLE == std::uint32_t(OBJECT_UNOCCLUDABLE), "OSGVIS_OBJECT_UNOCCLUDABLE");
static_assert((OSGVIS_OBJECT_DYNAMIC | OSGVIS_OBJECT_OCCLUDER | OSGVIS_OBJECT_TRANSPARENT | OSGVIS_OBJECT_ALWAYS_VISIBLE |
               OSGVIS_OBJECT_NO_AUTO_OCCLUDER | OSGVIS_OBJECT_CULL_BACK | OSGVIS_OBJECT_CULL_FRONT |
               OSGVIS_OBJECT_SLIVERS | OSGVIS_OBJECT_UNOCCLUDABLE) == OBJECT_ALL_FLAGS,
              "a core ObjectFlags bit has no OSGVIS_OBJECT_* in osgVis/visapi.h");

namespace
{
void require(bool condition, const char* what)
{
    if (!condition)
        throw ApiFailure(OSGVIS_ERROR_INVALID_ARGUMENT, what);
}

Vec3 vec3(const double v[3])
{
    return {v[0], v[1], v[2]};
}

Mat4 mat4(const double m[16])
{
    Mat4 out;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            out[column][row] = m[column * 4 + row];
    return out;
}

bool finite(const Aabb& box)
{
    for (int i = 0; i < 3; ++i)
    {
        if (!std::isfinite(box.min[i]) || !std::isfinite(box.max[i]))
            return false;
    }
    return true;
}

// Appends triangle_count triangles; returns the index of the first.
std::uint32_t appendTriangles(Scene& scene, const float* triangles, std::uint32_t count)
{
    const auto first = static_cast<std::uint32_t>(scene.triangles.size());
    for (std::uint32_t t = 0; t < count; ++t)
    {
        const float* f = triangles + 9 * std::size_t(t);
        scene.triangles.push_back({Vec3f(f[0], f[1], f[2]), Vec3f(f[3], f[4], f[5]), Vec3f(f[6], f[7], f[8])});
    }
    return first;
}

// Appends the object's new triangles and points it at them. A sliver among them flags the object,
// as the OSG adapter does; nothing unflags it (the renderer may have flagged it itself).
void storeTriangles(Scene& scene, SceneObject& object, const float* triangles, std::uint32_t count)
{
    object.firstTriangle = appendTriangles(scene, triangles, count);
    object.triangleCount = count;
    if (hasSliverTriangle(scene.triangles.data() + object.firstTriangle, count))
        object.flags |= OBJECT_SLIVERS;
}

// Non-finite bounds make the object one no module may cull, as the OSG adapter does.
void setBounds(SceneObject& object, const Aabb& bounds)
{
    object.bounds = bounds;
    if (!finite(bounds))
        object.flags |= OBJECT_ALWAYS_VISIBLE;
}

std::vector<Vec3> polygonPoints(const double* points, std::uint32_t count)
{
    require(points && count >= 3, "a polygon needs points and at least 3 of them");
    std::vector<Vec3> out;
    for (std::uint32_t i = 0; i < count; ++i)
    {
        out.emplace_back(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
        require(std::isfinite(out.back().x) && std::isfinite(out.back().y) && std::isfinite(out.back().z),
                "a polygon point is not finite");
    }
    return out;
}

// The scene as the session takes it: the context's own, or, for a worker that reads it on its own
// thread while the renderer edits the context's, a copy.
std::shared_ptr<const Scene> sessionScene(const osgvis_context& context)
{
    if (context.sessionOptions.async && context.session && context.session->async())
        return std::make_shared<const Scene>(context.scene);
    return std::shared_ptr<const Scene>(&context.scene, [](const Scene*) {});
}

void notify(osgvis_context& context, SceneChange::Kind kind, ObjectId id)
{
    if (!context.session)
        return;
    if (context.session->async())
        context.pending.push_back({kind, {id}});
    else
        context.session->sceneChanged({kind, {id}});
}

void requireObject(const osgvis_context& context, std::uint32_t id)
{
    if (id >= context.scene.objects.size())
        throw ApiFailure(OSGVIS_ERROR_INVALID_ARGUMENT, "no object " + std::to_string(id));
}

void requireAnswer(const osgvis_context* context)
{
    require(context != nullptr, "null context");
    if (!context->answered)
        throw ApiFailure(OSGVIS_ERROR_BAD_STATE, "no query has been answered yet");
}

template <class Query> void timedQuery(osgvis_context& context, Query query)
{
    if (!context.session)
        throw ApiFailure(OSGVIS_ERROR_BAD_STATE, "no mode chosen (osgvis_context_set_mode)");
    context.answered = false;
    const auto start = std::chrono::steady_clock::now();
    if (!context.pending.empty())
    {
        context.session->sceneReplaced(sessionScene(context), context.pending);
        context.pending.clear();
    }
    query(*context.session, start);
    context.cullMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    context.answered = true;
}
} // namespace

// note: C linkage comes from the declarations in osgVis/visapi.h.
osgvis_status osgvis_context_create(osgvis_context** context)
{
    return guarded("osgvis_context_create",
                   [&]
                   {
                       require(context != nullptr, "null output");
                       *context = new osgvis_context;
                   });
}

void osgvis_context_destroy(osgvis_context* context)
{
    guarded("osgvis_context_destroy", [&] { delete context; });
}

osgvis_status osgvis_scene_add_object(osgvis_context* context, const osgvis_object_desc* object, uint32_t* id)
{
    return guarded("osgvis_scene_add_object",
                   [&]
                   {
                       require(context && object, "null context or object");
                       Scene& scene = context->scene;
                       const ObjectId added = scene.addObject({}, object->triangle_count, object->flags,
                                                              object->name ? std::string(object->name) : std::string());
                       SceneObject& o = scene.objects[added];
                       setBounds(o, {vec3(object->bounds_min), vec3(object->bounds_max)});
                       if (object->triangles)
                           storeTriangles(scene, o, object->triangles, object->triangle_count);
                       else
                           o.firstTriangle = static_cast<std::uint32_t>(scene.triangles.size()); // note: kept none
                       if (id)
                           *id = added;
                       notify(*context, SceneChange::Kind::Inserted, added);
                   });
}

osgvis_status osgvis_scene_add_occluder(osgvis_context* context, const double* points, uint32_t point_count,
                                        uint32_t owner)
{
    return guarded("osgvis_scene_add_occluder",
                   [&]
                   {
                       require(context != nullptr, "null context");
                       if (owner != OSGVIS_INVALID_OBJECT)
                           requireObject(*context, owner);
                       context->scene.occluders.push_back({ConvexPolygon(polygonPoints(points, point_count)), owner});
                   });
}

osgvis_status osgvis_scene_add_cell(osgvis_context* context, const double bounds_min[3], const double bounds_max[3],
                                    uint32_t* id)
{
    return guarded("osgvis_scene_add_cell",
                   [&]
                   {
                       require(context && bounds_min && bounds_max, "null context or bounds");
                       Cell cell;
                       cell.id = static_cast<std::uint32_t>(context->scene.cells.size());
                       cell.bounds = {vec3(bounds_min), vec3(bounds_max)};
                       require(finite(cell.bounds) && !cell.bounds.empty(), "a cell needs finite, non-empty bounds");
                       context->scene.cells.push_back(cell);
                       if (id)
                           *id = cell.id;
                   });
}

osgvis_status osgvis_scene_add_portal(osgvis_context* context, const double* points, uint32_t point_count,
                                      uint32_t cell_a, uint32_t cell_b)
{
    return guarded(
        "osgvis_scene_add_portal",
        [&]
        {
            require(context != nullptr, "null context");
            require(cell_a < context->scene.cells.size() && cell_b < context->scene.cells.size(),
                    "a portal joins two cells added before it");
            context->scene.portals.push_back({ConvexPolygon(polygonPoints(points, point_count)), cell_a, cell_b});
        });
}

osgvis_status osgvis_scene_move_object(osgvis_context* context, uint32_t id, const double bounds_min[3],
                                       const double bounds_max[3], const float* triangles, uint32_t triangle_count)
{
    return guarded("osgvis_scene_move_object",
                   [&]
                   {
                       require(context && bounds_min && bounds_max, "null context or bounds");
                       requireObject(*context, id);
                       SceneObject& o = context->scene.objects[id];
                       setBounds(o, {vec3(bounds_min), vec3(bounds_max)});
                       // note: the old triangles stay in the array, unreferenced, so no other object's range moves.
                       if (triangles)
                           storeTriangles(context->scene, o, triangles, triangle_count);
                       notify(*context, SceneChange::Kind::Moved, id);
                   });
}

osgvis_status osgvis_scene_remove_object(osgvis_context* context, uint32_t id)
{
    return guarded("osgvis_scene_remove_object",
                   [&]
                   {
                       require(context != nullptr, "null context");
                       requireObject(*context, id);
                       if (!context->session)
                           throw ApiFailure(OSGVIS_ERROR_BAD_STATE,
                                            "removing needs a mode (a scene not yet culled is still "
                                            "being described: leave the object out)");
                       notify(*context, SceneChange::Kind::Removed, id);
                   });
}

osgvis_status osgvis_context_set_mode(osgvis_context* context, const char* modes)
{
    return guarded("osgvis_context_set_mode",
                   [&]
                   {
                       require(context && modes, "null context or modes");
                       SessionOptions options = context->sessionOptions;
                       options.modes = modes;
                       context->session.reset(); // its worker joined before the new one starts
                       context->pending.clear();
                       context->session = std::make_unique<CullSession>(options);
                       context->session->setScene(sessionScene(*context));
                       context->answered = false;
                   });
}

osgvis_status osgvis_context_set_session(osgvis_context* context, const osgvis_session_desc* session)
{
    return guarded("osgvis_context_set_session",
                   [&]
                   {
                       require(context && session, "null context or session");
                       context->sessionOptions.async = session->async != 0;
                       context->sessionOptions.backOff.enabled = session->back_off != 0;
                   });
}

osgvis_status osgvis_answer_info_get(const osgvis_context* context, osgvis_answer_info* info)
{
    return guarded("osgvis_answer_info_get",
                   [&]
                   {
                       requireAnswer(context);
                       require(info != nullptr, "null output");
                       *info = context->answer;
                   });
}

osgvis_status osgvis_cull(osgvis_context* context, const osgvis_view_desc* view)
{
    return guarded("osgvis_cull",
                   [&]
                   {
                       require(context && view, "null context or view");
                       const View v = makeView(mat4(view->view_matrix), mat4(view->projection_matrix), view->time,
                                               view->viewport_width, view->viewport_height);
                       timedQuery(*context,
                                  [&](CullSession& session, std::chrono::steady_clock::time_point start)
                                  {
                                      context->visible = session.cull(v, start);
                                      const SessionFigures& figures = session.figures();
                                      context->answer.from_region = figures.async && !figures.asyncFallback;
                                      context->answer.region_missed = figures.asyncFallback;
                                      context->answer.backed_off = figures.backedOff;
                                  });
                   });
}

osgvis_status osgvis_cull_region(osgvis_context* context, const osgvis_region_desc* region)
{
    return guarded("osgvis_cull_region",
                   [&]
                   {
                       require(context && region, "null context or region");
                       if (context->session && !context->session->chain().supportsRegions())
                           throw ApiFailure(OSGVIS_ERROR_UNSUPPORTED,
                                            "mode '" + context->session->chain().name() + "' has no region answers");
                       ViewRegion r;
                       r.eyes = {vec3(region->eyes_min), vec3(region->eyes_max)};
                       r.minNearDistance = region->min_near_distance;
                       r.maxNearReach = region->max_near_reach;
                       timedQuery(*context,
                                  [&](CullSession& session, std::chrono::steady_clock::time_point)
                                  {
                                      session.chain().cullRegion(r, context->visible);
                                      context->answer = {};
                                  });
                   });
}

osgvis_status osgvis_visible_ids(const osgvis_context* context, uint32_t* ids, size_t capacity, size_t* written,
                                 size_t* count)
{
    return guarded("osgvis_visible_ids",
                   [&]
                   {
                       requireAnswer(context);
                       const VisibleSet& visible = context->visible;
                       size_t n = 0, stored = 0;
                       for (ObjectId id = 0; id < visible.capacity(); ++id)
                       {
                           if (!visible.test(id))
                               continue;
                           if (ids && stored < capacity)
                               ids[stored++] = id;
                           ++n;
                       }
                       if (written)
                           *written = stored;
                       if (count)
                           *count = n;
                   });
}

int osgvis_is_visible(const osgvis_context* context, uint32_t id)
{
    return context && context->answered && context->visible.test(id) ? 1 : 0;
}

osgvis_status osgvis_statistics_get(const osgvis_context* context, osgvis_statistics* statistics)
{
    return guarded("osgvis_statistics_get",
                   [&]
                   {
                       requireAnswer(context);
                       require(statistics != nullptr, "null output");
                       osgvis_statistics s{};
                       s.object_count = static_cast<uint32_t>(context->scene.objects.size());
                       for (const SceneObject& o : context->scene.objects)
                       {
                           s.triangle_count += o.triangleCount;
                           if (context->visible.test(o.id))
                           {
                               ++s.visible_count;
                               s.visible_triangle_count += o.triangleCount;
                           }
                       }
                       s.cull_milliseconds = context->cullMilliseconds;
                       s.stage_count = static_cast<uint32_t>(context->session->chain().lastTimings().size());
                       *statistics = s;
                   });
}

osgvis_status osgvis_stage_statistics(const osgvis_context* context, uint32_t index, const char** name,
                                      double* milliseconds, uint32_t* visible_after)
{
    return guarded("osgvis_stage_statistics",
                   [&]
                   {
                       requireAnswer(context);
                       const std::vector<StageTiming>& timings = context->session->chain().lastTimings();
                       if (index >= timings.size())
                           throw ApiFailure(OSGVIS_ERROR_INVALID_ARGUMENT, "no stage " + std::to_string(index));
                       if (name)
                           *name = timings[index].module.c_str();
                       if (milliseconds)
                           *milliseconds = timings[index].milliseconds;
                       if (visible_after)
                           *visible_after = static_cast<uint32_t>(timings[index].visibleAfter);
                   });
}

osgvis_status osgvis_scene_set_hierarchy(osgvis_context* context, const osgvis_hierarchy_desc* hierarchy)
{
    return guarded("osgvis_scene_set_hierarchy",
                   [&]
                   {
                       require(context != nullptr, "null context");
                       if (!hierarchy)
                       {
                           context->scene.hierarchy.reset();
                           return;
                       }
                       require(hierarchy->traverse != nullptr, "the hierarchy has no traverse callback");
                       require(hierarchy->layout == OSGVIS_HIERARCHY_DISJOINT ||
                                   hierarchy->layout == OSGVIS_HIERARCHY_OVERLAPPING,
                               "the layout is neither OSGVIS_HIERARCHY_DISJOINT nor OSGVIS_HIERARCHY_OVERLAPPING");
                       require(hierarchy->node_count > 0, "the hierarchy has no nodes");
                       context->scene.hierarchy = std::make_shared<CallbackHierarchy>(*hierarchy);
                   });
}

osgvis_status osgvis_scene_set_attribute(osgvis_context* context, uint32_t object, const char* name, const void* data,
                                         size_t size)
{
    return guarded("osgvis_scene_set_attribute",
                   [&]
                   {
                       require(context && name && *name, "null context or empty name");
                       require(size == 0 || data, "null data");
                       if (object != OSGVIS_INVALID_OBJECT)
                           requireObject(*context, object);
                       const auto* bytes = static_cast<const std::uint8_t*>(data);
                       context->scene.attributes.set(object, name, std::vector<std::uint8_t>(bytes, bytes + size));
                   });
}

osgvis_status osgvis_scene_set_mesh(osgvis_context* context, uint32_t object, const float* positions,
                                    uint32_t vertex_count, const uint32_t* indices, uint32_t triangle_count)
{
    return guarded("osgvis_scene_set_mesh",
                   [&]
                   {
                       require(context != nullptr, "null context");
                       requireObject(*context, object);
                       require((positions || vertex_count == 0) && (indices || triangle_count == 0),
                               "null positions or indices");
                       std::vector<Vec3f> points;
                       points.reserve(vertex_count);
                       for (std::uint32_t i = 0; i < vertex_count; ++i)
                       {
                           points.emplace_back(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
                           require(std::isfinite(points.back().x) && std::isfinite(points.back().y) &&
                                       std::isfinite(points.back().z),
                                   "a position is not finite");
                       }
                       context->scene.meshes[object] =
                           WingedEdgeMesh(std::move(points), std::vector<std::uint32_t>(indices, indices + 3 * std::size_t(triangle_count)));
                   });
}
