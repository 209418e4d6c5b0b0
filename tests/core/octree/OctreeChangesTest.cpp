// SPDX-License-Identifier: MIT
// The octree module under a changing scene (src/octree/OctreeChanges.cpp): what moved, came in or
// went is answered without a rebuild and never culled where a ray sees it; moved objects stop
// occluding; a quarter of the scene changed rebuilds. Every change goes both to the scene in
// place (sceneChanged) and to a copy (sceneReplaced), on the module's kd-tree and on a renderer's.
#include "BoxScenes.h"
#include "RayCastVisibility.h"
#include "TestHierarchies.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/octree/OctreeModule.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <random>
#include <string>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
void reshapeBox(Scene& scene, ObjectId id, const Vec3& lo, const Vec3& hi)
{
    const std::vector<Triangle> t = boxTriangles(lo, hi);
    SceneObject& object = scene.objects[id];
    ASSERT_EQ(object.triangleCount, t.size());
    std::copy(t.begin(), t.end(), scene.triangles.begin() + object.firstTriangle);
    object.bounds = boundsOf(t);
}

View lookAlongY(const Vec3& eye, double yawDegrees = 0.0)
{
    const double yaw = glm::radians(yawDegrees);
    const Vec3 direction(std::sin(yaw), std::cos(yaw), 0.0);
    return makeView(glm::lookAt(eye, eye + direction, Vec3(0, 0, 1)),
                    glm::perspective(glm::radians(60.0), 160.0 / 120.0, 0.1, 1000.0), 0.0, 160, 120);
}

struct Setup
{
    std::string mode;
    bool rendererTree;
};

std::string nameOf(const testing::TestParamInfo<Setup>& info)
{
    std::string name = info.param.mode + (info.param.rendererTree ? "_OnRendererKdTree" : "");
    for (char& c : name)
        if (c == '-')
            c = '_';
    return name;
}

// A street front (x -10..10, y 0..10, 15 high) hiding three boxes, an open box to the right, and
// `fillers` small boxes far behind, eye at (0, -20, 5) looking along +y.
class OctreeChanges : public testing::TestWithParam<Setup>
{
protected:
    void reset(bool replace, int fillers = 0)
    {
        replaceScenes = replace;
        scenes.clear();
        hiddenBoxes.clear();
        auto scene = std::make_unique<Scene>();
        front = addBox(*scene, {-10, 0, 0}, {10, 10, 15}, "street front");
        for (int i = 0; i < 3; ++i)
            hiddenBoxes.push_back(
                addBox(*scene, {-6.0 + 4.0 * i, 20, 0}, {-5.0 + 4.0 * i, 21, 2}, "hidden box " + std::to_string(i)));
        open = addBox(*scene, {25, 20, 0}, {26, 21, 2}, "open box");
        for (int i = 0; i < fillers; ++i)
            this->fillers.push_back(addBox(*scene, {-100.0 + 2.0 * (i % 100), 400.0 + 2.0 * (i / 100), 0},
                                           {-99.0 + 2.0 * (i % 100), 401.0 + 2.0 * (i / 100), 1}, "filler"));
        if (GetParam().rendererTree)
            scene->hierarchy = kdTreeOf(*scene);
        scenes.push_back(std::move(scene));
        removed.assign(scene_().objects.size(), false);
        module = createModule(GetParam().mode);
        module->setScene(scene_());
    }
    const Scene& scene_() const { return *scenes.back(); }
    OctreeModule& octree() { return dynamic_cast<OctreeModule&>(*module); }

