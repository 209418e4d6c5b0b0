// SPDX-License-Identifier: MIT
// The volume PVS (computeVolumePvs) and mode `multifocal` against the ray-cast reference, which
// shares no code with them: nothing seen from any sampled eye of a volume may be missing, also for
// volumes straddling walls, inside buildings and above the roofs; triangles of one mesh hide each
// other; the answer does not depend on the order of the occluders.
#include "BoxScenes.h"
#include "RayCastVisibility.h"
#include "RegionSampling.h"

#include <osgVis/core/module/ModuleChain.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/occluders/OccluderBuilder.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
VisibleSet volumeAnswer(const Scene& scene, const ViewRegion& region, const std::vector<OccluderPolygon>& occluders)
{
    MultifocalOptions options;
    options.nearDistance = region.maxNearReach;
    return computeVolumePvs(scene, occluders, region.eyes, options).objects;
}
} // namespace

TEST(VolumeVisibility, TheNearFaceOfABoxHidesItsFarFaceFromTheWholeVolume)
{
    Scene scene;
    addBox(scene, {5, -3, -3}, {7, 3, 3}, "block");
    const Aabb volume(Vec3(-0.5), Vec3(0.5));
    const VolumePvs pvs = computeVolumePvs(scene, volumeOccluders(scene), volume);
    ASSERT_EQ(pvs.hiddenTriangles.size(), 12u);
    for (std::size_t t = 0; t < 12; ++t)
    {
        const Triangle& tri = scene.triangles[t];
        const bool farFace = tri.a.x == 7.0f && tri.b.x == 7.0f && tri.c.x == 7.0f;
        EXPECT_EQ(pvs.hiddenTriangles[t] != 0, farFace) << "triangle " << t;
    }
    EXPECT_EQ(pvs.statistics.trianglesCulled, 2u);
    EXPECT_EQ(pvs.statistics.trianglesBackFacing, 10u); // the far face and the four sides
    EXPECT_TRUE(pvs.objects.test(0));
}

TEST(VolumeVisibility, KeepsEverythingTheRaysSeeFromAnyEyeOfTheVolume)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    const std::vector<OccluderPolygon> occluders = volumeOccluders(city.scene);
    const std::vector<ViewRegion> regions{
        regionAround({85, 10, 1.7}, {1.5, 4, 0.3}),  // along a street
        regionAround({85, 55, 1.7}, {3, 3, 0.3}),    // at a crossing
        regionAround({25, 85, 2.5}, {12, 2, 1}),     // as wide as a block
        regionAround({31, 36, 1.7}, {2, 2, 0.5}),    // straddling a building's wall
        regionAround({36, 36, 3.0}, {0.5, 0.5, 0.5}), // inside a building
        regionAround({85, 85, 60}, {4, 4, 2}),       // above the roofs
        regionAround({85, 40, 1.2}, {0.05, 0.05, 0.05}), // a small one
    };
    std::size_t kept = 0, total = 0;
    for (const ViewRegion& region : regions)
    {
        const VisibleSet answer = volumeAnswer(city.scene, region, occluders);
        EXPECT_EQ(missedFromRegion(rays, city.scene, region, answer, 8), "")
            << "eyes " << region.eyes.min.x << " " << region.eyes.min.y << " " << region.eyes.min.z;
        kept += answer.count();
        total += city.scene.objects.size();
    }
    // It culls: along the street the answer keeps 106 of the 252 objects (octree's region answer
    // keeps 175, tests/core/async).
    EXPECT_LE(volumeAnswer(city.scene, regions.front(), occluders).count(), 106u);
    EXPECT_LT(kept, total);
}

TEST(VolumeVisibility, TheAnswerDoesNotDependOnTheOrderOfTheOccluders)
{
    const City city = makeCity();
    std::vector<OccluderPolygon> occluders = volumeOccluders(city.scene);
    const ViewRegion region = regionAround({85, 10, 1.7}, {1.5, 4, 0.3});
    const VisibleSet first = volumeAnswer(city.scene, region, occluders);
    std::mt19937 random(3);
    std::shuffle(occluders.begin(), occluders.end(), random);
    EXPECT_EQ(volumeAnswer(city.scene, region, occluders), first);
}

TEST(VolumeVisibility, RefusesAnEmptyOrNonFiniteVolume)
{
    const City city = makeCity();
    EXPECT_THROW(computeVolumePvs(city.scene, {}, Aabb()), std::invalid_argument);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(computeVolumePvs(city.scene, {}, Aabb(Vec3(0), Vec3(nan, 1, 1))), std::invalid_argument);
    EXPECT_THROW(computeVolumePvs(city.scene, {}, Aabb(Vec3(0), Vec3(-1, 1, 1))), std::invalid_argument);
}

