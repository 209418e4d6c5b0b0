// SPDX-License-Identifier: MIT
// The renderer side of osgVis/visapi.h: a scene described through the C calls culls to exactly the
// sets the C++ chain answers on the same core Scene; scene changes reach the modules; every misuse
// gives its status and message; a renderer's hierarchy, attributes and meshes reach the modules.
#include "BoxScenes.h"
#include "RandomBoxScene.h"
#include "RegionSampling.h"

#include <osgVis/visapi.h>

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/spatial/DisjointCellTree.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <chrono>
#include <memory>
#include <thread>

using namespace osgVis::core;

namespace
{
struct ContextDeleter
{
    void operator()(osgvis_context* context) const { osgvis_context_destroy(context); }
};
using Context = std::unique_ptr<osgvis_context, ContextDeleter>;

Context newContext()
{
    osgvis_context* context = nullptr;
    EXPECT_EQ(osgvis_context_create(&context), OSGVIS_OK);
    return Context(context);
}

void copy(const Vec3& v, double out[3])
{
    out[0] = v.x, out[1] = v.y, out[2] = v.z;
}

void copy(const Mat4& m, double out[16])
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            out[4 * c + r] = m[c][r];
}

// The scene through the C calls: objects with their triangles, then its occluders.
void describe(osgvis_context* context, const Scene& scene)
{
    for (const SceneObject& o : scene.objects)
    {
        osgvis_object_desc desc{};
        copy(o.bounds.min, desc.bounds_min);
        copy(o.bounds.max, desc.bounds_max);
        desc.flags = o.flags;
        desc.triangle_count = o.triangleCount;
        desc.triangles = &scene.triangles[o.firstTriangle].a.x;
        desc.name = o.name.c_str();
        uint32_t id = 0;
        ASSERT_EQ(osgvis_scene_add_object(context, &desc, &id), OSGVIS_OK) << osgvis_last_error();
        ASSERT_EQ(id, o.id);
    }
}

osgvis_view_desc viewDesc(const View& view)
{
    osgvis_view_desc desc{};
    copy(view.viewMatrix, desc.view_matrix);
    copy(view.projectionMatrix, desc.projection_matrix);
    desc.viewport_width = view.viewportWidth;
    desc.viewport_height = view.viewportHeight;
    return desc;
}

std::vector<ObjectId> visibleIds(const osgvis_context* context)
{
    size_t count = 0;
    EXPECT_EQ(osgvis_visible_ids(context, nullptr, 0, nullptr, &count), OSGVIS_OK) << osgvis_last_error();
    std::vector<ObjectId> ids(count);
    size_t written = 0;
    EXPECT_EQ(osgvis_visible_ids(context, ids.data(), ids.size(), &written, &count), OSGVIS_OK);
    EXPECT_EQ(written, count);
    return ids;
}

// Ten unit boxes on -z in front of an eye at the origin looking down -z.
osgvis_view_desc lookDownMinusZ()
{
    return viewDesc(makeView(Mat4(1.0), glm::perspective(glm::radians(60.0), 1.0, 0.1, 100.0)));
}

void addUnitBox(osgvis_context* context, double z)
{
    osgvis_object_desc desc{{-0.5, -0.5, z - 0.5}, {0.5, 0.5, z + 0.5}, 0, 12, nullptr, nullptr};
    ASSERT_EQ(osgvis_scene_add_object(context, &desc, nullptr), OSGVIS_OK);
}
} // namespace

TEST(VisApi, VersionAndStatusNames)
{
    EXPECT_EQ(osgvis_version(), OSGVIS_VISAPI_VERSION);
    EXPECT_STREQ(osgvis_status_name(OSGVIS_ERROR_MODULE_LOAD), "OSGVIS_ERROR_MODULE_LOAD");
    EXPECT_STREQ(osgvis_status_name(static_cast<osgvis_status>(99)), "unknown status");
}

