// SPDX-License-Identifier: MIT
// The octree module on a renderer's own hierarchy (visibility API, ordered traversal by callback):
// a BVH built as the module builds its kd-tree gives exactly the module's sets, views and regions;
// a kd-tree of disjoint cells holding objects at inner nodes keeps everything the rays see, in
// either traversal order (each box is tested on its own); a node that strays from what was
// recorded is kept with its subtree; an unusable hierarchy is replaced by the module's own tree.
#include "BoxScenes.h"
#include "RegionSampling.h"
#include "TestHierarchies.h"

#include <osgVis/core/octree/OctreeModule.h>

#include <gtest/gtest.h>

using namespace osgVis::core;
using namespace osgVis::test;

TEST(OctreeHierarchy, RendererBvhBuiltLikeItsOwnTreeGivesExactlyItsSets)
{
    City city = makeCity();
    const std::vector<View> views = cityViews(40);
    for (bool fuseDisjoint : {true, false})
    {
        OctreeOptions options;
        options.fuseDisjoint = fuseDisjoint;
        OctreeModule own(options);
        own.setScene(city.scene);
        Scene withHierarchy = city.scene;
        withHierarchy.hierarchy = std::make_shared<Bvh>(city.scene, HierarchyLayout::Overlapping, options.maxLeafObjects);
        OctreeModule walked(options);
        walked.setScene(withHierarchy);
        ASSERT_TRUE(walked.walksSceneHierarchy());
        EXPECT_FALSE(own.walksSceneHierarchy());
        EXPECT_EQ(walked.hierarchyProblem(), "");
        std::size_t culled = 0;
        for (std::size_t v = 0; v < views.size(); ++v)
        {
            const VisibleSet a = cullAll(own, city.scene.objects.size(), views[v]);
            const VisibleSet b = cullAll(walked, city.scene.objects.size(), views[v]);
            ASSERT_EQ(a.ids(), b.ids()) << own.name() << ", view " << v;
            EXPECT_EQ(walked.lastStatistics().nodesStrayed, 0u);
            EXPECT_EQ(walked.lastStatistics().nodesVisited, own.lastStatistics().nodesVisited) << "view " << v;
            culled += city.scene.objects.size() - a.count();
        }
        EXPECT_GT(culled, views.size() * 100) << "the comparison is not between two empty answers";

        for (const Vec3& center : {Vec3(25.0, 60.0, 1.7), Vec3(85.0, 20.0, 6.0)})
        {
            const ViewRegion region = regionAround(center, Vec3(2.0, 2.0, 1.0));
            VisibleSet a(city.scene.objects.size(), true), b(city.scene.objects.size(), true);
            own.cullRegion(region, a);
            walked.cullRegion(region, b);
            EXPECT_EQ(a.ids(), b.ids()) << "region around " << center.x << ", " << center.y;
        }
    }
}

TEST(OctreeHierarchy, DisjointCellsInEitherOrderKeepWhatTheRaysSee)
{
    City city = makeCity();
    const std::vector<View> views = cityViews(30);
    Scene frontToBack = city.scene, backToFront = city.scene;
    frontToBack.hierarchy = kdTreeOf(city.scene);
    backToFront.hierarchy = std::make_shared<BackToFront>(kdTreeOf(city.scene));
    OctreeModule ordered, reversed, own;
    ordered.setScene(frontToBack);
    reversed.setScene(backToFront);
    own.setScene(city.scene);
    ASSERT_TRUE(ordered.walksSceneHierarchy());
    ASSERT_TRUE(reversed.walksSceneHierarchy());
    EXPECT_EQ(missedByRays("renderer kd-tree", ordered, frontToBack, views), 0u);
    EXPECT_EQ(missedByRays("own kd-tree", own, city.scene, views), 0u); // the efficacy beside it
    for (std::size_t v = 0; v < views.size(); ++v)
    {
        const VisibleSet a = cullAll(ordered, city.scene.objects.size(), views[v]);
        const VisibleSet b = cullAll(reversed, city.scene.objects.size(), views[v]);
        EXPECT_EQ(reversed.lastStatistics().nodesStrayed, 0u) << "order is not needed, so not checked";
        ASSERT_EQ(a.ids(), b.ids()) << "view " << v;
    }
    const std::size_t walked = culledOver(ordered, frontToBack, views), built = culledOver(own, city.scene, views);
    EXPECT_GT(walked, built * 9 / 10) << "objects at inner nodes are still tested one by one";
}

TEST(OctreeHierarchy, NodeThatStraysIsKeptWithItsSubtree)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<GrowsAfterFirstWalk>(kdTreeOf(city.scene));
    OctreeOptions options;
    options.fuseDisjoint = false; // the sweep runs after the traversal and would cull on its own
    OctreeModule module(options);
    module.setScene(city.scene); // the recording walk
    ASSERT_TRUE(module.walksSceneHierarchy());
    for (const View& view : cityViews(5))
    {
        const VisibleSet answer = cullAll(module, city.scene.objects.size(), view);
        EXPECT_EQ(module.lastStatistics().nodesStrayed, 1u);
        EXPECT_EQ(answer.count(), city.scene.objects.size());
    }
}

TEST(OctreeHierarchy, UnusableHierarchyIsReplacedByTheModulesOwnTree)
{
    expectUnusableHierarchyReplaced<OctreeModule, OctreeOptions>();
}