    // One query, checked against rays: nothing a ray sees may be culled.
    VisibleSet check(const std::string& what, const View& view = lookAlongY({0, -20, 5}))
    {
        VisibleSet visible(scene_().objects.size(), true);
        for (ObjectId id = 0; id < removed.size(); ++id)
            if (removed[id])
                visible.clear(id);
        module->cull(view, visible);
        const RayCastResult seen = RayCastVisibility(scene_(), removed).cast(view);
        for (ObjectId id = 0; id < seen.visible.size(); ++id)
            EXPECT_FALSE(seen.visible[id] && !visible.test(id))
                << what << ": '" << scene_().objects[id].name << "' seen by a ray but culled (replace "
                << replaceScenes << ")";
        return visible;
    }
    void change(SceneChange::Kind kind, std::vector<ObjectId> ids, const std::function<void(Scene&)>& mutate)
    {
        const SceneChange c{kind, ids};
        if (replaceScenes)
        {
            scenes.push_back(std::make_unique<Scene>(*scenes.back()));
            mutate(*scenes.back());
            module->sceneReplaced(scene_(), {c});
        }
        else
        {
            mutate(*scenes.back());
            module->sceneChanged(c);
        }
        removed.resize(scene_().objects.size(), false);
        for (ObjectId id : ids)
            removed[id] = kind == SceneChange::Kind::Removed;
    }
    // The premise of every test: the front hides the three boxes.
    void startWalk()
    {
        const VisibleSet first = check("first frame");
        for (ObjectId id : hiddenBoxes)
            ASSERT_FALSE(first.test(id)) << scene_().objects[id].name << " not culled behind the street front";
    }

    bool replaceScenes = false;
    std::vector<std::unique_ptr<Scene>> scenes; // every copy kept: the module may hold any
    std::vector<bool> removed;
    std::unique_ptr<VisibilityModule> module;
    ObjectId front = InvalidObject, open = InvalidObject;
    std::vector<ObjectId> hiddenBoxes, fillers;
};

TEST_P(OctreeChanges, AHiddenObjectMovedIntoTheOpenShowsAtOnceAndOneMovedBehindTheFrontStaysCulled)
{
    for (const bool replace : {false, true})
    {
        reset(replace);
        ASSERT_NO_FATAL_FAILURE(startWalk());
        const ObjectId moved = hiddenBoxes[1];
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {24, 20, 0}, {25, 21, 2}); });
        EXPECT_TRUE(check("moved into the open").test(moved));
        EXPECT_EQ(octree().lastStatistics().changedTested, 1u) << "answered by a rebuild";
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {1, 25, 0}, {2, 26, 2}); });
        EXPECT_FALSE(check("moved behind the front again").test(moved)) << "a moved object is tested on its own";
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {-28, 25, 0}, {-27, 26, 2}); });
        EXPECT_TRUE(check("moved again").test(moved));
    }
}

TEST_P(OctreeChanges, InsertedObjectsAreTestedOnTheirOwn)
{
    for (const bool replace : {false, true})
    {
        reset(replace);
        ASSERT_NO_FATAL_FAILURE(startWalk());
        const ObjectId first = ObjectId(scene_().objects.size());
        ObjectId behind = InvalidObject, tower = InvalidObject, inOpen = InvalidObject;
        change(SceneChange::Kind::Inserted, {first, first + 1, first + 2},
               [&](Scene& s)
               {
                   behind = addBox(s, {-1, 22, 0}, {0, 23, 2}, "inserted behind");
                   tower = addBox(s, {3, 21, 0}, {4, 22, 40}, "inserted tower"); // rises above the front
                   inOpen = addBox(s, {-26, 20, 0}, {-25, 21, 2}, "inserted in the open");
               });
        const VisibleSet answer = check("after insert");
        EXPECT_TRUE(answer.test(tower));
        EXPECT_TRUE(answer.test(inOpen));
        EXPECT_FALSE(answer.test(behind)) << "the front hides what came in behind it";
        EXPECT_EQ(octree().lastStatistics().changedTested, 3u);
    }
}