TEST(VisApi, AnswersWhatTheChainAnswersOnTheSameScene)
{
    const Scene scene = osgVis::test::randomBoxScene(21, 400);
    const std::vector<View> views = osgVis::test::randomViews(22, 60);
    for (const char* modes : {"frustum", "frustum+octree", "frustum+mask"})
    {
        Context context = newContext();
        describe(context.get(), scene);
        ASSERT_EQ(osgvis_context_set_mode(context.get(), modes), OSGVIS_OK) << osgvis_last_error();
        ModuleChain chain = createChain(modes);
        chain.setScene(scene);
        for (const View& view : views)
        {
            const osgvis_view_desc desc = viewDesc(view);
            ASSERT_EQ(osgvis_cull(context.get(), &desc), OSGVIS_OK) << osgvis_last_error();
            VisibleSet expected;
            chain.cull(view, expected);
            EXPECT_EQ(visibleIds(context.get()), expected.ids()) << modes;

            osgvis_statistics statistics{};
            ASSERT_EQ(osgvis_statistics_get(context.get(), &statistics), OSGVIS_OK);
            EXPECT_EQ(statistics.object_count, scene.objects.size());
            EXPECT_EQ(statistics.visible_count, expected.count());
            EXPECT_EQ(statistics.triangle_count, 12u * scene.objects.size());
            EXPECT_EQ(statistics.visible_triangle_count, 12u * expected.count());
            EXPECT_EQ(statistics.stage_count, chain.size());
            const char* stage = nullptr;
            uint32_t after = 0;
            ASSERT_EQ(osgvis_stage_statistics(context.get(), 0, &stage, nullptr, &after), OSGVIS_OK);
            EXPECT_STREQ(stage, "frustum");
        }
    }
}

// The plugin `cfrustum` has no scene_changed: its CallbackModule hands it the scene again.
TEST(VisApi, SceneChangesReachTheModules)
{
    for (const char* modes : {"frustum", "cfrustum"})
    {
        Context context = newContext();
        for (int i = 0; i < 3; ++i)
            addUnitBox(context.get(), -5.0 - 2.0 * i); // ids 0 1 2, all in view
        addUnitBox(context.get(), 5.0);                // id 3, behind the eye
        ASSERT_EQ(osgvis_context_set_mode(context.get(), modes), OSGVIS_OK) << osgvis_last_error();
        const osgvis_view_desc view = lookDownMinusZ();
        ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
        EXPECT_EQ(visibleIds(context.get()), (std::vector<ObjectId>{0, 1, 2})) << modes;

        const double behindMin[3] = {-0.5, -0.5, 9.5}, behindMax[3] = {0.5, 0.5, 10.5};
        ASSERT_EQ(osgvis_scene_move_object(context.get(), 1, behindMin, behindMax, nullptr, 0), OSGVIS_OK);
        ASSERT_EQ(osgvis_scene_remove_object(context.get(), 2), OSGVIS_OK);
        addUnitBox(context.get(), -20.0); // id 4, inserted after the mode was chosen
        ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
        EXPECT_EQ(visibleIds(context.get()), (std::vector<ObjectId>{0, 4})) << modes;
        EXPECT_EQ(osgvis_is_visible(context.get(), 4), 1);
        EXPECT_EQ(osgvis_is_visible(context.get(), 2), 0);
    }
}

// A region answer through the C call: the frustum module answers regions (every direction), so it
// keeps every object; the query is timed like a view's.
TEST(VisApi, RegionQuery)
{
    Context context = newContext();
    addUnitBox(context.get(), -5.0);
    addUnitBox(context.get(), 5.0);
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "frustum"), OSGVIS_OK);
    const osgvis_region_desc region{{-1, -1, -1}, {1, 1, 1}, 0.1, 0.2};
    ASSERT_EQ(osgvis_cull_region(context.get(), &region), OSGVIS_OK) << osgvis_last_error();
    EXPECT_EQ(visibleIds(context.get()), (std::vector<ObjectId>{0, 1}));
    osgvis_statistics statistics{};
    ASSERT_EQ(osgvis_statistics_get(context.get(), &statistics), OSGVIS_OK);
    EXPECT_GE(statistics.cull_milliseconds, 0.0);
}

TEST(VisApi, NonFiniteBoundsAreNeverCulled)
{
    Context context = newContext();
    const double nan = std::nan("");
    osgvis_object_desc desc{{nan, 0, 0}, {1, 1, 1}, 0, 0, nullptr, nullptr};
    ASSERT_EQ(osgvis_scene_add_object(context.get(), &desc, nullptr), OSGVIS_OK);
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "frustum"), OSGVIS_OK);
    const osgvis_view_desc view = viewDesc(
        makeView(glm::lookAt(Vec3(0, 0, 0), Vec3(0, 0, 10), Vec3(0, 1, 0)), glm::perspective(1.0, 1.0, 0.1, 5.0)));
    ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
    EXPECT_EQ(visibleIds(context.get()), (std::vector<ObjectId>{0}));
}

