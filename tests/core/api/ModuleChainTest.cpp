// SPDX-License-Identifier: MIT
#include <osgVis/core/frustum/FrustumModule.h>
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/plugin/PluginModules.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <limits>

using namespace osgVis::core;

namespace
{
// Keeps only even ids: a stand-in for a second, independent stage.
class EvenOnlyModule : public VisibilityModule
{
public:
    explicit EvenOnlyModule(int* builds = nullptr) : _builds(builds) {}
    const char* name() const override { return "test-even"; }
    void setScene(const Scene& scene) override
    {
        _scene = &scene;
        if (_builds)
            ++*_builds;
    }
    void cull(const View&, VisibleSet& visible) override
    {
        for (ObjectId id : visible.ids())
        {
            if (id % 2)
                visible.clear(id);
        }
    }

private:
    int* _builds;
};

class EvenOnlyRegionModule : public EvenOnlyModule
{
public:
    bool supportsRegions() const override { return true; }
    void cullRegion(const ViewRegion&, VisibleSet& visible) override { cull(View{}, visible); }
};

class ApproximateModule : public EvenOnlyModule
{
public:
    const char* name() const override { return "test-approx"; }
    bool approximate() const override { return true; }
};

std::string knownList()
{
    std::string out;
    for (const std::string& n : moduleNames())
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

// Ten unit boxes along -z in front of an eye at the origin, then ten behind it.
Scene lineScene()
{
    Scene scene;
    for (int i = 0; i < 10; ++i)
        scene.addObject(Aabb(Vec3(-0.5, -0.5, -5.0 - i), Vec3(0.5, 0.5, -4.5 - i)), 12);
    for (int i = 0; i < 10; ++i)
        scene.addObject(Aabb(Vec3(-0.5, -0.5, 4.5 + i), Vec3(0.5, 0.5, 5.0 + i)), 12);
    return scene;
}

View lookDownMinusZ()
{
    return makeView(Mat4(1.0), glm::perspective(glm::radians(60.0), 1.0, 0.1, 100.0));
}

// The answer of frustum then EvenOnlyModule, looking down -z from the origin.
VisibleSet frustumThenEvenOnly(const Scene& scene)
{
    ModuleChain chain = createChain("frustum");
    chain.add(std::make_unique<EvenOnlyModule>());
    chain.setScene(scene);
    VisibleSet visible;
    chain.cull(lookDownMinusZ(), visible);
    return visible;
}

std::vector<ObjectId> range(ObjectId first, ObjectId end, ObjectId step = 1)
{
    std::vector<ObjectId> ids;
    for (ObjectId i = first; i < end; i += step)
        ids.push_back(i);
    return ids;
}
} // namespace

TEST(ModuleRegistry, FrustumIsRegistered)
{
    const std::vector<std::string> names = moduleNames();
    EXPECT_NE(std::find(names.begin(), names.end(), "frustum"), names.end());
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    EXPECT_TRUE(hasModule("frustum"));
    EXPECT_FALSE(hasModule("nope"));
    EXPECT_STREQ(createModule("frustum")->name(), "frustum");
}

TEST(ModuleRegistry, UnknownModeNamesTheKnownOnes)
{
    try
    {
        createModule("foo");
        FAIL() << "no exception";
    }
    catch (const UnknownModeError& e)
    {
        std::string searched;
        for (const std::string& folder : pluginSearchPath())
            searched += (searched.empty() ? "" : ", ") + folder;
        EXPECT_EQ(std::string(e.what()),
                  "unknown mode 'foo' (known: " + knownList() + "; no plugin osgvis_module_foo.so in " + searched + ")");
        EXPECT_NE(std::string(e.what()).find("frustum"), std::string::npos);
    }
    EXPECT_THROW(createChain("frustum,foo"), UnknownModeError);
}

TEST(ModuleRegistry, ChainNamesAreTrimmedAndMustNotBeEmpty)
{
    EXPECT_EQ(createChain(" frustum ,\tfrustum").name(), "frustum,frustum");
    EXPECT_EQ(createChain("frustum").size(), 1u);
    EXPECT_EQ(createChain("frustum + frustum,frustum").name(), "frustum,frustum,frustum");
    for (const std::string bad : {"", "frustum,,frustum", "frustum,", " , ", "frustum+", "+frustum"})
    {
        try
        {
            createChain(bad);
            FAIL() << "no exception for '" << bad << "'";
        }
        catch (const UnknownModeError& e)
        {
            EXPECT_EQ(std::string(e.what()), "empty mode name in '" + bad + "' (known: " + knownList() + ")");
        }
    }
}

TEST(ModuleRegistry, RegisteredModulesAreCreatedByName)
{
    registerModule("test-even", [] { return std::make_unique<EvenOnlyModule>(); });
    EXPECT_TRUE(hasModule("test-even"));
    ModuleChain chain = createChain("frustum,test-even");
    EXPECT_EQ(chain.name(), "frustum,test-even");
    EXPECT_FALSE(chain.approximate());
}

TEST(ModuleChain, StagesRefineInOrder)
{
    const Scene scene = lineScene();
    ModuleChain chain;
    chain.add(createModule("frustum"));
    chain.add(std::make_unique<EvenOnlyModule>());
    chain.setScene(scene);

    VisibleSet visible;
    chain.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.capacity(), scene.objects.size());
    EXPECT_EQ(visible.ids(), range(0, 10, 2));

