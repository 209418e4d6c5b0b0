// SPDX-License-Identifier: MIT
// Issue 56: the octree's work budget (OctreeOptions::workBudget). Whatever the budget, the
// traversal spends at most its 3/5 share, every object the rays see stays visible (the frustum
// still decides what the budget does not reach), a budget that suffices changes nothing, the
// module says when the budget cut a query short, and answers the same on every run.
#include "BoxScenes.h"
#include "FirstQuery.h"
#include "RayCastVisibility.h"

#include <osgVis/core/octree/OctreeModule.h>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
using Answer = FirstQuery<OctreeModule>;

Answer query(const Scene& scene, const View& view, std::uint64_t budget)
{
    OctreeOptions options;
    options.workBudget = budget;
    return firstQuery<OctreeModule>(scene, view, options);
}

// Objects outside the view's frustum (by their boxes).
std::size_t outsideFrustum(const Scene& scene, const View& view)
{
    std::size_t count = 0;
    for (const SceneObject& object : scene.objects)
        count += view.frustum.classify(object.bounds) == Containment::Outside;
    return count;
}
} // namespace

TEST(OctreeBudget, SpendsItsShareKeepsWhatTheRaysSeeAndStillCullsTheFrustum)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    std::size_t cutShort = 0, hiddenUnlimited = 0, hiddenSmall = 0;
    for (const View& view : cityStreetViews())
    {
        const RayCastResult seen = rays.cast(view);
        const Answer unlimited = query(city.scene, view, 0);
        EXPECT_FALSE(unlimited.stats.overBudget);
        const std::uint64_t needed = unlimited.stats.traversalWork + unlimited.stats.sweepWork;
        ASSERT_GT(needed, 1000u);
        const std::size_t outside = outsideFrustum(city.scene, view);
        ASSERT_GT(outside, 0u);
        for (const std::uint64_t budget : {needed * 2, needed / 2, needed / 8, std::uint64_t(10)})
        {
            const Answer limited = query(city.scene, view, budget);
            EXPECT_LE(limited.stats.traversalWork, budget / 5 * 3) << "budget " << budget;
            EXPECT_LE(limited.stats.traversalWork + limited.stats.sweepWork, needed) << "budget " << budget;
            if (!(limited.visible == unlimited.visible))
            {
                EXPECT_TRUE(limited.stats.overBudget) << "hid less without saying so, budget " << budget;
            }
            cutShort += limited.stats.overBudget;
            for (ObjectId id = 0; id < city.scene.objects.size(); ++id)
            {
                if (seen.visible[id])
                {
                    ASSERT_TRUE(limited.visible.test(id)) << "object " << id << " seen by the rays, budget " << budget;
                }
            }
            // Out of budget the frustum still decides: nothing outside it is kept.
            EXPECT_GE(city.scene.objects.size() - limited.visible.count(), outside) << "budget " << budget;
            if (budget == needed * 2)
            {
                EXPECT_TRUE(limited.visible == unlimited.visible) << "a budget that suffices changes nothing";
            }
            if (budget == 10)
                hiddenSmall += city.scene.objects.size() - limited.visible.count();
            EXPECT_TRUE(query(city.scene, view, budget).visible == limited.visible) << "reproducible";
        }
        hiddenUnlimited += city.scene.objects.size() - unlimited.visible.count();
    }
    EXPECT_GE(cutShort, 12u) << "half and an eighth of the need cut every query short";
    EXPECT_LT(hiddenSmall, hiddenUnlimited);
}

TEST(OctreeBudget, ABudgetedQueryIsTheSameAtEveryThreadCountAndOffByDefault)
{
    EXPECT_EQ(OctreeOptions().workBudget, 0u);
    const City city = makeCity();
    const View view = cityStreetViews()[2];
    const Answer unlimited = query(city.scene, view, 0);
    const std::uint64_t budget = (unlimited.stats.traversalWork + unlimited.stats.sweepWork) / 3;
    const Answer reference = query(city.scene, view, budget);
    ASSERT_TRUE(reference.stats.overBudget);
    for (const int threads : {1, 2, 4})
    {
        tbb::task_arena arena(threads);
        Answer answer{VisibleSet(), {}};
        arena.execute([&] { answer = query(city.scene, view, budget); });
        EXPECT_TRUE(answer.visible == reference.visible) << threads << " threads";
        EXPECT_EQ(answer.stats.traversalWork, reference.stats.traversalWork) << threads << " threads";
    }
}