TEST(VisApi, MisuseGivesStatusAndMessage)
{
    Context context = newContext();
    const osgvis_view_desc view = lookDownMinusZ();
    EXPECT_EQ(osgvis_cull(context.get(), &view), OSGVIS_ERROR_BAD_STATE);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_cull: no mode chosen (osgvis_context_set_mode)");
    size_t count = 0;
    EXPECT_EQ(osgvis_visible_ids(context.get(), nullptr, 0, nullptr, &count), OSGVIS_ERROR_BAD_STATE);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_visible_ids: no query has been answered yet");
    EXPECT_EQ(osgvis_cull(nullptr, &view), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_cull: null context or view");

    EXPECT_EQ(osgvis_context_set_mode(context.get(), "frustum+nope"), OSGVIS_ERROR_UNKNOWN_MODE);
    EXPECT_EQ(std::string(osgvis_last_error()).rfind("osgvis_context_set_mode: unknown mode 'nope' (known: ", 0), 0u)
        << osgvis_last_error();
    EXPECT_EQ(osgvis_scene_remove_object(context.get(), 0), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_scene_remove_object: no object 0");
    const double line[6] = {0, 0, 0, 1, 0, 0};
    EXPECT_EQ(osgvis_scene_add_occluder(context.get(), line, 2, OSGVIS_INVALID_OBJECT), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_scene_add_occluder: a polygon needs points and at least 3 of them");

    addUnitBox(context.get(), -5.0);
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "frustum"), OSGVIS_OK);
    osgvis_region_desc region{{-1, -1, -1}, {1, 1, 1}, 0.1, 0.2};
    ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
    EXPECT_EQ(osgvis_stage_statistics(context.get(), 1, nullptr, nullptr, nullptr), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_stage_statistics: no stage 1");
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "cfrustum"), OSGVIS_OK) << osgvis_last_error();
    EXPECT_EQ(osgvis_cull_region(context.get(), &region), OSGVIS_ERROR_UNSUPPORTED);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_cull_region: mode 'cfrustum' has no region answers");
}

namespace
{
// The renderer's side of a hierarchy handed over by callback: a kd-tree it built (the same builder
// the cdt module uses for its own tree), walked by the renderer's own code.
struct RendererTree
{
    DisjointCellTree tree;
    int traversals = 0;
    bool destroyed = false;

    static void walk(const RendererTree& self, std::uint32_t index, const double eye[3], const osgvis_hierarchy_visitor* v)
    {
        const DisjointCellTree::Node& n = self.tree.node(index);
        osgvis_hierarchy_node node{};
        node.id = index;
        copy(n.cell.min, node.region_min);
        copy(n.cell.max, node.region_max);
        node.objects = self.tree.objects().data() + n.firstObject;
        node.object_count = n.objectCount;
        if (!v->enter(v->state, &node))
            return;
        if (!n.leaf())
        {
            const bool lowFirst = eye[n.axis] < n.split;
            walk(self, lowFirst ? n.left : n.right, eye, v);
            walk(self, lowFirst ? n.right : n.left, eye, v);
        }
        v->leave(v->state, &node);
    }
    static void traverse(void* user, const double eye[3], const osgvis_hierarchy_visitor* visitor)
    {
        auto& self = *static_cast<RendererTree*>(user);
        ++self.traversals;
        walk(self, 0, eye, visitor);
    }
    static void destroy(void* user) { static_cast<RendererTree*>(user)->destroyed = true; }

    osgvis_hierarchy_desc desc()
    {
        return {OSGVIS_HIERARCHY_DISJOINT, tree.nodeCount(), this, &RendererTree::traverse, &RendererTree::destroy};
    }
};

RendererTree rendererTree(const Scene& scene)
{
    std::vector<Aabb> bounds;
    for (const SceneObject& o : scene.objects)
        bounds.push_back(o.bounds);
    RendererTree t;
    t.tree.build(bounds, std::vector<bool>(bounds.size(), true), 1);
    return t;
}
} // namespace

