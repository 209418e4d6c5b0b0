// SPDX-License-Identifier: MIT
// Issue 44: the mask's work budget (MaskOptions::workBudget). Whatever the budget, a critical frame
// spends no more than it, keeps every object the rays see, hides a subset of what the unlimited
// module hides, says when the budget cut it short, and answers the same on every run.
#include "BoxScenes.h"
#include "RayCastVisibility.h"

#include <osgVis/core/mask/MaskModule.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
std::vector<View> streetViews()
{
    const Mat4 projection = glm::perspective(glm::radians(60.0), 4.0 / 3.0, 0.1, 1000.0);
    std::vector<View> views;
    for (int f = 0; f < 6; ++f)
    {
        const double yaw = glm::radians(-20.0 + 8.0 * f);
        const Vec3 eye(85.0, -8.0 + 25.0 * f, 1.7);
        views.push_back(makeView(glm::lookAt(eye, eye + Vec3(std::sin(yaw), std::cos(yaw), -0.02), Vec3(0, 0, 1)),
                                 projection, 0.0, 320, 240));
    }
    return views;
}

struct Answer
{
    VisibleSet visible;
    MaskModule::Statistics stats;
};

// A fresh module's first (critical) frame.
Answer firstFrame(const Scene& scene, const View& view, std::uint64_t budget)
{
    MaskOptions options;
    options.workBudget = budget;
    MaskModule module(options);
    module.setScene(scene);
    Answer answer{VisibleSet(scene.objects.size(), true), {}};
    module.cull(view, answer.visible);
    answer.stats = module.lastStatistics();
    return answer;
}
} // namespace

TEST(MaskBudget, NeverSpendsMoreThanItsBudgetAndOnlyHidesLess)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    std::size_t cutShort = 0, hiddenUnlimited = 0, hiddenSmall = 0;
    for (const View& view : streetViews())
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
