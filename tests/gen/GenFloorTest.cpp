// SPDX-License-Identifier: MIT
// The floor preset: one office storey of fixed size (~2 300 objects whatever the budget), walked
// along its corridors only.
#include "SceneProbe.h"

#include <osgVis/gen/Generator.h>
#include <osgVis/gen/SceneStats.h>

#include <gtest/gtest.h>

#include <sstream>

namespace gen = osgVis::gen;
using gen::test::drawablesOf;

namespace
{
gen::GeneratedScene makeFloor(std::uint64_t triangles, std::uint32_t seed = 1)
{
    gen::GenerateOptions options;
    options.kind = gen::SceneKind::Floor;
    options.triangles = triangles;
    options.seed = seed;
    return gen::generate(options);
}

bool overFloorOf(const osg::BoundingBox& floor, const osgVis::core::WalkKey& key)
{
    return key.eye.x > floor.xMin() && key.eye.x < floor.xMax() && key.eye.y > floor.yMin() &&
           key.eye.y < floor.yMax();
}
} // namespace

TEST(GenFloor, HasAboutTwoThousandThreeHundredObjectsAtTheDefaultBudget)
{
    EXPECT_EQ(gen::defaultTriangles(gen::SceneKind::Floor), 300000u);
    for (std::uint32_t seed : {1u, 2u, 3u})
    {
        const gen::SceneStats stats = gen::sceneStats(*makeFloor(300000, seed).root);
        EXPECT_GE(stats.objects, 2185u) << "seed " << seed; // 2 300 − 5 %
        EXPECT_LE(stats.objects, 2415u) << "seed " << seed; // 2 300 + 5 %
        EXPECT_NEAR(double(stats.triangles), 300000.0, 30000.0) << "seed " << seed;
    }
}

TEST(GenFloor, BudgetChangesOnlyTheTessellation)
{
    const gen::GeneratedScene coarse = makeFloor(gen::minTrianglesFor(gen::SceneKind::Floor));
    const gen::GeneratedScene fine = makeFloor(1000000);
    const gen::SceneStats coarseStats = gen::sceneStats(*coarse.root), fineStats = gen::sceneStats(*fine.root);
    EXPECT_EQ(coarseStats.objects, fineStats.objects);
    EXPECT_NEAR(double(fineStats.triangles), 1e6, 1e5);
    EXPECT_NEAR(double(coarseStats.triangles), 60000.0, 6000.0);

    const auto coarseDrawables = drawablesOf(*coarse.root), fineDrawables = drawablesOf(*fine.root);
    ASSERT_EQ(coarseDrawables.size(), fineDrawables.size());
    for (std::size_t i = 0; i < coarseDrawables.size(); ++i)
    {
        EXPECT_EQ(coarseDrawables[i].name, fineDrawables[i].name);
        for (unsigned c = 0; c < 8; ++c)
            EXPECT_NEAR((coarseDrawables[i].worldBounds.corner(c) - fineDrawables[i].worldBounds.corner(c)).length(),
                        0.0f, 1e-4f);
    }
    std::ostringstream coarseWalk, fineWalk;
    coarse.walk.write(coarseWalk);
    fine.walk.write(fineWalk);
    EXPECT_EQ(coarseWalk.str(), fineWalk.str());
}

TEST(GenFloor, IsOneStorey)
{
    const auto drawables = drawablesOf(*makeFloor(60000).root);
    ASSERT_FALSE(drawables.empty());
    for (const auto& d : drawables)
    {
        EXPECT_GE(d.worldBounds.zMin(), -1e-4f) << d.name;
        EXPECT_LE(d.worldBounds.zMax(), 3.0f + 1e-4f) << d.name; // walls and ceilings are 3 m tall
    }
}

TEST(GenFloor, WalkNeverEntersARoom)
{
    for (std::uint32_t seed : {1u, 2u})
    {
        const gen::GeneratedScene scene = makeFloor(60000, seed);
        std::vector<osg::BoundingBox> corridors;
        std::size_t rooms = 0;
        for (const auto& d : drawablesOf(*scene.root))
        {
            if (d.name == "corridor floor")
                corridors.push_back(d.worldBounds);
            rooms += d.name == "floor" ? 1 : 0;
        }
        ASSERT_EQ(rooms, 204u);
        ASSERT_EQ(corridors.size(), 6u + 2u); // six wings' corridors and the two cross corridors
        ASSERT_GE(scene.walk.keys.size(), 200u);
        for (std::size_t i = 0; i < scene.walk.keys.size(); ++i)
        {
            bool inCorridor = false;
            for (const osg::BoundingBox& corridor : corridors)
                inCorridor = inCorridor || overFloorOf(corridor, scene.walk.keys[i]);
            EXPECT_TRUE(inCorridor) << "seed " << seed << " view " << i << " leaves the corridors";
            EXPECT_NEAR(scene.walk.keys[i].eye.z, 1.7, 1e-9);
        }
    }
}

TEST(GenFloor, SameSeedGivesTheSameWalkAndKindParses)
{
    EXPECT_EQ(gen::parseSceneKind("floor"), gen::SceneKind::Floor);
    EXPECT_STREQ(gen::sceneKindName(gen::SceneKind::Floor), "floor");
    std::ostringstream a, b;
    makeFloor(60000, 5).walk.write(a);
    makeFloor(60000, 5).walk.write(b);
    EXPECT_EQ(a.str(), b.str());
    EXPECT_THROW(makeFloor(gen::minTrianglesFor(gen::SceneKind::Floor) - 1), std::invalid_argument);
}
