// SPDX-License-Identifier: MIT
// The automatic walk through a model's free space: eyes at a person's height inside the room, none
// inside solid geometry or under a low ceiling, looking along free directions; and the definition
// of "inside solid geometry" it rests on, checked by brute force with random rays (no shared code).
//
//   side view of the room (10 x 10 x 3, faces turned inwards) with a closed crate (2 x 2 x 1,
//   faces turned outwards) on the floor:
//      +--------------------------+ z = 3
//      |                          |
//      |        +----+            |
//      |        |crate            |
//      +--------+----+------------+ z = 0
#include "BruteForceRays.h"

#include <FreeSpaceWalk.h>
#include <RayScene.h>

#include <gtest/gtest.h>


using namespace osgVis;

namespace
{
// Two counter-clockwise triangles of the quad a b c d (front seen with a b c d counter-clockwise).
void addQuad(core::Scene& scene, core::Vec3 a, core::Vec3 b, core::Vec3 c, core::Vec3 d)
{
    scene.triangles.push_back({core::Vec3f(a), core::Vec3f(b), core::Vec3f(c)});
    scene.triangles.push_back({core::Vec3f(a), core::Vec3f(c), core::Vec3f(d)});
}

// A closed box; `inwards` turns its faces to the inside (a room), else outwards (a solid crate).
void addBox(core::Scene& scene, core::Vec3 lo, core::Vec3 hi, bool inwards)
{
    const core::Vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                             {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {3, 0, 4, 7}};
    const std::uint32_t first = std::uint32_t(scene.triangles.size());
    for (const auto& f : faces)
        if (inwards)
            addQuad(scene, p[f[3]], p[f[2]], p[f[1]], p[f[0]]);
        else
            addQuad(scene, p[f[0]], p[f[1]], p[f[2]], p[f[3]]);
    const core::ObjectId id = scene.addObject(core::Aabb(lo, hi), 12);
    scene.objects[id].firstTriangle = first;
}

core::Scene roomWithCrate()
{
    core::Scene scene;
    addBox(scene, core::Vec3(0, 0, 0), core::Vec3(10, 10, 3), true);
    addBox(scene, core::Vec3(4, 4, 0), core::Vec3(6, 6, 1), false);
    return scene;
}

} // namespace

TEST(FreeSpaceWalk, InsideSolidMeansMostRaysMeetABackFace)
{
    const core::Scene scene = roomWithCrate();
    const apps::RayScene rays(scene);
    EXPECT_TRUE(apps::insideSolid(rays, core::Vec3(5, 5, 0.5))) << "inside the crate";
    EXPECT_FALSE(apps::insideSolid(rays, core::Vec3(5, 5, 5))) << "above the room: half the rays meet nothing";
    EXPECT_FALSE(apps::insideSolid(rays, core::Vec3(2, 2, 1.5))) << "in the room";
    const apps::RayHit down = rays.nearest(core::Vec3(2, 2, 1.5), core::Vec3(0, 0, -1));
    EXPECT_NEAR(down.distance, 1.5, 1e-5);
    EXPECT_FALSE(down.backFace);
    const apps::RayHit intoCrate = rays.nearest(core::Vec3(5, 5, 0.5), core::Vec3(1, 0, 0));
    EXPECT_NEAR(intoCrate.distance, 1.0, 1e-5);
    EXPECT_TRUE(intoCrate.backFace);
}

TEST(FreeSpaceWalk, EyesStandInTheRoomAtAPersonsHeightAndLookAlongFreeDirections)
{
    const core::Scene scene = roomWithCrate();
    const apps::RayScene rays(scene);
    apps::FreeSpaceWalkReport report;
    apps::FreeSpaceWalkOptions options;
    options.stations = 12;
    const core::Walk walk = apps::makeFreeSpaceWalk(rays, options, &report);
    EXPECT_EQ(report.stations, 12u);
    EXPECT_GE(walk.keys.size(), 12u) << "at least the freest direction of every eye";
    EXPECT_LE(walk.keys.size(), 12u * options.gazesPerStation);
    EXPECT_NEAR(report.eyeHeight, 0.55 * 3.0, 0.01) << report.eyeHeightRule << ": the median ceiling is the room's 3 m "
                                                        "(the crate's top has 2 m above it)";
    EXPECT_GT(report.lowCeiling, 0u) << "floor points on the crate's top have 2 m above them, less than 1.25 x 1.65";
    std::mt19937 random(7);
    for (const core::WalkKey& key : walk.keys)
    {
        EXPECT_NEAR(key.eye.z, report.eyeHeight, 1e-3);
        EXPECT_GT(key.eye.x, 0.0);
        EXPECT_LT(key.eye.x, 10.0);
        EXPECT_GT(key.eye.y, 0.0);
        EXPECT_LT(key.eye.y, 10.0);
        EXPECT_FALSE(key.eye.x > 4 && key.eye.x < 6 && key.eye.y > 4 && key.eye.y < 6) << "on the crate";
        EXPECT_FALSE(test::insideByBruteForce(scene, key.eye, random));
        const core::Vec3 gaze = key.center - key.eye;
        EXPECT_NEAR(gaze.z, 0.0, 1e-9) << "horizontal gaze";
        EXPECT_GE(rays.nearest(key.eye, gaze).distance, report.eyeHeight) << "an eye height free ahead at least";
        for (int d = 0; d < 16; ++d)
            EXPECT_GE(rays.nearest(key.eye, core::Vec3(std::cos(d * 0.3927), std::sin(d * 0.3927), 0)).distance,
                      0.25 * report.eyeHeight - 1e-6)
                << "not against a wall";
    }
    EXPECT_GT(walk.projection.zFar, glm::length(scene.bounds().extent()));
    EXPECT_LT(walk.projection.zNear, 0.2);
}

TEST(FreeSpaceWalk, AModelWithNowhereToStandIsAnError)
{
    core::Scene scene;
    // A vertical wall only: no upward-facing triangle.
    addQuad(scene, core::Vec3(0, 0, 0), core::Vec3(1, 0, 0), core::Vec3(1, 0, 1), core::Vec3(0, 0, 1));
    scene.addObject(core::Aabb(core::Vec3(0, 0, 0), core::Vec3(1, 0.01, 1)), 2);
    const apps::RayScene rays(scene);
    try
    {
        apps::makeFreeSpaceWalk(rays);
        FAIL() << "expected FreeSpaceWalkError";
    }
    catch (const apps::FreeSpaceWalkError& e)
    {
        EXPECT_NE(std::string(e.what()).find("no upward-facing surface"), std::string::npos) << e.what();
    }
    EXPECT_THROW(apps::RayScene(core::Scene{}), std::runtime_error);
}