TEST(VisApi, CdtOnTheRenderersHierarchyAnswersItsOwnTreesSets)
{
    const osgVis::test::City city = osgVis::test::makeCity();
    const std::vector<View> views = osgVis::test::randomViews(31, 30);
    std::vector<View> streetViews = views;
    for (int i = 0; i < 30; ++i)
        streetViews.push_back(osgVis::test::lookFrom({-5.0 + 30.0 * (i % 6), -5.0 + 6.0 * i, 1.7},
                                                     {std::sin(0.7 * i), std::cos(0.7 * i), -0.05}, {0, 0, 1}, 60.0, 160, 120));
    RendererTree tree = rendererTree(city.scene);
    Context own = newContext(), walked = newContext();
    describe(own.get(), city.scene);
    describe(walked.get(), city.scene);
    const osgvis_hierarchy_desc desc = tree.desc();
    ASSERT_EQ(osgvis_scene_set_hierarchy(walked.get(), &desc), OSGVIS_OK) << osgvis_last_error();
    for (osgvis_context* c : {own.get(), walked.get()})
        ASSERT_EQ(osgvis_context_set_mode(c, "frustum+cdt"), OSGVIS_OK) << osgvis_last_error();
    const int checkingTraversals = tree.traversals;
    EXPECT_EQ(checkingTraversals, 1) << "set_mode walks the hierarchy once to check it";
    double ownMs = 0.0, walkedMs = 0.0;
    std::size_t culled = 0;
    for (std::size_t v = 0; v < streetViews.size(); ++v)
    {
        const osgvis_view_desc d = viewDesc(streetViews[v]);
        ASSERT_EQ(osgvis_cull(own.get(), &d), OSGVIS_OK);
        ASSERT_EQ(osgvis_cull(walked.get(), &d), OSGVIS_OK);
        const std::vector<ObjectId> expected = visibleIds(own.get());
        EXPECT_EQ(visibleIds(walked.get()), expected) << "view " << v;
        culled += city.scene.objects.size() - expected.size();
        osgvis_statistics a{}, b{};
        osgvis_statistics_get(own.get(), &a);
        osgvis_statistics_get(walked.get(), &b);
        ownMs += a.cull_milliseconds;
        walkedMs += b.cull_milliseconds;
    }
    EXPECT_GT(tree.traversals, checkingTraversals) << "the cull walked the renderer's tree";
    EXPECT_GT(culled, streetViews.size() * 100) << "cdt culls on these views";
    std::printf("[ cdt ] %zu views: own tree %.3f ms/view, renderer's tree by callback %.3f ms/view\n",
                streetViews.size(), ownMs / double(streetViews.size()), walkedMs / double(streetViews.size()));
    walked.reset();
    EXPECT_TRUE(tree.destroyed) << "the context let the renderer free its hierarchy";
}

namespace
{
// An in-process module that reads what the renderer attached: attributes, meshes, the hierarchy.
struct Seen
{
    std::string sceneUnits;
    int weightFound = 0;
    std::uint32_t weight = 0;
    osgvis_status closedStatus = OSGVIS_ERROR_INTERNAL, openStatus = OSGVIS_OK;
    std::uint32_t closedEdges = 0;
    std::string openReason;
    int hasHierarchy = -1;
    int nodesEntered = 0;
};
Seen seen;

int countEnter(void* state, const osgvis_hierarchy_node*)
{
    ++*static_cast<int*>(state);
    return 1;
}

osgvis_status readScene(void*, const osgvis_scene* scene)
{
    const void* data = nullptr;
    size_t size = 0;
    if (osgvis_scene_attribute(scene, OSGVIS_INVALID_OBJECT, "units", &data, &size))
        seen.sceneUnits.assign(static_cast<const char*>(data), size);
    seen.weightFound = osgvis_scene_attribute(scene, 1, "weight", &data, &size);
    if (seen.weightFound && size == sizeof seen.weight)
        std::memcpy(&seen.weight, data, size);
    const double corner[3] = {3.0, 3.0, 3.0};
    uint32_t edges[64];
    seen.closedStatus = osgvis_scene_silhouette(scene, 0, corner, edges, 32, &seen.closedEdges);
    uint32_t count = 0;
    seen.openStatus = osgvis_scene_silhouette(scene, 1, corner, edges, 32, &count);
    seen.openReason = osgvis_last_error();
    seen.hasHierarchy = osgvis_scene_hierarchy(scene, nullptr, nullptr);
    if (seen.hasHierarchy)
    {
        const osgvis_hierarchy_visitor visitor{&seen.nodesEntered, countEnter, nullptr};
        osgvis_scene_traverse(scene, corner, &visitor);
    }
    return OSGVIS_OK;
}

void* noState(void*)
{
    static int state;
    return &state;
}
void noDestroy(void*) {}
osgvis_status keepAll(void*, const osgvis_view*, osgvis_visible*) { return OSGVIS_OK; }
} // namespace

