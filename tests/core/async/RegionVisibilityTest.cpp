// SPDX-License-Identifier: MIT
// Region queries and asynchronous visibility (issue 6) against the ray-cast reference: a region's
// answer must hold every object some eye of the region sees in any direction; AsyncVisibility must
// answer only inside a region computed for the current scene, predict a steady walk, and keep
// every object the rays see along it.
#include "BoxScenes.h"
#include "RayCastVisibility.h"
#include "RegionSampling.h"

#include <osgVis/core/async/AsyncVisibility.h>
#include <osgVis/core/api/ModuleRegistry.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <sstream>
#include <thread>
#include <type_traits>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
// A fresh chain's answer for a region (ViewRegion) or a single view (View).
template <class Query> VisibleSet chainAnswer(const std::string& modes, const Scene& scene, const Query& query)
{
    ModuleChain chain = createChain(modes);
    chain.setScene(scene);
    VisibleSet visible;
    if constexpr (std::is_same_v<Query, ViewRegion>)
        chain.cullRegion(query, visible);
    else
        chain.cull(query, visible);
    return visible;
}

VisibleSet regionAnswer(const std::string& modes, const Scene& scene, const ViewRegion& region)
{
    return chainAnswer(modes, scene, region);
}

} // namespace

TEST(RegionQueries, ChainsAnswerRegionsOnlyWhenEveryStageDoes)
{
    EXPECT_TRUE(createChain("frustum+octree").supportsRegions());
    EXPECT_TRUE(createChain("octree-single").supportsRegions());
    EXPECT_TRUE(createChain("cellportal").supportsRegions());
    EXPECT_FALSE(createChain("mask").supportsRegions());
    EXPECT_FALSE(createChain("frustum+mask-approx").supportsRegions());
}

TEST(RegionQueries, ViewRegionHoldsOnlyPerspectiveViewsInsideWithinItsNearBounds)
{
    const ViewRegion region = regionAround({0, 0, 2}, {1, 1, 0.5});
    EXPECT_TRUE(region.holds(lookFrom({0.9, -0.9, 2.4}, {0, 1, 0}, {0, 0, 1}, 90.0, 64, 64)));
    EXPECT_FALSE(region.holds(lookFrom({1.1, 0, 2}, {0, 1, 0}, {0, 0, 1}, 90.0, 64, 64)));
    View farNear = lookFrom({0, 0, 2}, {0, 1, 0}, {0, 0, 1});
    farNear.projectionMatrix = glm::perspective(glm::radians(60.0), 1.0, 1.0, 1000.0);
    EXPECT_FALSE(region.holds(farNear)) << "its near plane reaches past the region's bound";
    View nearer = farNear;
    nearer.projectionMatrix = glm::perspective(glm::radians(60.0), 1.0, 0.01, 1000.0);
    EXPECT_FALSE(region.holds(nearer)) << "its near plane is nearer than the region's depth bound";
    View ortho = farNear;
    ortho.projectionMatrix = glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 100.0);
    ortho.orthographic = true;
    EXPECT_FALSE(region.holds(ortho));
}

TEST(RegionQueries, AWallHidesWhatIsBehindItOnlyFromRegionsWhollyInFront)
{
    Scene scene;
    addBox(scene, {-10, 10, 0}, {10, 11, 10}, "wall");
    const ObjectId behind = addBox(scene, {-1, 20, 0}, {1, 22, 2}, "crate behind");
    const ObjectId before = addBox(scene, {-1, 4, 0}, {1, 5, 1}, "crate before");
    for (const std::string modes : {"octree", "frustum+octree", "octree-single", "multifocal"})
    {
        SCOPED_TRACE(modes);
        const VisibleSet small = regionAnswer(modes, scene, regionAround({0, 0, 1.7}, {2, 2, 0.5}));
        EXPECT_FALSE(small.test(behind));
        EXPECT_TRUE(small.test(before));
        // Eyes out to x = 30 see past the wall's end.
        EXPECT_TRUE(regionAnswer(modes, scene, regionAround({20, 0, 1.7}, {10, 2, 0.5})).test(behind));
        // Eyes high above see over it.
        EXPECT_TRUE(regionAnswer(modes, scene, regionAround({0, 0, 20}, {1, 1, 4})).test(behind));
        // Eyes inside the wall's slab are on both sides of its faces.
        EXPECT_TRUE(regionAnswer(modes, scene, regionAround({0, 9.5, 1.7}, {1, 1.2, 0.5})).test(behind));
    }
}