TEST_P(OctreeChanges, ARemovedOrMovedOccluderHidesNothing)
{
    for (const bool replace : {false, true})
    {
        for (const SceneChange::Kind kind : {SceneChange::Kind::Removed, SceneChange::Kind::Moved})
        {
            reset(replace);
            ASSERT_NO_FATAL_FAILURE(startWalk());
            // Moved by 0.5 it would still hide the boxes, but its polygons are those of its old place:
            // it hides nothing until a rebuild.
            change(kind, {front}, [&](Scene& s) { reshapeBox(s, front, {-9.5, 0, 0}, {10.5, 10, 15}); });
            const VisibleSet answer = check("occluder changed");
            for (ObjectId id : hiddenBoxes)
                EXPECT_TRUE(answer.test(id)) << scene_().objects[id].name << " kind " << int(kind);
        }
    }
}

TEST_P(OctreeChanges, AQuarterOfTheSceneChangedRebuildsAndTheFrontHidesAgain)
{
    for (const bool replace : {false, true})
    {
        reset(replace, 300);
        ASSERT_NO_FATAL_FAILURE(startWalk());
        change(SceneChange::Kind::Moved, {front}, [&](Scene& s) { reshapeBox(s, front, {-9.5, 0, 0}, {10.5, 10, 15}); });
        EXPECT_TRUE(check("front moved").test(hiddenBoxes[0]));
        std::vector<ObjectId> many(fillers.begin(), fillers.begin() + 80);
        change(SceneChange::Kind::Moved, many,
               [&](Scene& s)
               {
                   for (ObjectId id : many)
                       reshapeBox(s, id, s.objects[id].bounds.min + Vec3(0, 1, 0), s.objects[id].bounds.max + Vec3(0, 1, 0));
               });
        const VisibleSet answer = check("rebuilt");
        EXPECT_EQ(octree().lastStatistics().changedTested, 0u) << "not rebuilt";
        for (ObjectId id : hiddenBoxes)
            EXPECT_FALSE(answer.test(id)) << scene_().objects[id].name << " not hidden by the rebuilt front";
    }
}

// Random moves, inserts and removals over a city, every frame checked by rays from a jittered eye.
TEST_P(OctreeChanges, ACityThatKeepsChangingIsNeverWronglyCulled)
{
    for (const bool replace : {false, true})
    {
        reset(replace);
        City city = makeCity();
        scenes.clear();
        scenes.push_back(std::make_unique<Scene>(std::move(city.scene)));
        if (GetParam().rendererTree)
            scenes.back()->hierarchy = kdTreeOf(scene_());
        removed.assign(scene_().objects.size(), false);
        module->setScene(scene_());
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::size_t culled = 0;
        for (int frame = 0; frame < 12; ++frame)
        {
            const ObjectId a = ObjectId(random() % scene_().objects.size());
            const Vec3 to(-5 + 180 * unit(random), -5 + 180 * unit(random), 0);
            if (!removed[a])
                change(SceneChange::Kind::Moved, {a},
                       [&](Scene& s) { reshapeBox(s, a, to, to + (s.objects[a].bounds.max - s.objects[a].bounds.min)); });
            const ObjectId b = ObjectId(random() % scene_().objects.size());
            if (!removed[b] && frame % 3 == 0)
                change(SceneChange::Kind::Removed, {b}, [](Scene&) {});
            if (frame % 4 == 1)
            {
                const ObjectId id = ObjectId(scene_().objects.size());
                change(SceneChange::Kind::Inserted, {id},
                       [&](Scene& s) { addBox(s, to + Vec3(2, 2, 0), to + Vec3(4, 4, 30), "inserted tower"); });
            }
            const Vec3 eye(-5 + 3 * unit(random), -5 + 150 * unit(random), 1.7);
            const VisibleSet answer = check("frame " + std::to_string(frame), lookAlongY(eye, 360 * unit(random)));
            culled += std::size_t(std::count(removed.begin(), removed.end(), false)) - answer.count();
        }
        EXPECT_GT(culled, 0u) << "the walk culled nothing: it proves nothing";
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, OctreeChanges,
                         testing::Values(Setup{"octree", false}, Setup{"octree-paper", false},
                                         Setup{"octree-single", false}, Setup{"octree", true}),
                         nameOf);
} // namespace
