// SPDX-License-Identifier: MIT
// Modules that answer a changing scene without a rebuild (module/ChangedObjects.h: frustum, octree,
// cdt): what moved, came in or went is never culled where a ray sees it, what moved out of view or
// behind a static occluder is still culled, moved and removed objects stop occluding, and a quarter
// of the scene changed rebuilds. Every change goes both to the scene in place (sceneChanged) and to
// a copy (sceneReplaced), on the module's own tree and on a renderer's kd-tree.
#include "BoxScenes.h"
#include "ChangingScene.h"
#include "RayCastVisibility.h"
#include "TestHierarchies.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/cdt/CdtModule.h>
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

// The street front (ChangingScene.h) and `fillers` small boxes far behind, eye at (0, -20, 5)
// looking along +y.
class ModuleChanges : public testing::TestWithParam<Setup>
{
protected:
    void reset(bool replace, int fillers = 0)
    {
        replaceScenes = replace;
        StreetFront street = makeStreetFront();
        front = street.front;
        open = street.open;
        hiddenBoxes = street.hiddenBoxes;
        this->fillers.clear();
        for (int i = 0; i < fillers; ++i)
            this->fillers.push_back(addBox(street.scene, {-100.0 + 2.0 * (i % 100), 400.0 + 2.0 * (i / 100), 0},
                                           {-99.0 + 2.0 * (i % 100), 401.0 + 2.0 * (i / 100), 1}, "filler"));
        start(std::move(street.scene));
    }
    // A fresh module on `scene` (with a renderer's kd-tree over it when the setup says so).
    void start(Scene scene)
    {
        if (GetParam().rendererTree)
            scene.hierarchy = kdTreeOf(scene);
        scenes.reset(std::move(scene));
        module = createModule(GetParam().mode);
        module->setScene(scene_());
    }
    const Scene& scene_() const { return scenes.current(); }
    const std::vector<bool>& removed() const { return scenes.removed(); }
    bool occludes() const { return GetParam().mode != "frustum"; }
    // Octree and cdt count the objects they tested on their own; frustum says nothing (-1).
    int changedTested() const
    {
        if (const auto* octree = dynamic_cast<const OctreeModule*>(module.get()))
            return int(octree->lastStatistics().changedTested);
        if (const auto* cdt = dynamic_cast<const CdtModule*>(module.get()))
            return int(cdt->lastStatistics().changedTested);
        return -1;
    }

    // One query, checked against rays: nothing a ray sees may be culled.
    VisibleSet check(const std::string& what, const View& view = lookAlongY({0, -20, 5}))
    {
        VisibleSet visible(scene_().objects.size(), true);
        for (ObjectId id = 0; id < removed().size(); ++id)
            if (removed()[id])
                visible.clear(id);
        module->cull(view, visible);
        const RayCastResult seen = RayCastVisibility(scene_(), removed()).cast(view);
        for (ObjectId id = 0; id < seen.visible.size(); ++id)
            EXPECT_FALSE(seen.visible[id] && !visible.test(id))
                << what << ": '" << scene_().objects[id].name << "' seen by a ray but culled (replace "
                << replaceScenes << ")";
        return visible;
    }
    void change(SceneChange::Kind kind, std::vector<ObjectId> ids, const std::function<void(Scene&)>& mutate)
    {
        scenes.change(*module, kind, std::move(ids), mutate, replaceScenes);
    }
    // The premise of the occlusion tests: the front hides the three boxes.
    void startWalk()
    {
        const VisibleSet first = check("first frame");
        for (ObjectId id : hiddenBoxes)
            ASSERT_TRUE(!occludes() || !first.test(id)) << scene_().objects[id].name << " not culled behind the street front";
    }
    // The eye turned away from everything but the open box (which then lies left of the view).
    View lookingRight() const { return lookAlongY({0, -20, 5}, 90.0); }

    bool replaceScenes = false;
    ChangingScene scenes;
    std::unique_ptr<VisibilityModule> module;
    ObjectId front = InvalidObject, open = InvalidObject;
    std::vector<ObjectId> hiddenBoxes, fillers;
};