TEST(RegionQueries, OctreeRegionsKeepEverythingTheRaysSeeFromAnyEyeInThem)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    // Along the street x = 85, at a crossing, and a region as wide as a block.
    const std::vector<ViewRegion> regions{regionAround({85, 10, 1.7}, {1.5, 4, 0.3}),
                                          regionAround({85, 55, 1.7}, {3, 3, 0.3}),
                                          regionAround({25, 85, 2.5}, {12, 2, 1})};
    for (const ViewRegion& region : regions)
        for (const std::string modes : {"frustum+octree", "octree-single", "multifocal"})
            EXPECT_EQ(missedFromRegion(rays, city.scene, region, regionAnswer(modes, city.scene, region)), "")
                << modes;
    // A region a few metres long does cull: the rays see 69 objects from it in every direction,
    // the answer keeps 175 of the 252 (a region as wide as a block keeps nearly everything).
    EXPECT_LT(regionAnswer("frustum+octree", city.scene, regions.front()).count(), 190u);
}

TEST(RegionQueries, CellPortalRegionKeepsTheCellsPvs)
{
    // Two rooms joined by a door, a third room behind a closed wall.
    Scene scene;
    addBox(scene, {-0.2, -0.2, -0.2}, {12.2, 4.2, 0.0}, "floor");
    addBox(scene, {-0.2, -0.2, 3.0}, {12.2, 4.2, 3.2}, "ceiling");
    addBox(scene, {-0.2, -0.2, 0.0}, {12.2, 0.0, 3.0}, "south wall");
    addBox(scene, {-0.2, 4.0, 0.0}, {12.2, 4.2, 3.0}, "north wall");
    addBox(scene, {-0.2, 0.0, 0.0}, {0.0, 4.0, 3.0}, "west wall");
    addBox(scene, {12.0, 0.0, 0.0}, {12.2, 4.0, 3.0}, "east wall");
    addBox(scene, {3.9, 0.0, 0.0}, {4.1, 1.5, 3.0}, "wall with door");
    addBox(scene, {3.9, 2.5, 0.0}, {4.1, 4.0, 3.0}, "wall with door");
    addBox(scene, {3.9, 1.5, 2.0}, {4.1, 2.5, 3.0}, "lintel");
    addBox(scene, {7.9, 0.0, 0.0}, {8.1, 4.0, 3.0}, "closed wall");
    const ObjectId crate0 = addBox(scene, {1, 1, 0}, {2, 2, 1}, "crate 0");
    const ObjectId crate1 = addBox(scene, {5, 1, 0}, {6, 2, 1}, "crate 1");
    const ObjectId crate2 = addBox(scene, {10, 1, 0}, {11, 2, 1}, "crate 2");

    const VisibleSet inRoom0 = regionAnswer("cellportal", scene, regionAround({2, 2, 1.5}, {1, 1, 0.5}));
    EXPECT_TRUE(inRoom0.test(crate0));
    EXPECT_TRUE(inRoom0.test(crate1));
    EXPECT_FALSE(inRoom0.test(crate2));
    // The same as the PVS a single eye there gets.
    ModuleChain pvs = createChain("cellportal-pvs");
    pvs.setScene(scene);
    VisibleSet single;
    pvs.cull(lookFrom({2, 2, 1.5}, {1, 0, 0}, {0, 0, 1}, 90.0, 64, 64), single);
    EXPECT_EQ(inRoom0, single);
    // A region reaching into the closed room keeps its crate; one leaving the building keeps all.
    EXPECT_TRUE(regionAnswer("cellportal", scene, regionAround({7.5, 2, 1.5}, {1, 1, 0.5})).test(crate2));
    EXPECT_EQ(regionAnswer("cellportal", scene, regionAround({2, 2, 1.5}, {3, 3, 0.5})).count(),
              scene.objects.size());
    const RayCastVisibility rays(scene);
    const ViewRegion region = regionAround({5, 2, 1.5}, {0.7, 1.2, 0.8});
    EXPECT_EQ(missedFromRegion(rays, scene, region, regionAnswer("cellportal", scene, region)), "");
}

