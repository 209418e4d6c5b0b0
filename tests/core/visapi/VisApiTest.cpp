// SPDX-License-Identifier: MIT
// The renderer side of osgVis/visapi.h: a scene described through the C calls culls to exactly the
// sets the C++ chain answers on the same core Scene; scene changes reach the modules; every misuse
// gives its status and message.
#include "RandomBoxScene.h"

#include <osgVis/visapi.h>

#include <osgVis/core/api/ModuleRegistry.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <memory>

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
