// SPDX-License-Identifier: MIT
// The query phase allocates nothing after warm-up: a replaced global operator new counts.
#include "AllocationCounter.h"

#include <osgVis/core/frustum/FrustumModule.h>
#include <osgVis/core/api/ModuleRegistry.h>

#include <atomic>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <new>

using namespace osgVis::core;

TEST(FrustumModule, NoAllocationAfterWarmUp)
{
    Scene scene;
    for (int x = 0; x < 20; ++x)
        for (int y = 0; y < 20; ++y)
            scene.addObject(Aabb(Vec3(3 * x, 3 * y, 0), Vec3(3 * x + 1, 3 * y + 1, 1)), 12);
    ModuleChain chain = createChain("frustum");
    chain.setScene(scene);
    const Mat4 projection = glm::perspective(glm::radians(60.0), 1.25, 0.1, 100.0);
    VisibleSet visible;
    std::vector<View> views;
    for (int i = 0; i < 20; ++i)
        views.push_back(makeView(glm::lookAt(Vec3(i * 2.0, -10, 5), Vec3(30, 30, 0), Vec3(0, 0, 1)), projection));
    for (const View& v : views)
        chain.cull(v, visible); // warm-up

    const std::size_t before = osgVis::test::allocationCount();
    for (const View& v : views)
        chain.cull(v, visible);
    EXPECT_EQ(osgVis::test::allocationCount() - before, 0u);
    EXPECT_GT(visible.count(), 0u);
    EXPECT_LT(visible.count(), scene.objects.size());
}
