// SPDX-License-Identifier: MIT
// The walks osgvisbench derives from a scene's walk: evenly subsampled keys, six cube faces per key
// covering every direction, and faster observers (every S-th key, bouncing at the walk's ends).
#include "../../apps/osgvisbench/DerivedWalks.h"

#include <osgVis/core/geometry/Frustum.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace osgVis;

namespace
{
// Keys 0..n-1 with eye (i, 0, 0), looking +y, at 10 keys per second.
core::Walk straightWalk(std::size_t n)
{
    core::Walk walk;
    walk.width = 320;
    walk.height = 200;
    for (std::size_t i = 0; i < n; ++i)
    {
        core::WalkKey key;
        key.time = 0.1 * double(i);
        key.eye = core::Vec3(double(i), 0.0, 0.0);
        key.center = key.eye + core::Vec3(0.0, 1.0, 0.0);
        walk.keys.push_back(key);
    }
    return walk;
}

std::vector<double> eyeXs(const core::Walk& walk)
{
    std::vector<double> xs;
    for (const core::WalkKey& key : walk.keys)
        xs.push_back(key.eye.x);
    return xs;
}

core::Vec3 direction(const core::WalkKey& key)
{
    return glm::normalize(key.center - key.eye);
}
} // namespace

TEST(DerivedWalks, SubsamplingKeepsFirstAndLast)
{
    EXPECT_EQ(eyeXs(bench::subsampledWalk(straightWalk(10), 4)), (std::vector<double>{0, 3, 6, 9}));
    EXPECT_EQ(bench::subsampledWalk(straightWalk(10), 0).keys.size(), 10u);
    EXPECT_EQ(bench::subsampledWalk(straightWalk(10), 50).keys.size(), 10u);
}

TEST(DerivedWalks, CubeFacesLookAlongTheKeysOwnAxes)
{
    core::Walk walk = straightWalk(1);
    walk.keys[0].eye = core::Vec3(1, 2, 3);
    walk.keys[0].center = core::Vec3(1, 3, 3); // forward +y, up +z: right is +x
    const core::Walk cube = bench::cubeFaceWalk(walk);
    ASSERT_EQ(cube.keys.size(), 6u);
    EXPECT_EQ(cube.width, 200u);
    EXPECT_EQ(cube.height, 200u);
    EXPECT_EQ(cube.projection.kind, core::WalkProjection::Kind::Perspective);
    EXPECT_EQ(cube.projection.fovY, 90.0);
    const core::Vec3 expected[6] = {{0, 1, 0}, {0, -1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int face = 0; face < 6; ++face)
    {
        EXPECT_LT(glm::length(direction(cube.keys[face]) - expected[face]), 1e-12) << "face " << face;
        EXPECT_EQ(cube.keys[face].eye, core::Vec3(1, 2, 3));
        EXPECT_EQ(cube.keys[face].time, 0.0);
    }
}

TEST(DerivedWalks, CubeFacesCoverEveryDirection)
{
    core::Walk walk = straightWalk(1);
    walk.keys[0].center = core::Vec3(0.3, 1.0, 0.2); // a tilted frame
    walk.keys[0].up = core::Vec3(0.1, 0.0, 1.0);
    const core::Walk cube = bench::cubeFaceWalk(walk);
    const core::Mat4 projection = cube.projection.matrix(cube.aspect());
    std::vector<core::Frustum> faces;
    for (const core::WalkKey& key : cube.keys)
        faces.push_back(core::Frustum::fromMatrix(projection * key.viewMatrix()));

    // Points on a sphere around the eye, by latitude and longitude.
    for (int latitude = -90; latitude <= 90; latitude += 10)
        for (int longitude = 0; longitude < 360; longitude += 10)
        {
            const double phi = glm::radians(double(latitude)), theta = glm::radians(double(longitude));
            const core::Vec3 point =
                walk.keys[0].eye +
                5.0 * core::Vec3(std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), std::sin(phi));
            const core::Aabb box(point - core::Vec3(1e-3), point + core::Vec3(1e-3));
            int seenBy = 0;
            for (const core::Frustum& face : faces)
                seenBy += face.classify(box) != core::Containment::Outside;
            EXPECT_GE(seenBy, 1) << "latitude " << latitude << " longitude " << longitude;
        }
}

TEST(DerivedWalks, FasterObserverSkipsKeysAndBouncesAtTheEnds)
{
    const core::Walk walk = straightWalk(10);
    EXPECT_EQ(eyeXs(bench::pacedWalk(walk, 1)), eyeXs(walk));
    // One pass at 4x has 3 frames (0, 4, 8); ten keys ask for 10 frames, so it walks back.
    const core::Walk fast = bench::pacedWalk(walk, 4);
    EXPECT_EQ(eyeXs(fast), (std::vector<double>{0, 4, 8, 6, 2, 2, 6, 8, 4, 0}));
    for (std::size_t frame = 0; frame < fast.keys.size(); ++frame)
        EXPECT_DOUBLE_EQ(fast.keys[frame].time, 0.1 * double(frame)) << "the frame rate is kept";

    const core::Walk longWalk = straightWalk(100);
    EXPECT_EQ(bench::pacedWalk(longWalk, 2).keys.size(), 50u) << "one pass when it has 30 frames or more";
    const core::Walk sixteen = bench::pacedWalk(longWalk, 16);
    ASSERT_EQ(sixteen.keys.size(), 30u);
    EXPECT_NEAR(sixteen.keys[29].time, 2.9, 1e-12) << "times continue past the walk's end";
}