TEST_P(ModuleChanges, AHiddenObjectMovedIntoTheOpenShowsAtOnceAndOneMovedOutOfSightIsCulled)
{
    for (const bool replace : {false, true})
    {
        reset(replace);
        ASSERT_NO_FATAL_FAILURE(startWalk());
        const ObjectId moved = hiddenBoxes[1];
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {24, 20, 0}, {25, 21, 2}); });
        EXPECT_TRUE(check("moved into the open").test(moved));
        EXPECT_NE(changedTested(), 0) << "answered by a rebuild";
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {1, -40, 0}, {2, -39, 2}); });
        EXPECT_FALSE(check("moved behind the eye").test(moved)) << "a moved object is tested on its own";
        if (occludes())
        {
            change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {1, 25, 0}, {2, 26, 2}); });
            EXPECT_FALSE(check("moved behind the front again").test(moved));
        }
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {-28, 25, 0}, {-27, 26, 2}); });
        EXPECT_TRUE(check("moved again").test(moved));
    }
}

TEST_P(ModuleChanges, InsertedObjectsAreTestedOnTheirOwn)
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
        EXPECT_TRUE(!occludes() || !answer.test(behind)) << "the front hides what came in behind it";
        EXPECT_NE(changedTested(), 0);
        const ObjectId outOfView = ObjectId(scene_().objects.size());
        change(SceneChange::Kind::Inserted, {outOfView}, [&](Scene& s) { addBox(s, {-1, -40, 0}, {0, -39, 2}, "behind the eye"); });
        EXPECT_FALSE(check("inserted behind the eye").test(outOfView));
    }
}

TEST_P(ModuleChanges, ARemovedOrMovedOccluderHidesNothing)
{
    if (!occludes())
        GTEST_SKIP() << "nothing occludes in " << GetParam().mode;
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

TEST_P(ModuleChanges, AQuarterOfTheSceneChangedRebuildsAndTheFrontHidesAgain)
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
        EXPECT_TRUE(changedTested() <= 0) << "not rebuilt";
        for (ObjectId id : hiddenBoxes)
            EXPECT_TRUE(!occludes() || !answer.test(id)) << scene_().objects[id].name << " not hidden by the rebuilt front";
    }
}

// Random moves, inserts and removals over a city, every frame checked by rays from a jittered eye.
TEST_P(ModuleChanges, ACityThatKeepsChangingIsNeverWronglyCulled)
{
    for (const bool replace : {false, true})
    {
        replaceScenes = replace;
        start(makeCity().scene);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::size_t culled = 0;
        for (int frame = 0; frame < 12; ++frame)
        {
            const ObjectId a = ObjectId(random() % scene_().objects.size());
            const Vec3 to(-5 + 180 * unit(random), -5 + 180 * unit(random), 0);
            if (!removed()[a])
                change(SceneChange::Kind::Moved, {a},
                       [&](Scene& s) { reshapeBox(s, a, to, to + (s.objects[a].bounds.max - s.objects[a].bounds.min)); });
            const ObjectId b = ObjectId(random() % scene_().objects.size());
            if (!removed()[b] && frame % 3 == 0)
                change(SceneChange::Kind::Removed, {b}, [](Scene&) {});
            if (frame % 4 == 1)
            {
                const ObjectId id = ObjectId(scene_().objects.size());
                change(SceneChange::Kind::Inserted, {id},
                       [&](Scene& s) { addBox(s, to + Vec3(2, 2, 0), to + Vec3(4, 4, 30), "inserted tower"); });
            }
            const Vec3 eye(-5 + 3 * unit(random), -5 + 150 * unit(random), 1.7);
            const VisibleSet answer = check("frame " + std::to_string(frame), lookAlongY(eye, 360 * unit(random)));
            culled += std::size_t(std::count(removed().begin(), removed().end(), false)) - answer.count();
        }
        EXPECT_GT(culled, 0u) << "the walk culled nothing: it proves nothing";
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, ModuleChanges,
                         testing::Values(Setup{"frustum", false}, Setup{"octree", false}, Setup{"octree-paper", false},
                                         Setup{"octree-single", false}, Setup{"octree", true}, Setup{"cdt", false},
                                         Setup{"cdt-depthfree", false}, Setup{"cdt", true}),
                         nameOf);
} // namespace
