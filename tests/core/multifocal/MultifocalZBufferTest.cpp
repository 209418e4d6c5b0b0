// SPDX-License-Identifier: MIT
// The multifocal z-buffer of one plane (src/multifocal/MultifocalZBuffer.h): what an umbra hides,
// what it must not (beside it, in front of it, through a slit narrower than a pixel), and the
// coverage maps that let overlapping umbrae hide together what neither covers alone.
#include "multifocal/MultifocalZBuffer.h"

#include <gtest/gtest.h>

using namespace osgVis::core;

namespace
{
const Aabb Volume(Vec3(-0.5), Vec3(0.5));

// A wall in the plane x = `x` over y in [y0, y1], z in [-10, 10], normal towards V.
std::vector<Vec3> wall(double x, double y0, double y1)
{
    return {Vec3(x, y0, -10), Vec3(x, y0, 10), Vec3(x, y1, 10), Vec3(x, y1, -10)};
}

const Plane WallPlane(Vec3(-1, 0, 0), 4.0); // x = 4

// The plane x = 5 (4.5 beyond V's +x face), its window [-8.5, 8.5]² in (y, z): pixel edges fall at
// known places (for 16 pixels: at half-integers, so y = 0 is a pixel's middle).
MultifocalZBuffer bufferFor(int resolution)
{
    CorrespondencePlane plane;
    plane.axis = 0;
    plane.direction = 1;
    plane.position = 5.0;
    plane.u = 1;
    plane.v = 2;
    plane.origin = Vec2(-8.5);
    plane.pixel = 17.0 / resolution;
    plane.width = plane.height = resolution;
    MultifocalZBuffer buffer;
    buffer.reset(plane, Volume, 1e-9);
    return buffer;
}

bool boxHidden(MultifocalZBuffer& buffer, const Aabb& box)
{
    const auto corners = boxCorners(box);
    return buffer.hidden(corners.data(), corners.size());
}
} // namespace

TEST(MultifocalZBuffer, AWallHidesWhatIsBehindItButNotBesideOrBeforeIt)
{
    MultifocalZBuffer buffer = bufferFor(64);
    ASSERT_TRUE(buffer.insert(wall(4, -10, 10), WallPlane));
    EXPECT_TRUE(boxHidden(buffer, Aabb(Vec3(8, -1, -1), Vec3(9, 1, 1))));
    EXPECT_TRUE(boxHidden(buffer, Aabb(Vec3(4.5, -1, -1), Vec3(5, 1, 1)))); // behind P's near side too
    EXPECT_FALSE(boxHidden(buffer, Aabb(Vec3(2, -1, -1), Vec3(3, 1, 1))));  // before the wall
}

TEST(MultifocalZBuffer, ANarrowWallHidesOnlyItsUmbra)
{
    MultifocalZBuffer buffer = bufferFor(64);
    // A wall 2 wide at x = 4 seen from a volume 1 wide: a box behind its middle is hidden from
    // every eye; one at y in [1.5, 2.5] is seen past its end from (-0.5, 0.5, z).
    ASSERT_TRUE(buffer.insert(wall(4, -1, 1), WallPlane));
    EXPECT_TRUE(boxHidden(buffer, Aabb(Vec3(8, -0.2, -1), Vec3(8.5, 0.2, 1))));
    EXPECT_FALSE(boxHidden(buffer, Aabb(Vec3(8, 1.5, -1), Vec3(8.5, 2.5, 1))));
}

TEST(MultifocalZBuffer, ASlitNarrowerThanAPixelKeepsWhatIsBehindIt)
{
    MultifocalZBuffer buffer = bufferFor(17); // pixels 1 unit wide
    ASSERT_TRUE(buffer.insert(wall(4, -10, -0.005), WallPlane));
    ASSERT_TRUE(buffer.insert(wall(4, 0.005, 10), WallPlane));
    EXPECT_FALSE(boxHidden(buffer, Aabb(Vec3(8, -0.1, -0.1), Vec3(8.2, 0.1, 0.1))));
}

TEST(MultifocalZBuffer, OverlappingUmbraeHideTogetherOnlyWithCoverageMaps)
{
    // Walls y <= 0.2 and y >= -0.2 at x = 4 overlap; their umbrae on P overlap in |y| < 0.07, inside
    // the pixel y in [-0.5, 0.5], which neither covers whole: only the coverage map, which takes the
    // two pieces together, finds that pixel covered.
    for (const std::size_t fragments : {std::size_t(8), std::size_t(0)})
    {
        SCOPED_TRACE(fragments);
        MultifocalZBuffer buffer = bufferFor(17);
        buffer.maxFragmentsPerPixel = fragments;
        ASSERT_TRUE(buffer.insert(wall(4, -10, 0.2), WallPlane));
        ASSERT_TRUE(buffer.insert(wall(4, -0.2, 10), WallPlane));
        EXPECT_EQ(boxHidden(buffer, Aabb(Vec3(8, -0.01, -0.01), Vec3(8.05, 0.01, 0.01))), fragments > 0);
    }
}

TEST(MultifocalZBuffer, ADeeperOccluderHidesLessThanANearerOne)
{
    // The wall at x = 6 hides a box at x in [5, 5.5] behind the wall at x = 4 but not itself.
    MultifocalZBuffer buffer = bufferFor(64);
    ASSERT_TRUE(buffer.insert(wall(6, -10, 10), Plane(Vec3(-1, 0, 0), 6.0)));
    EXPECT_FALSE(boxHidden(buffer, Aabb(Vec3(5, -1, -1), Vec3(5.5, 1, 1))));
    EXPECT_TRUE(boxHidden(buffer, Aabb(Vec3(7, -1, -1), Vec3(7.5, 1, 1))));
    ASSERT_TRUE(buffer.insert(wall(4, -10, 10), WallPlane));
    EXPECT_TRUE(boxHidden(buffer, Aabb(Vec3(5, -1, -1), Vec3(5.5, 1, 1))));
}

TEST(MultifocalZBuffer, NothingAtOrBehindTheVolumesFaceIsTestable)
{
    MultifocalZBuffer buffer = bufferFor(64);
    ASSERT_TRUE(buffer.insert(wall(4, -10, 10), WallPlane));
    EXPECT_FALSE(boxHidden(buffer, Aabb(Vec3(0.4, -1, -1), Vec3(9, 1, 1)))); // reaches into V's slab
    // An occluder reaching V's slab is refused.
    EXPECT_FALSE(buffer.insert(wall(0.5, -10, 10), Plane(Vec3(-1, 0, 0), 0.5)));
}