// ---- AsyncVisibility -------------------------------------------------------------------------

namespace
{
View streetView(double y, double yawDegrees = 0.0)
{
    const double yaw = glm::radians(yawDegrees);
    return lookFrom({85.0, y, 1.7}, {std::sin(yaw), std::cos(yaw), -0.02}, {0, 0, 1});
}

VisibleSet syncAnswer(const std::string& modes, const Scene& scene, const View& view)
{
    return chainAnswer(modes, scene, view);
}

bool isSubset(const VisibleSet& a, const VisibleSet& b)
{
    for (ObjectId id : a.ids())
        if (!b.test(id))
            return false;
    return true;
}

std::shared_ptr<const Scene> shared(const Scene& scene)
{
    return std::make_shared<const Scene>(scene);
}
} // namespace

TEST(AsyncVisibility, AnswersOnlyOnceTheWorkerHasARegionHoldingTheView)
{
    const City city = makeCity();
    AsyncVisibility async("frustum+octree");
    ASSERT_TRUE(async.supported());
    async.setScene(shared(city.scene));
    const View view = streetView(10.0);
    VisibleSet visible(3, true);
    EXPECT_FALSE(async.cull(view, visible)) << "the worker cannot have answered yet";
    EXPECT_EQ(visible.capacity(), 3u) << "a miss leaves the set untouched";
    async.waitIdle();
    ASSERT_TRUE(async.cull(view, visible));
    // Between the view's own answer and frustum culling alone.
    EXPECT_TRUE(isSubset(syncAnswer("frustum+octree", city.scene, view), visible));
    EXPECT_TRUE(isSubset(visible, syncAnswer("frustum", city.scene, view)));
    EXPECT_LT(visible.count(), syncAnswer("frustum", city.scene, view).count());

    // A jump far from the region is never answered from it.
    EXPECT_FALSE(async.cull(streetView(150.0), visible));
    const AsyncStatistics statistics = async.statistics();
    EXPECT_EQ(statistics.answered, 1u);
    EXPECT_EQ(statistics.missed, 2u);
    EXPECT_GE(statistics.regionsComputed, 1u);
}

// What a prefetch reads: the finished regions, every direction, so more than the view's answer and
// everything the rays see from the region's eyes.
TEST(AsyncVisibility, RegionsAheadHoldTheAnswersOfEveryDirection)
{
    const City city = makeCity();
    AsyncVisibility async("frustum+octree");
    VisibleSet ahead(3, true);
    EXPECT_FALSE(async.regionsAhead(ahead)) << "no scene yet";
    async.setScene(shared(city.scene));
    const View view = streetView(10.0);
    VisibleSet visible;
    EXPECT_FALSE(async.cull(view, visible));
    EXPECT_FALSE(async.regionsAhead(ahead)) << "no region finished yet";
    EXPECT_EQ(ahead.capacity(), 3u) << "nothing finished leaves the set untouched";
    async.waitIdle();
    ASSERT_TRUE(async.cull(view, visible));
    ASSERT_TRUE(async.regionsAhead(ahead));
    EXPECT_TRUE(isSubset(visible, ahead));
    EXPECT_GT(ahead.count(), visible.count()) << "a region looks every way, the view only ahead";
    const VisibleSet behind = syncAnswer("frustum+octree", city.scene, streetView(10.0, 180.0));
    EXPECT_TRUE(isSubset(behind, ahead));
    EXPECT_LT(ahead.count(), city.scene.objects.size());
}