TEST(VisApi, AttributesMeshesAndHierarchyReachAModule)
{
    static const osgvis_module_callbacks reader{
        OSGVIS_VISAPI_VERSION, "attribute-reader", 0, noState, noDestroy, readScene, nullptr, keepAll, nullptr, nullptr};
    ASSERT_EQ(osgvis_register_module("attribute-reader", &reader, nullptr), OSGVIS_OK) << osgvis_last_error();
    Context context = newContext();
    addUnitBox(context.get(), -3.0);
    addUnitBox(context.get(), -6.0);
    ASSERT_EQ(osgvis_scene_set_attribute(context.get(), OSGVIS_INVALID_OBJECT, "units", "metre", 5), OSGVIS_OK);
    const std::uint32_t weight = 42, other = 7;
    ASSERT_EQ(osgvis_scene_set_attribute(context.get(), 1, "weight", &other, sizeof other), OSGVIS_OK);
    ASSERT_EQ(osgvis_scene_set_attribute(context.get(), 1, "weight", &weight, sizeof weight), OSGVIS_OK);
    ASSERT_EQ(osgvis_scene_set_attribute(context.get(), 0, "weight", &weight, sizeof weight), OSGVIS_OK);
    ASSERT_EQ(osgvis_scene_set_attribute(context.get(), 0, "weight", nullptr, 0), OSGVIS_OK); // removes it
    // A closed unit cube for object 0; the same cube without its x = 1 side for object 1.
    float corners[24];
    for (int i = 0; i < 8; ++i)
        corners[3 * i] = float(i & 1), corners[3 * i + 1] = float((i >> 1) & 1), corners[3 * i + 2] = float((i >> 2) & 1);
    const uint32_t faces[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    ASSERT_EQ(osgvis_scene_set_mesh(context.get(), 0, corners, 8, faces, 12), OSGVIS_OK) << osgvis_last_error();
    ASSERT_EQ(osgvis_scene_set_mesh(context.get(), 1, corners, 8, faces, 10), OSGVIS_OK) << osgvis_last_error();
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "attribute-reader"), OSGVIS_OK) << osgvis_last_error();
    EXPECT_EQ(seen.sceneUnits, "metre");
    EXPECT_EQ(seen.weightFound, 1);
    EXPECT_EQ(seen.weight, 42u) << "the second call replaced the bytes";
    EXPECT_EQ(seen.closedStatus, OSGVIS_OK);
    EXPECT_EQ(seen.closedEdges, 6u) << "a cube seen from beyond a corner has a hexagonal silhouette";
    EXPECT_EQ(seen.openStatus, OSGVIS_ERROR_UNSUPPORTED);
    EXPECT_EQ(seen.openReason, "osgvis_scene_silhouette: the mesh of object 1 is not closed: edge 1-3 is used by 1 face");
    EXPECT_EQ(seen.hasHierarchy, 0);

    // Object 0's attribute is gone; with a hierarchy the module can walk it.
    RendererTree tree;
    tree.tree.build({{{-0.5, -0.5, -3.5}, {0.5, 0.5, -2.5}}, {{-0.5, -0.5, -6.5}, {0.5, 0.5, -5.5}}}, {true, true}, 1);
    const osgvis_hierarchy_desc desc = tree.desc();
    ASSERT_EQ(osgvis_scene_set_hierarchy(context.get(), &desc), OSGVIS_OK);
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "attribute-reader"), OSGVIS_OK) << osgvis_last_error();
    EXPECT_EQ(seen.hasHierarchy, 1);
    EXPECT_EQ(seen.nodesEntered, int(tree.tree.nodeCount()));
}

