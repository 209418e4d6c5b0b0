// SPDX-License-Identifier: MIT
// Depth ties in mode `multifocal` (docs/multifocal.md, "Depth ties"): a box standing 1 cm behind a
// wall is hidden from a view cell only as far as the depth buffer of the views served resolves the
// gap. The margin follows each view's near plane and depth bits, a cell's answer is reused only for
// views its margin holds for, and baked cells and regions serve only such views.
#include "BoxScenes.h"
#include "RegionSampling.h"

#include <osgVis/core/module/BakedData.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
constexpr ObjectId Tied = 1;

// A 40 × 40 wall across x = 5 and a box (object Tied) from x = 5.01 behind it, the eye's cell
// around the origin. From the cell the box lies 4.76 to 6.25 away, and a 24-bit buffer at a near
// plane of 0.1 resolves the gap there many times over; a 16-bit one, or one at a near plane of
// 0.001, does not.
Scene wallAndTiedBox()
{
    Scene scene;
    addTriangles(scene,
                 {{Vec3f(5, -20, -20), Vec3f(5, 20, -20), Vec3f(5, 20, 20)}, {Vec3f(5, -20, -20), Vec3f(5, 20, 20), Vec3f(5, -20, 20)}},
                 "wall");
    addBox(scene, {5.01, -0.5, -0.5}, {6, 0.5, 0.5}, "tied");
    return scene;
}

MultifocalModuleOptions cellAroundTheOrigin()
{
    MultifocalModuleOptions options;
    options.cellSize = Vec3(0.5);
    options.cellOrigin = Vec3(-0.25);
    return options;
}

// Looking down +x from `eye`, 60° at 4:3, near plane at `nearPlane`.
View alongX(const Vec3& eye, double nearPlane)
{
    return makeView(glm::lookAt(eye, eye + Vec3(1, 0, 0), Vec3(0, 0, 1)),
                    glm::perspective(glm::radians(60.0), 4.0 / 3.0, nearPlane, 100.0));
}

// A 90° 16:9 view from the origin whose ray 0.9 of the way to the frame's corner, 61° off its
// axis, meets the tied box.
View throughCorner(std::uint32_t depthBits)
{
    return lookThroughCorner(Vec3(0), Vec3(5.5, 0, 0), 90.0, 1280, 720, 0.1, 0.9, depthBits);
}

bool tiedKept(MultifocalModule& module, const View& view)
{
    VisibleSet visible(2, true);
    module.cull(view, visible);
    return visible.test(Tied);
}
} // namespace

// A cell's answer computed for a far near plane has a depth margin for that plane (and half of it)
// only: a view with a nearer one, where the depth buffer resolves less, has the cell computed again.
TEST(MultifocalDepthTies, ACellsAnswerIsReusedOnlyForViewsItsMarginHolds)
{
    const Scene scene = wallAndTiedBox();
    MultifocalModule module(cellAroundTheOrigin());
    module.setScene(scene);
    EXPECT_FALSE(tiedKept(module, alongX(Vec3(0), 1.0))) << "a near plane of 1 resolves the gap";
    EXPECT_FALSE(tiedKept(module, alongX(Vec3(0.1, 0, 0), 1.0))) << "the same projection elsewhere in the cell";
    EXPECT_FALSE(tiedKept(module, alongX(Vec3(0), 0.6))) << "a near plane down to half the first is served";
    EXPECT_EQ(module.cellsComputed(), 1u);
    EXPECT_TRUE(tiedKept(module, alongX(Vec3(0), 0.001))) << "a near plane of 0.001 does not";
    EXPECT_EQ(module.cellsComputed(), 2u);
}

// The margin comes from the view's own depth bits, on a wide view whose steep corner rays meet the box.
TEST(MultifocalDepthTies, TheMarginFollowsTheViewsDepthBits)
{
    const Scene scene = wallAndTiedBox();
    for (std::uint32_t bits : {24u, 16u})
    {
        MultifocalModule module(cellAroundTheOrigin());
        module.setScene(scene);
        EXPECT_EQ(tiedKept(module, throughCorner(bits)), bits == 16) << bits << " bits";
    }
}

// Baked cells hold for the views their bake's margin holds for: a near plane no farther than an
// eighth of the reach baked for (docs/multifocal.md), a 24-bit depth buffer. Others keep everything.
TEST(MultifocalDepthTies, BakedCellsServeOnlyViewsTheirMarginHolds)
{
    const Scene scene = wallAndTiedBox();
    auto baked = std::make_shared<BakedViewCells>();
    baked->fingerprint = sceneFingerprint(scene);
    baked->objectCount = std::uint32_t(scene.objects.size());
    baked->nearDistance = 0.4;
    baked->cells.totalCells = 1;
    baked->cells.cellIndices = {0};
    baked->cells.cells = {Aabb(Vec3(-0.25), Vec3(0.25))};
    baked->cells.pvs = {VisibleSet(scene.objects.size())}; // nothing: a set no computation gives
    auto given = std::make_shared<BakedData>();
    given->set<BakedViewCells>(baked);
    MultifocalModule module;
    module.setBakedData(*given);
    module.setScene(scene);
    ASSERT_EQ(module.bakedCells(), baked);
    EXPECT_FALSE(tiedKept(module, throughCorner(24))) << "near 0.1 ≥ 0.4 / 8, reach 0.23 ≤ 0.4";
    EXPECT_EQ(module.viewsOutsideBakedCells(), 0u);
    EXPECT_TRUE(tiedKept(module, throughCorner(16)));
    EXPECT_TRUE(tiedKept(module, alongX(Vec3(0), 0.01))) << "near 0.01 < 0.4 / 8";
    EXPECT_EQ(module.viewsOutsideBakedCells(), 2u);
}

// A region's answer holds for views of its depth bits and more.
TEST(MultifocalDepthTies, ARegionsMarginFollowsItsDepthBits)
{
    const Scene scene = wallAndTiedBox();
    MultifocalModule module;
    module.setScene(scene);
    ViewRegion region = regionAround(Vec3(0), Vec3(0.25));
    for (std::uint32_t bits : {24u, 16u})
    {
        region.depthBits = bits;
        VisibleSet visible(scene.objects.size(), true);
        module.cullRegion(region, visible);
        EXPECT_EQ(visible.test(Tied), bits == 16) << bits << " bits";
    }
    EXPECT_FALSE(region.holds(throughCorner(15)));
    EXPECT_TRUE(region.holds(throughCorner(24)));
}
