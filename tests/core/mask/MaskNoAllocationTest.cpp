// SPDX-License-Identifier: MIT
// Issue 44: a warm mask frame allocates nothing, critical frames included (selection, groups,
// rasterization, pyramid, marking, stamps). A replaced global operator new counts; the walk is
// replayed later in walk time, so every measured frame is critical and does the same work as
// the warm-up frame at its place.
#include "AllocationCounter.h"
#include "BoxScenes.h"
#include "TestHierarchies.h"

#include <osgVis/core/mask/MaskModule.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
// A street walk with a turn each frame and steps far beyond δ: every frame is critical.
std::vector<View> turningWalk(double startTime)
{
    const Mat4 projection = glm::perspective(glm::radians(60.0), 4.0 / 3.0, 0.1, 1000.0);
    std::vector<View> views;
    for (int f = 0; f < 24; ++f)
    {
        const double yaw = glm::radians(15.0 * std::sin(0.7 * f));
        const Vec3 eye(85.0 + 0.3 * f, -8.0 + 6.0 * f, 1.7);
        views.push_back(makeView(glm::lookAt(eye, eye + Vec3(std::sin(yaw), std::cos(yaw), -0.02), Vec3(0, 0, 1)),
                                 projection, startTime + 0.1 * f, 320, 240));
    }
    return views;
}

// Allocations during the second walk, after the first warmed the module; checks that every frame
// of the second walk was critical and that the walk culled something.
std::size_t allocationsOfWarmWalk(MaskModule& module, const Scene& scene)
{
    module.setScene(scene);
    VisibleSet visible;
    for (const View& view : turningWalk(0.0))
    {
        visible.reset(scene.objects.size(), true);
        module.cull(view, visible);
    }
    const std::vector<View> walk = turningWalk(1000.0);
    std::size_t critical = 0, culled = 0;
    const std::size_t before = allocationCount();
    for (const View& view : walk)
    {
        visible.reset(scene.objects.size(), true); // no allocation: same capacity
        module.cull(view, visible);
        critical += module.lastStatistics().critical != MaskModule::CriticalReason::None;
        culled += module.lastStatistics().culled;
    }
    const std::size_t allocations = allocationCount() - before;
    EXPECT_EQ(critical, walk.size());
    EXPECT_GT(culled, 0u);
    return allocations;
}
} // namespace

TEST(MaskModule, WarmCriticalFramesAllocateNothingOnItsKdTree)
{
    const City city = makeCity();
    MaskModule module;
    EXPECT_EQ(allocationsOfWarmWalk(module, city.scene), 0u);
    EXPECT_FALSE(module.walksSceneHierarchy());
}

TEST(MaskModule, WarmCriticalFramesAllocateNothingOnTheRenderersHierarchy)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<Bvh>(city.scene, HierarchyLayout::Overlapping);
    MaskModule module;
    EXPECT_EQ(allocationsOfWarmWalk(module, city.scene), 0u);
    EXPECT_TRUE(module.walksSceneHierarchy());
}