TEST(MultifocalModule, AViewTakesItsCellsPvsAndKeepsItWhileTheEyeStaysInTheCell)
{
    const City city = makeCity();
    MultifocalModuleOptions options;
    options.cellSize = Vec3(4, 4, 2);
    options.cellOrigin = Vec3(0, 0, 0.5); // eyes from 0.5 to 2.5 m above the street
    MultifocalModule module(options);
    module.setScene(city.scene);
    const View view = lookFrom({85.5, 10.5, 1.7}, {0, 1, 0}, {0, 0, 1});
    VisibleSet visible(city.scene.objects.size(), true);
    module.cull(view, visible);
    const Aabb cell = module.cellOf(view.eye);
    EXPECT_EQ(cell.min, Vec3(84, 8, 0.5));
    EXPECT_EQ(cell.max, Vec3(88, 12, 2.5));
    MultifocalOptions volume = moduleVolumeOptions();
    volume.nearDistance = nearPlaneReach(view);
    volume.minNearDistance = 0.5 * nearDistance(view); // a cell serves near planes down to half the view's
    EXPECT_EQ(visible, computeVolumePvs(city.scene, volumeOccluders(city.scene), cell, volume).objects);
    EXPECT_LT(visible.count(), city.scene.objects.size());

    VisibleSet again(city.scene.objects.size(), true);
    module.cull(lookFrom({87.5, 8.5, 1.2}, {-1, 0, 0}, {0, 0, 1}), again);
    EXPECT_EQ(again, visible);
    EXPECT_EQ(module.cellsComputed(), 1u);
    // Orthographic views keep everything.
    VisibleSet ortho(city.scene.objects.size(), true);
    module.cull(makeView(glm::lookAt(Vec3(85, 10, 50), Vec3(85, 10, 0), Vec3(0, 1, 0)),
                         glm::ortho(-50.0, 50.0, -50.0, 50.0, 0.1, 100.0)),
                ortho);
    EXPECT_EQ(ortho.count(), city.scene.objects.size());
}

TEST(MultifocalModule, EachPassOfARegionAnswerKeepsEverythingTheRaysSee)
{
    const City city = makeCity();
    const RayCastVisibility rays(city.scene);
    MultifocalModule module;
    module.setScene(city.scene);
    ASSERT_EQ(module.regionPasses(), 2u);
    for (const ViewRegion& region : {regionAround({85, 10, 1.7}, {2, 2, 1}), regionAround({55, 85, 1.7}, {2, 2, 1})})
        for (std::uint32_t pass = 0; pass < 2; ++pass)
        {
            VisibleSet answer(city.scene.objects.size(), true);
            module.cullRegionPass(region, answer, pass);
            EXPECT_EQ(missedFromRegion(rays, city.scene, region, answer), "") << "pass " << pass;
            EXPECT_LT(answer.count(), city.scene.objects.size()) << "pass " << pass;
        }
}

TEST(VolumeVisibility, AdversarialOccludersKeepEverythingTheRaysSee)
{
    // An oblique wall crossing every plane placed beyond the volume's +x face; a wall seen edge-on
    // from part of the volume (its plane cuts the volume); a slit between two walls narrower than
    // a plane pixel; an occludee reaching behind the volume.
    Scene scene;
    // Low enough that the sightlines through the slit pass above it.
    addTriangles(scene, {{Vec3f(4, -8, 0), Vec3f(9, 8, 0), Vec3f(9, 8, 1.5f)}, {Vec3f(4, -8, 0), Vec3f(9, 8, 1.5f), Vec3f(4, -8, 1.5f)}},
                 "oblique wall");
    addBox(scene, {3, -0.01, 4}, {12, 0.01, 6}, "edge-on wall"); // above the sightlines through the slit
    addBox(scene, {14, -10, 0}, {14.5, -0.004, 6}, "slit wall left");
    addBox(scene, {14, 0.004, 0}, {14.5, 10, 6}, "slit wall right");
    addBox(scene, {20, -0.5, 2}, {21, 0.5, 3}, "behind the slit");
    addBox(scene, {11, 3, 0}, {12, 4, 0.4}, "behind the oblique wall");
    addBox(scene, {-6, -1, 0}, {16, -0.5, 0.3}, "reaching behind the volume");
    const RayCastVisibility rays(scene);
    const ViewRegion facingTheSlit[] = {regionAround({0, 0, 2.5}, {0.5, 0.5, 0.5}), regionAround({0, 0.2, 2.5}, {1, 1, 1})};
    for (const ViewRegion& region : facingTheSlit)
    {
        const VisibleSet answer = volumeAnswer(scene, region, volumeOccluders(scene));
        EXPECT_EQ(missedFromRegion(rays, scene, region, answer, 16), "");
        EXPECT_TRUE(answer.test(4)) << "seen through the slit";
        EXPECT_TRUE(answer.test(6)) << "reaches behind the volume";
    }
    const ViewRegion aside = regionAround({-2, -3, 1}, {0.3, 0.3, 0.3});
    EXPECT_EQ(missedFromRegion(rays, scene, aside, volumeAnswer(scene, aside, volumeOccluders(scene)), 16), "");
}

