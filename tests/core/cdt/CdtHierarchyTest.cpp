// SPDX-License-Identifier: MIT
// The cdt module on a renderer's own hierarchy (visibility API, ordered traversal by callback): a
// renderer kd-tree built as the module builds its own gives exactly the module's sets; a BVH
// (overlapping boxes) is walked under the depth-only rule and keeps everything the rays see; a
// hierarchy that lies about being disjoint is caught and walked as overlapping; a traversal out
// of front-to-back order keeps every candidate; an unusable one is replaced by the module's tree.
#include "BoxScenes.h"
#include "RayCastVisibility.h"
#include "RegionSampling.h"
#include "TestHierarchies.h"

#include <osgVis/core/cdt/CdtModule.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace osgVis::core;
using namespace osgVis::test;

TEST(CdtHierarchy, RendererKdTreeGivesExactlyTheOwnTreesSets)
{
    City city = makeCity();
    const std::vector<View> views = cityViews(40);
    for (CdtOptions::Rule rule : {CdtOptions::Rule::Combined, CdtOptions::Rule::DepthFree, CdtOptions::Rule::DepthOnly})
    {
        CdtOptions options;
        options.rule = rule;
        CdtModule own(options);
        own.setScene(city.scene);
        Scene withHierarchy = city.scene;
        withHierarchy.hierarchy = kdTreeOf(city.scene);
        CdtModule walked(options);
        walked.setScene(withHierarchy);
        ASSERT_TRUE(walked.walksSceneHierarchy());
        EXPECT_FALSE(own.walksSceneHierarchy());
        EXPECT_EQ(walked.walkedLayout(), HierarchyLayout::Disjoint);
        EXPECT_EQ(walked.hierarchyProblem(), "");
        std::size_t culled = 0;
        for (std::size_t v = 0; v < views.size(); ++v)
        {
            const VisibleSet a = cullAll(own, city.scene.objects.size(), views[v]);
            const VisibleSet b = cullAll(walked, city.scene.objects.size(), views[v]);
            ASSERT_EQ(a.ids(), b.ids()) << own.name() << ", view " << v;
            EXPECT_FALSE(walked.lastStatistics().traversalStrayed);
            culled += city.scene.objects.size() - a.count();
        }
        EXPECT_GT(culled, views.size() * 100) << "the comparison is not between two empty answers";
    }
}

TEST(CdtHierarchy, OverlappingBvhIsWalkedByDepthAndKeepsWhatTheRaysSee)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<Bvh>(city.scene, HierarchyLayout::Overlapping);
    CdtModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.walksSceneHierarchy());
    EXPECT_EQ(module.walkedLayout(), HierarchyLayout::Overlapping);
    const std::vector<View> views = cityViews(30);
    EXPECT_EQ(missedByRays("renderer BVH", module, city.scene, views), 0u);
    const City plain = makeCity();
    CdtModule own; // for the efficacy beside it
    own.setScene(plain.scene);
    EXPECT_EQ(missedByRays("own kd-tree", own, plain.scene, views), 0u);
    std::size_t culled = 0;
    for (const View& view : views)
        culled += city.scene.objects.size() - cullAll(module, city.scene.objects.size(), view).count();
    EXPECT_GT(culled, views.size() * 50) << "a BVH still groups: occlusion by depth culls";
}

TEST(CdtHierarchy, BvhDeclaredDisjointIsCaughtAndWalkedAsOverlapping)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<Bvh>(city.scene, HierarchyLayout::Disjoint);
    CdtModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.walksSceneHierarchy());
    EXPECT_EQ(module.walkedLayout(), HierarchyLayout::Overlapping);
    EXPECT_NE(module.hierarchyProblem().find("declared disjoint, but"), std::string::npos) << module.hierarchyProblem();
    EXPECT_EQ(missedByRays("BVH said disjoint", module, city.scene, cityViews(30)), 0u);
}

TEST(CdtHierarchy, TraversalOutOfFrontToBackOrderKeepsEveryCandidate)
{
    City city = makeCity();
    city.scene.hierarchy = std::make_shared<BackToFront>(kdTreeOf(city.scene));
    CdtModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.walksSceneHierarchy());
    for (const View& view : cityViews(10))
    {
        const VisibleSet answer = cullAll(module, city.scene.objects.size(), view);
        EXPECT_TRUE(module.lastStatistics().traversalStrayed);
        EXPECT_EQ(answer.count(), city.scene.objects.size());
    }
}

TEST(CdtHierarchy, UnusableHierarchyIsReplacedByTheModulesOwnTree)
{
    expectUnusableHierarchyReplaced<CdtModule, CdtOptions>();
}
