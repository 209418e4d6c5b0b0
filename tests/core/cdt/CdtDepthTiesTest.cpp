// SPDX-License-Identifier: MIT
// Depth ties in the CDT method's depth-free rule (docs/cdt.md, "The traversal"): a wall goes in as
// cover that needs no depth only when it lies inside its cell by more than the view's depth buffer
// resolves; a box in the next cell, 4 mm behind the wall, seen along a steep corner ray of a wide
// view, is culled with a 24-bit buffer and kept with a 16-bit one, in which the two tie.
#include "BoxScenes.h"
#include "RegionSampling.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/scene/TraversalHierarchy.h>

#include <gtest/gtest.h>

#include <memory>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
constexpr double Gap = 0.004;
constexpr ObjectId Wall = 0, Tied = 1;

// A renderer's kd-tree of two cells split at x = Gap: the wall's (the eye's) and the box's.
class SplitAtGap : public TraversalHierarchy
{
public:
    HierarchyLayout layout() const override { return HierarchyLayout::Disjoint; }
    std::uint32_t nodeCount() const override { return 3; }
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override
    {
        const HierarchyNode root{0, Aabb(Vec3(-100), Vec3(100)), nullptr, 0};
        const HierarchyNode wall{1, Aabb(Vec3(-100), Vec3(Gap, 100, 100)), &Wall, 1};
        const HierarchyNode tied{2, Aabb(Vec3(Gap, -100, -100), Vec3(100)), &Tied, 1};
        if (!visitor.enter(root))
            return;
        const bool wallFirst = eye.x <= Gap;
        for (const HierarchyNode* node : {wallFirst ? &wall : &tied, wallFirst ? &tied : &wall})
            if (visitor.enter(*node))
                visitor.leave(*node);
        visitor.leave(root);
    }
};

// A 2 × 2 wall across x = 0 and a 10 cm box from x = Gap behind it, seen from 10 in front.
Scene wallAndTiedBox()
{
    Scene scene;
    addTriangles(scene, {{Vec3f(0, -1, -1), Vec3f(0, 1, 1), Vec3f(0, 1, -1)}, {Vec3f(0, -1, -1), Vec3f(0, -1, 1), Vec3f(0, 1, 1)}},
                 "wall");
    addBox(scene, {Gap, -0.05, -0.05}, {Gap + 0.1, 0.05, 0.05}, "tied");
    scene.hierarchy = std::make_shared<SplitAtGap>();
    return scene;
}
} // namespace

// The box's ray runs 61° off the axis of a 90° 16:9 view (its corners 64° off it). At 24 bits the
// 4 mm gap is 140 depth steps there, at 16 bits half of one.
TEST(CdtDepthTies, TheDepthFreeRuleKeepsWhatTiesInTheViewsDepthBuffer)
{
    const Scene scene = wallAndTiedBox();
    for (const char* mode : {"cdt", "cdt-depthfree"})
        for (std::uint32_t bits : {24u, 16u})
        {
            const std::unique_ptr<VisibilityModule> module = createModule(mode);
            module->setScene(scene);
            const View view = lookThroughCorner(Vec3(-10, 0, 0), Vec3(Gap + 0.05, 0, 0), 90.0, 1280, 720, 0.1, 0.9, bits);
            VisibleSet visible(scene.objects.size(), true);
            module->cull(view, visible);
            EXPECT_TRUE(visible.test(Wall)) << mode << ", " << bits << " bits";
            EXPECT_EQ(visible.test(Tied), bits == 16) << mode << ", " << bits << " bits";
        }
}