TEST(AsyncVisibility, PredictsASteadyWalkAndKeepsEverythingTheRaysSee)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    // Octree regions along the predicted path; multifocal regions of a bake cell's size, answered
    // in two passes (coarse, then full), each conservative.
    for (const std::string modes : {"frustum+octree", "frustum+multifocal"})
    {
        SCOPED_TRACE(modes);
        AsyncOptions options;
        options.lookAheadFrames = 8;
        if (modes == "frustum+multifocal")
            options.regionSize = Vec3(4, 4, 2);
        AsyncVisibility async(modes, options);
        async.setScene(shared(city.scene));
        async.waitIdle();
        std::ostringstream missed;
        VisibleSet visible;
        std::size_t answeredFrames = 0;
        for (int frame = 0; frame < 60; ++frame)
        {
            // 0.5 m per frame, looking about a little: the region is ahead of the eye, every direction.
            const View view = streetView(-5.0 + 0.5 * frame, 15.0 * std::sin(0.2 * frame));
            if (async.cull(view, visible))
            {
                ++answeredFrames;
                for (ObjectId id : rays.cast(view).ids())
                    if (!visible.test(id))
                        missed << "frame " << frame << ": " << city.scene.objects[id].name << "\n";
            }
            async.waitIdle(); // a worker as fast as the frames
        }
        EXPECT_EQ(missed.str(), "");
        // Only the first frame (no step seen yet) and the second (the first region had no path) miss.
        EXPECT_GE(answeredFrames, 57u);
        const AsyncStatistics statistics = async.statistics();
        EXPECT_LT(statistics.regionsComputed, 20u) << "a region serves several frames";
        EXPECT_EQ(statistics.refinedAnswers, modes == "frustum+multifocal" ? statistics.regionsComputed : 0u);
    }
}

TEST(AsyncVisibility, ARegionSizeMakesRegionsAtLeastThatLarge)
{
    const City city = makeCity();
    AsyncOptions options;
    options.regionSize = Vec3(4, 4, 2);
    AsyncVisibility async("frustum+multifocal", options);
    async.setScene(shared(city.scene));
    VisibleSet visible;
    async.cull(streetView(10.0), visible);
    async.waitIdle();
    // The eye stands still: the region is the 4 × 4 × 2 box around it, so a step of 1.5 m stays in
    // it (without a size the region would be the eye's point grown by the slack).
    ASSERT_TRUE(async.cull(streetView(10.0), visible));
    async.waitIdle();
    EXPECT_TRUE(async.cull(streetView(11.5), visible));
}

TEST(AsyncVisibility, ANewSceneDropsEveryRegionOfTheOldOne)
{
    City city = makeCity();
    AsyncVisibility async("frustum+octree");
    async.setScene(shared(city.scene));
    const View view = streetView(10.0);
    VisibleSet visible;
    async.cull(view, visible);
    async.waitIdle();
    ASSERT_TRUE(async.cull(view, visible));
    // The street gets a wall across it right in front of the eye: the old answer would be wrong.
    const ObjectId wall = addBox(city.scene, {80, 14, 0}, {90, 15, 20}, "new wall");
    async.setScene(shared(city.scene));
    EXPECT_FALSE(async.cull(view, visible));
    async.waitIdle();
    ASSERT_TRUE(async.cull(view, visible));
    EXPECT_EQ(visible.capacity(), city.scene.objects.size());
    EXPECT_TRUE(visible.test(wall));
}

TEST(AsyncVisibility, ChainsWithoutRegionQueriesNeverAnswer)
{
    const City city = makeCity();
    AsyncVisibility async("frustum+mask");
    EXPECT_FALSE(async.supported());
    async.setScene(shared(city.scene));
    VisibleSet visible;
    for (int frame = 0; frame < 3; ++frame)
    {
        EXPECT_FALSE(async.cull(streetView(10.0), visible));
        async.waitIdle();
    }
}

// For ThreadSanitizer: the worker computes while the cull thread culls, reads statistics and
// replaces the scene, and the object is destroyed with work in flight.
TEST(AsyncVisibility, CullsWhileTheWorkerComputesAndStopsWithWorkQueued)
{
    const City city = makeCity();
    std::atomic<bool> done{false};
    {
        AsyncVisibility async("frustum+octree");
        async.setScene(shared(city.scene));
        std::thread reader(
            [&]
            {
                while (!done)
                    (void)async.statistics();
            });
        VisibleSet visible;
        for (int frame = 0; frame < 200; ++frame)
        {
            async.cull(streetView(-5.0 + 0.7 * frame), visible);
            if (frame == 100)
                async.setScene(shared(city.scene));
        }
        done = true;
        reader.join();
        const AsyncStatistics statistics = async.statistics();
        EXPECT_EQ(statistics.answered + statistics.missed, 200u);
    }
}