    const std::vector<StageTiming>& timings = chain.lastTimings();
    ASSERT_EQ(timings.size(), 2u);
    EXPECT_EQ(timings[0].module, "frustum");
    EXPECT_EQ(timings[0].visibleAfter, 10u);
    EXPECT_EQ(timings[1].module, "test-even");
    EXPECT_EQ(timings[1].visibleAfter, 5u);
    EXPECT_GE(timings[0].milliseconds, 0.0);
}

TEST(ModuleChain, StartsFromAllObjectsEveryFrame)
{
    const Scene scene = lineScene();
    ModuleChain chain;
    chain.setScene(scene);
    VisibleSet visible(3); // wrong size and content on purpose
    chain.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.ids(), range(0, 20)); // no stages: nothing culled

    chain.add(createModule("frustum")); // added after setScene: gets the scene too
    chain.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.ids(), range(0, 10));
}

TEST(ModuleChain, AlwaysVisibleObjectsSurviveEveryStage)
{
    Scene scene = lineScene();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const ObjectId broken = scene.addObject(Aabb(Vec3(nan), Vec3(nan)), 3, OBJECT_ALWAYS_VISIBLE);
    const ObjectId behind = 15;
    scene.objects[behind].flags |= OBJECT_ALWAYS_VISIBLE;
    std::vector<ObjectId> expected = range(0, 10, 2);
    expected.push_back(behind);
    expected.push_back(broken);
    EXPECT_EQ(frustumThenEvenOnly(scene).ids(), expected);
}

TEST(ModuleChain, ObjectsWithSliversSurviveOcclusionButNotTheFrustum)
{
    // A sliver's pixels may take any depth (docs/occluders.md): the oracle saw one through a wall
    // nine units in front of it on OpenArena's oa_dm1 as OSG's bsp plugin draws it.
    Scene scene = lineScene();
    const ObjectId inView = 3, outOfView = 13; // odd: EvenOnlyModule culls both
    scene.objects[inView].flags |= OBJECT_SLIVERS;
    scene.objects[outOfView].flags |= OBJECT_SLIVERS;
    std::vector<ObjectId> expected = range(0, 10, 2);
    expected.insert(expected.begin() + 2, inView);
    EXPECT_EQ(frustumThenEvenOnly(scene).ids(), expected);

    // A region has no single frustum: every sliver object stays.
    ModuleChain regions;
    regions.add(std::make_unique<EvenOnlyRegionModule>());
    regions.setScene(scene);
    ViewRegion region;
    region.eyes = Aabb(Vec3(-0.1), Vec3(0.1));
    VisibleSet visible;
    regions.cullRegion(region, visible);
    EXPECT_TRUE(visible.test(inView));
    EXPECT_TRUE(visible.test(outOfView));
    EXPECT_FALSE(visible.test(inView + 2));
}

TEST(ModuleChain, RemovedObjectsAreNotReported)
{
    Scene scene = lineScene();
    int builds = 0;
    ModuleChain chain;
    chain.add(std::make_unique<EvenOnlyModule>(&builds));
    chain.setScene(scene);
    EXPECT_EQ(builds, 1);

    SceneChange removed{SceneChange::Kind::Removed, {0, 2, 19}};
    chain.sceneChanged(removed);
    EXPECT_EQ(builds, 2); // the default sceneChanged rebuilds
    VisibleSet visible;
    chain.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.ids(), (std::vector<ObjectId>{4, 6, 8, 10, 12, 14, 16, 18}));

    scene.addObject(Aabb(Vec3(0.0), Vec3(1.0)), 1);
    chain.sceneChanged({SceneChange::Kind::Inserted, {2, 20}});
    chain.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.ids(), (std::vector<ObjectId>{2, 4, 6, 8, 10, 12, 14, 16, 18, 20}));
}

TEST(ModuleChain, ApproximateIfAnyStageIs)
{
    ModuleChain chain = createChain("frustum");
    EXPECT_FALSE(chain.approximate());
    chain.add(std::make_unique<ApproximateModule>());
    EXPECT_TRUE(chain.approximate());
    EXPECT_EQ(chain.name(), "frustum,test-approx");
}

TEST(ModuleChain, WithoutSceneAnswersNothing)
{
    ModuleChain chain = createChain("frustum");
    VisibleSet visible(5, true);
    chain.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.capacity(), 0u);
}

TEST(FrustumModule, OnlyRefinesTheIncomingSet)
{
    const Scene scene = lineScene();
    FrustumModule module;
    module.setScene(scene);
    VisibleSet visible(scene.objects.size());
    visible.set(1);
    visible.set(3);
    visible.set(12); // behind the eye
    module.cull(lookDownMinusZ(), visible);
    EXPECT_EQ(visible.ids(), (std::vector<ObjectId>{1, 3}));
}

TEST(FrustumModule, KeepsObjectsWithoutUsableBounds)
{
    Scene scene = lineScene();
    const ObjectId empty = scene.addObject(Aabb(), 0);
    const double inf = std::numeric_limits<double>::infinity();
    const ObjectId infinite = scene.addObject(Aabb(Vec3(-inf), Vec3(inf)), 1);
    FrustumModule module;
    module.setScene(scene);
    VisibleSet visible(scene.objects.size(), true);
    module.cull(lookDownMinusZ(), visible);
    EXPECT_TRUE(visible.test(empty));
    EXPECT_TRUE(visible.test(infinite));
    EXPECT_EQ(visible.count(), 12u);
}