TEST(VisApi, HierarchyAttributeAndMeshMisuse)
{
    Scene boxes;
    osgVis::test::addBox(boxes, {-0.5, -0.5, -3.5}, {0.5, 0.5, -2.5}, "near");
    osgVis::test::addBox(boxes, {-0.5, -0.5, -6.5}, {0.5, 0.5, -5.5}, "far"); // wholly behind the near one
    Context context = newContext();
    describe(context.get(), boxes);
    osgvis_hierarchy_desc desc{OSGVIS_HIERARCHY_DISJOINT, 1, nullptr, nullptr, nullptr};
    EXPECT_EQ(osgvis_scene_set_hierarchy(context.get(), &desc), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_scene_set_hierarchy: the hierarchy has no traverse callback");
    desc.traverse = [](void*, const double*, const osgvis_hierarchy_visitor*) {};
    desc.layout = static_cast<osgvis_hierarchy_layout>(5);
    EXPECT_EQ(osgvis_scene_set_hierarchy(context.get(), &desc), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(),
                 "osgvis_scene_set_hierarchy: the layout is neither OSGVIS_HIERARCHY_DISJOINT nor OSGVIS_HIERARCHY_OVERLAPPING");
    EXPECT_EQ(osgvis_scene_set_attribute(context.get(), 9, "x", "y", 1), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_scene_set_attribute: no object 9");
    EXPECT_EQ(osgvis_scene_set_attribute(context.get(), 0, "", "y", 1), OSGVIS_ERROR_INVALID_ARGUMENT);
    const float nan[3] = {0.f, std::nanf(""), 0.f};
    const uint32_t face[3] = {0, 0, 0};
    EXPECT_EQ(osgvis_scene_set_mesh(context.get(), 0, nan, 1, face, 1), OSGVIS_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(osgvis_last_error(), "osgvis_scene_set_mesh: a position is not finite");

    // A hierarchy that holds no object is unusable: cdt walks its own tree (and culls object 1).
    desc.layout = OSGVIS_HIERARCHY_OVERLAPPING;
    EXPECT_EQ(osgvis_scene_set_hierarchy(context.get(), &desc), OSGVIS_OK);
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "cdt"), OSGVIS_OK) << osgvis_last_error();
    const osgvis_view_desc view = lookDownMinusZ();
    ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
    EXPECT_EQ(visibleIds(context.get()), std::vector<ObjectId>{0});
}

namespace
{
// What a module sees of the objects' flags (osgvis_scene_object), read by `flag-reader` at set_scene.
std::vector<std::uint32_t> flagsSeen;

osgvis_status readFlags(void*, const osgvis_scene* scene)
{
    flagsSeen.assign(osgvis_scene_object_count(scene), 0);
    for (uint32_t id = 0; id < flagsSeen.size(); ++id)
    {
        osgvis_object_info info{};
        if (osgvis_scene_object(scene, id, &info) != OSGVIS_OK)
            return OSGVIS_ERROR_INTERNAL;
        flagsSeen[id] = info.flags;
    }
    return OSGVIS_OK;
}

// A box object with its triangles and `extra` ones, handed through the C call.
void addBoxObject(osgvis_context* context, const Vec3& lo, const Vec3& hi, uint32_t flags,
                  const std::vector<Triangle>& extra = {})
{
    std::vector<Triangle> triangles = osgVis::test::boxTriangles(lo, hi);
    triangles.insert(triangles.end(), extra.begin(), extra.end());
    osgvis_object_desc desc{{}, {}, flags, uint32_t(triangles.size()), &triangles[0].a.x, nullptr};
    copy(lo, desc.bounds_min);
    copy(hi, desc.bounds_max);
    ASSERT_EQ(osgvis_scene_add_object(context, &desc, nullptr), OSGVIS_OK) << osgvis_last_error();
}
} // namespace

// Objects that no occluder may hide, behind a wall (docs/occluders.md): one with a sliver triangle
// (three distinct corners on one line, as a fan over a face's corners has), which the C interface
// flags as the OSG adapter does, when it is added and when it moves; and one the renderer flags
// unoccludable (version 1.3 names both flags).
TEST(VisApi, SliverAndUnoccludableObjectsAreNeverHiddenBehindAWall)
{
    static const osgvis_module_callbacks reader{
        OSGVIS_VISAPI_VERSION, "flag-reader", 0, noState, noDestroy, readFlags, nullptr, keepAll, nullptr, nullptr};
    ASSERT_EQ(osgvis_register_module("flag-reader", &reader, nullptr), OSGVIS_OK) << osgvis_last_error();
    const std::vector<Triangle> sliver{{Vec3f(1.2f, 0, -10.5f), Vec3f(1.5f, 0, -10.5f), Vec3f(1.8f, 0, -10.5f)}};
    for (const char* modes : {"frustum+octree", "frustum+mask", "frustum+cdt"})
    {
        Context context = newContext();
        addBoxObject(context.get(), {-5, -5, -3.2}, {5, 5, -3}, 0);                                 // 0: the wall
        addBoxObject(context.get(), {-0.5, -0.5, -11}, {0.5, 0.5, -10}, 0);                         // 1
        addBoxObject(context.get(), {1, -0.5, -11}, {2, 0.5, -10}, 0, sliver);                      // 2
        addBoxObject(context.get(), {-2, -0.5, -11}, {-1, 0.5, -10}, OSGVIS_OBJECT_UNOCCLUDABLE); // 3
        addBoxObject(context.get(), {-0.5, 1, -11}, {0.5, 2, -10}, OSGVIS_OBJECT_CULL_BACK);        // 4
        ASSERT_EQ(osgvis_context_set_mode(context.get(), "flag-reader"), OSGVIS_OK) << osgvis_last_error();
        EXPECT_EQ(flagsSeen, (std::vector<std::uint32_t>{0, 0, OSGVIS_OBJECT_SLIVERS, OSGVIS_OBJECT_UNOCCLUDABLE,
                                                         OSGVIS_OBJECT_CULL_BACK}));

        ASSERT_EQ(osgvis_context_set_mode(context.get(), modes), OSGVIS_OK) << osgvis_last_error();
        const osgvis_view_desc view = lookDownMinusZ();
        ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
        EXPECT_EQ(visibleIds(context.get()), (std::vector<ObjectId>{0, 2, 3})) << modes;

        std::vector<Triangle> moved = osgVis::test::boxTriangles({-0.5, 1, -12}, {0.5, 2, -11});
        moved.push_back({Vec3f(-0.3f, 1.5f, -11.5f), Vec3f(0.1f, 1.5f, -11.5f), Vec3f(0.3f, 1.5f, -11.5f)});
        const double lo[3] = {-0.5, 1, -12}, hi[3] = {0.5, 2, -11};
        ASSERT_EQ(osgvis_scene_move_object(context.get(), 4, lo, hi, &moved[0].a.x, uint32_t(moved.size())), OSGVIS_OK);
        ASSERT_EQ(osgvis_cull(context.get(), &view), OSGVIS_OK);
        EXPECT_EQ(visibleIds(context.get()), (std::vector<ObjectId>{0, 2, 3, 4})) << modes << ", moved";
    }
}

// Version 1.2, the session a context culls through, as the OSG adapter's views do: with back-off on,
// some frames skip the chain on its probing schedule (every object visible, said so), the others
// answer exactly as the chain; off, every frame is the chain's.
TEST(VisApi, BackOffSkipsTheChainOnItsScheduleAndSaysSo)
{
    const Scene scene = osgVis::test::randomBoxScene(31, 200);
    const std::vector<View> views = osgVis::test::randomViews(32, 200);
    for (const int backOff : {1, 0})
    {
        Context context = newContext();
        describe(context.get(), scene);
        const osgvis_session_desc session{0, backOff};
        ASSERT_EQ(osgvis_context_set_session(context.get(), &session), OSGVIS_OK) << osgvis_last_error();
        ASSERT_EQ(osgvis_context_set_mode(context.get(), "frustum"), OSGVIS_OK) << osgvis_last_error();
        ModuleChain chain = createChain("frustum");
        chain.setScene(scene);
        int backedOff = 0;
        for (const View& view : views)
        {
            const osgvis_view_desc desc = viewDesc(view);
            ASSERT_EQ(osgvis_cull(context.get(), &desc), OSGVIS_OK) << osgvis_last_error();
            osgvis_answer_info info{};
            ASSERT_EQ(osgvis_answer_info_get(context.get(), &info), OSGVIS_OK) << osgvis_last_error();
            EXPECT_EQ(info.from_region, 0);
            EXPECT_EQ(info.region_missed, 0);
            if (info.backed_off)
            {
                ++backedOff;
                EXPECT_EQ(visibleIds(context.get()).size(), scene.objects.size());
                continue;
            }
            VisibleSet expected;
            chain.cull(view, expected);
            EXPECT_EQ(visibleIds(context.get()), expected.ids());
        }
        if (backOff)
            EXPECT_GE(backedOff, 8) << "one probe block of 8 frames in every 8 blocks at least once";
        else
            EXPECT_EQ(backedOff, 0);
    }
}

// With async on, a worker answers regions ahead of a slowly moving eye: answers come from regions
// once it has one, and every answer keeps what the chain sees, also after the renderer moves an
// object (the worker gets a copy of the changed scene at the next cull).
TEST(VisApi, AsyncAnswersFromRegionsAndNeverLosesWhatTheChainSees)
{
    Scene expectedScene;
    Context context = newContext();
    for (int i = 0; i < 10; ++i)
    {
        const double z = -3.0 - 2.0 * i, x = (i % 3) * 3.0 - 3.0;
        osgvis_object_desc desc{{x - 0.5, -0.5, z - 0.5}, {x + 0.5, 0.5, z + 0.5}, 0, 0, nullptr, nullptr};
        ASSERT_EQ(osgvis_scene_add_object(context.get(), &desc, nullptr), OSGVIS_OK);
        expectedScene.addObject({Vec3(x - 0.5, -0.5, z - 0.5), Vec3(x + 0.5, 0.5, z + 0.5)}, 0, 0, "");
    }
    const osgvis_session_desc session{1, 0};
    ASSERT_EQ(osgvis_context_set_session(context.get(), &session), OSGVIS_OK);
    ASSERT_EQ(osgvis_context_set_mode(context.get(), "frustum"), OSGVIS_OK) << osgvis_last_error();
    ModuleChain chain = createChain("frustum");
    chain.setScene(expectedScene);
    const Mat4 projection = glm::perspective(glm::radians(40.0), 1.0, 0.1, 100.0);
    int fromRegion = 0;
    for (int frame = 0; frame < 400; ++frame)
    {
        if (frame == 200)
        {
            // Object 0 (in view) moves behind the eye, object 9 (off to the side) into the middle.
            const double behindMin[3] = {-0.5, -0.5, 9.5}, behindMax[3] = {0.5, 0.5, 10.5};
            const double middleMin[3] = {-0.5, -0.5, -10.5}, middleMax[3] = {0.5, 0.5, -9.5};
            ASSERT_EQ(osgvis_scene_move_object(context.get(), 0, behindMin, behindMax, nullptr, 0), OSGVIS_OK);
            ASSERT_EQ(osgvis_scene_move_object(context.get(), 9, middleMin, middleMax, nullptr, 0), OSGVIS_OK);
            expectedScene.objects[0].bounds = {Vec3(-0.5, -0.5, 9.5), Vec3(0.5, 0.5, 10.5)};
            expectedScene.objects[9].bounds = {Vec3(-0.5, -0.5, -10.5), Vec3(0.5, 0.5, -9.5)};
            chain.sceneChanged({SceneChange::Kind::Moved, {0, 9}});
        }
        const Vec3 eye(0.002 * frame, 0.0, 0.0);
        const View view = makeView(glm::lookAt(eye, eye + Vec3(0, 0, -1), Vec3(0, 1, 0)), projection);
        const osgvis_view_desc desc = viewDesc(view);
        ASSERT_EQ(osgvis_cull(context.get(), &desc), OSGVIS_OK) << osgvis_last_error();
        osgvis_answer_info info{};
        ASSERT_EQ(osgvis_answer_info_get(context.get(), &info), OSGVIS_OK);
        EXPECT_NE(info.from_region, info.region_missed);
        fromRegion += info.from_region;
        VisibleSet expected;
        chain.cull(view, expected);
        for (ObjectId id : expected.ids())
            EXPECT_EQ(osgvis_is_visible(context.get(), id), 1) << "object " << id << " at frame " << frame;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_GT(fromRegion, 100) << "the worker should keep ahead of so slow an eye";
}
