// SPDX-License-Identifier: MIT
// Issue 44: the mask's work budget (MaskOptions::workBudget). Whatever the budget, a critical frame
// spends no more than it, keeps every object the rays see, hides a subset of what the unlimited
// module hides, says when the budget cut it short, and answers the same on every run.
#include "BoxScenes.h"
#include "FirstQuery.h"
#include "RayCastVisibility.h"

#include <osgVis/core/mask/MaskModule.h>

#include <gtest/gtest.h>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
using Answer = FirstQuery<MaskModule>;

Answer firstFrame(const Scene& scene, const View& view, std::uint64_t budget)
{
    MaskOptions options;
    options.workBudget = budget;
    return firstQuery<MaskModule>(scene, view, options);
}
} // namespace

TEST(MaskBudget, NeverSpendsMoreThanItsBudgetAndOnlyHidesLess)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    std::size_t cutShort = 0, hiddenUnlimited = 0, hiddenSmall = 0;
    for (const View& view : cityStreetViews())
    {
        const RayCastResult seen = rays.cast(view);
        const Answer unlimited = firstFrame(city.scene, view, 0);
        EXPECT_FALSE(unlimited.stats.overBudget);
        const std::uint64_t needed = unlimited.stats.rasterWork + unlimited.stats.markWork;
        ASSERT_GT(needed, 100u);
        for (const std::uint64_t budget : {needed * 2, needed / 2, needed / 8, std::uint64_t(40)})
        {
            const Answer limited = firstFrame(city.scene, view, budget);
            EXPECT_LE(limited.stats.rasterWork, budget / 5 * 3) << "budget " << budget;
            EXPECT_LE(limited.stats.rasterWork + limited.stats.markWork, budget) << "budget " << budget;
            if (!(limited.visible == unlimited.visible))
            {
                EXPECT_TRUE(limited.stats.overBudget) << "hid less without saying so, budget " << budget;
            }
            if (limited.stats.groupsSkipped != 0)
            {
                EXPECT_TRUE(limited.stats.overBudget);
            }
            cutShort += limited.stats.overBudget;
            for (ObjectId id = 0; id < city.scene.objects.size(); ++id)
            {
                if (seen.visible[id])
                {
                    ASSERT_TRUE(limited.visible.test(id)) << "object " << id << " seen by the rays, budget " << budget;
                }
                if (unlimited.visible.test(id))
                {
                    ASSERT_TRUE(limited.visible.test(id)) << "object " << id << " hidden only with a budget " << budget;
                }
            }
            if (budget == needed * 2)
            {
                EXPECT_TRUE(limited.visible == unlimited.visible) << "a budget that suffices changes nothing";
            }
            if (budget == 40)
                hiddenSmall += city.scene.objects.size() - limited.visible.count();
            EXPECT_TRUE(firstFrame(city.scene, view, budget).visible == limited.visible) << "reproducible";
        }
        hiddenUnlimited += city.scene.objects.size() - unlimited.visible.count();
    }
    EXPECT_GE(cutShort, 12u) << "half and an eighth of the need cut every frame short";
    EXPECT_LT(hiddenSmall, hiddenUnlimited);
}

TEST(MaskBudget, OffByDefaultWithTheCalibratedBoxTestWeight)
{
    const MaskOptions options;
    EXPECT_EQ(options.workBudget, 0u);
    EXPECT_EQ(options.boxTestWork, 7u);
}