// Two baked view cells of `scene` along the city's street, their PVS objects first..first+9 for
// each first in `firsts`: sets no computation would give. Baked for a near-plane reach of 0.38, so
// that they serve the tests' views (near plane 0.1, reach 0.14) and regions (0.05, 0.35): a reach
// no shorter than theirs, a near plane no nearer than an eighth of it (docs/multifocal.md).
std::shared_ptr<BakedViewCells> twoBakedCells(const Scene& scene, std::uint64_t fingerprint,
                                              std::initializer_list<std::uint32_t> firsts)
{
    auto baked = std::make_shared<BakedViewCells>();
    baked->fingerprint = fingerprint;
    baked->objectCount = std::uint32_t(scene.objects.size());
    baked->nearDistance = 0.38;
    baked->cells.totalCells = 2;
    baked->cells.cellIndices = {0, 1};
    baked->cells.cells = {Aabb(Vec3(84, 4, 0.7), Vec3(88, 8, 2.7)), Aabb(Vec3(84, 8, 0.7), Vec3(88, 12, 2.7))};
    for (std::uint32_t first : firsts)
    {
        VisibleSet pvs(scene.objects.size());
        for (ObjectId id = first; id < first + 10; ++id)
            pvs.set(id);
        baked->cells.pvs.push_back(pvs);
    }
    return baked;
}

TEST(MultifocalModule, ARegionInsideBakedCellsTakesTheUnionOfTheirPvs)
{
    City city = makeCity();
    addBox(city.scene, {500, 500, 0}, {501, 501, 1}, "far away"); // a model of its own in the store of bakes
    // Cell PVS of objects 0..9 and 5..14, registered under another model first.
    auto baked = twoBakedCells(city.scene, sceneFingerprint(city.scene) ^ 1, {0u, 5u});
    registerBakedViewCells(baked);
    MultifocalModule other;
    other.setScene(city.scene);
    EXPECT_FALSE(other.bakedCells()) << "another model's cells";

    auto mine = std::make_shared<BakedViewCells>(*baked);
    mine->fingerprint = sceneFingerprint(city.scene);
    registerBakedViewCells(mine);
    MultifocalModule module;
    module.setScene(city.scene);
    ASSERT_TRUE(module.bakedCells());
    ViewRegion inside = regionAround({86, 8, 1.7}, {1, 2, 0.5});
    VisibleSet answer(city.scene.objects.size(), true);
    module.cullRegion(inside, answer);
    EXPECT_EQ(answer.count(), 15u);
    // Reaching out of the cells, the region is computed.
    const ViewRegion outside = regionAround({86, 12, 1.7}, {1, 1, 0.5});
    VisibleSet computed(city.scene.objects.size(), true);
    module.cullRegion(outside, computed);
    MultifocalOptions volume = moduleVolumeOptions();
    volume.nearDistance = outside.maxNearReach;
    volume.minNearDistance = outside.minNearDistance;
    EXPECT_EQ(computed, computeVolumePvs(city.scene, volumeOccluders(city.scene), outside.eyes, volume).objects);
    // A baked view answers from its cell.
    VisibleSet view(city.scene.objects.size(), true);
    module.cull(lookFrom({86, 6, 1.7}, {0, 1, 0}, {0, 0, 1}), view);
    EXPECT_EQ(view, mine->cells.pvs[0]);
}

// Cells handed to the chain by whoever holds the model (a group read from a .pvs) win over the
// process-wide store's cells of the same model; cells of another model are not used.
TEST(MultifocalModule, BakedCellsHandedToTheChainWinOverTheStore)
{
    City city = makeCity();
    addBox(city.scene, {600, 600, 0}, {601, 601, 1}, "elsewhere"); // a model of this test's own
    const std::uint64_t fingerprint = sceneFingerprint(city.scene);
    registerBakedViewCells(twoBakedCells(city.scene, fingerprint, {0u, 5u}));
    const std::shared_ptr<const BakedViewCells> handed = twoBakedCells(city.scene, fingerprint, {20u, 30u});

    auto given = std::make_shared<BakedData>();
    given->set(handed);
    ModuleChain chain;
    chain.add(std::make_unique<MultifocalModule>());
    chain.setBakedData(given);
    chain.setScene(city.scene);
    const auto& module = static_cast<const MultifocalModule&>(chain.module(0));
    EXPECT_EQ(module.bakedCells(), handed);
    VisibleSet view(city.scene.objects.size(), true);
    chain.module(0).cull(lookFrom({86, 6, 1.7}, {0, 1, 0}, {0, 0, 1}), view);
    EXPECT_EQ(view, handed->cells.pvs[0]);

    // Another model's cells handed over: the store's, baked for this one, are used.
    auto other = std::make_shared<BakedData>();
    other->set<BakedViewCells>(twoBakedCells(city.scene, fingerprint ^ 1, {20u, 30u}));
    chain.setBakedData(other);
    chain.setScene(city.scene);
    ASSERT_TRUE(module.bakedCells());
    EXPECT_EQ(module.bakedCells()->cells.pvs[0], findBakedViewCells(fingerprint)->cells.pvs[0]);
}
