// SPDX-License-Identifier: MIT
#include <osgVis/core/geometry/ConvexPolygon.h>

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace osgVis::core;

namespace
{
//  (0,2) +-----+ (2,2)
//        |     |
//  (0,0) +-----+ (2,0)      counter-clockwise seen from +z
ConvexPolygon square2()
{
    return ConvexPolygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}});
}

// Keeps x >= 1.
const Plane keepXAtLeast1({1, 0, 0}, -1);
} // namespace

TEST(ConvexPolygon, AreaNormalCentroidAndPlane)
{
    const ConvexPolygon p = square2();
    EXPECT_EQ(p.newellNormal(), Vec3(0, 0, 8));
    EXPECT_DOUBLE_EQ(p.area(), 4.0);
    EXPECT_EQ(p.centroid(), Vec3(1, 1, 0));
    Plane plane;
    ASSERT_TRUE(p.plane(plane));
    EXPECT_EQ(plane.normal, Vec3(0, 0, 1));
    EXPECT_DOUBLE_EQ(plane.d, 0.0);

    const ConvexPolygon triangle({{0, 0, 5}, {4, 0, 5}, {0, 3, 5}});
    EXPECT_DOUBLE_EQ(triangle.area(), 6.0);
    EXPECT_NEAR(triangle.centroid().x, 4.0 / 3.0, 1e-15);
    EXPECT_NEAR(triangle.centroid().y, 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(triangle.centroid().z, 5.0);

    Plane none;
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).plane(none));
}

TEST(ConvexPolygon, ClipKeepsPositiveSideExactly)
{
    const ConvexPolygon clipped = square2().clipped(keepXAtLeast1);
    const std::vector<Vec3> expected{{1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}};
    EXPECT_EQ(clipped.vertices(), expected);
    EXPECT_DOUBLE_EQ(clipped.area(), 2.0);
}

TEST(ConvexPolygon, ClipTriangleCornerBecomesQuad)
{
    // Cutting one corner off a triangle gives a quadrilateral.
    const ConvexPolygon triangle({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}});
    const ConvexPolygon clipped = triangle.clipped(Plane({-1, 0, 0}, 2)); // keeps x <= 2
    const std::vector<Vec3> expected{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 4, 0}};
    EXPECT_EQ(clipped.vertices(), expected);
}

TEST(ConvexPolygon, ClipAllInsideOrOutside)
{
    EXPECT_EQ(square2().clipped(Plane({1, 0, 0}, 5)).vertices(), square2().vertices());
    EXPECT_TRUE(square2().clipped(Plane({1, 0, 0}, -5)).empty());
}

TEST(ConvexPolygon, ClipThroughVertexAddsNoDuplicate)
{
    // The plane x + y = 2 passes through (2,0) and (0,2); keep the side with the origin.
    const ConvexPolygon clipped = square2().clipped(Plane({-1, -1, 0}, 2));
    const std::vector<Vec3> expected{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    EXPECT_EQ(clipped.vertices(), expected);
}

TEST(ConvexPolygon, ClipTouchingOnlyAVertexOrEdgeIsEmpty)
{
    const ConvexPolygon triangle({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}});
    EXPECT_TRUE(triangle.clipped(Plane({-1, 0, 0}, 0)).empty()); // keeps x <= 0: only an edge
    EXPECT_TRUE(triangle.clipped(Plane({1, 0, 0}, -2)).empty()); // keeps x >= 2: only a vertex
}

TEST(ConvexPolygon, AcceptsGoodOccluders)
{
    EXPECT_TRUE(square2().isValidOccluder());
    EXPECT_TRUE(ConvexPolygon({{0, 2, 0}, {2, 2, 0}, {2, 0, 0}, {0, 0, 0}}).isValidOccluder()); // clockwise
    // A repeated vertex does not spoil an otherwise good square.
    EXPECT_TRUE(ConvexPolygon({{0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}).isValidOccluder());
    // Collinear vertex along an edge.
    EXPECT_TRUE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}).isValidOccluder());
    // Far from the origin: the test is relative, not absolute.
    EXPECT_TRUE(ConvexPolygon({{1e6, 1e6, 5}, {1e6 + 3, 1e6, 5}, {1e6 + 3, 1e6 + 3, 5}}).isValidOccluder());
}

TEST(ConvexPolygon, RejectsDegenerateOccluders)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(ConvexPolygon().isValidOccluder());
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}}).isValidOccluder());
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {2, 0, 0}, {nan, 2, 0}}).isValidOccluder());
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {2, 0, 0}, {inf, 2, 0}}).isValidOccluder());
    // Repeated vertices leaving fewer than three distinct ones.
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}}).isValidOccluder());
    EXPECT_FALSE(ConvexPolygon({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}).isValidOccluder());
    // Zero area (collinear) and tiny area.
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).isValidOccluder());
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1e-5, 0, 0}, {1e-5, 1e-5, 0}, {0, 1e-5, 0}}).isValidOccluder());
    // Sliver: large area in absolute terms, but a thousand units long and a ten-millionth wide.
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1000, 0, 0}, {1000, 1e-7, 0}}).isValidOccluder());
    // Non-planar quad: one corner lifted by a tenth of the side.
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}}).isValidOccluder());
    // Non-convex dart: (1,1) is a reflex vertex.
    EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {2, 1, 0}, {0, 2, 0}, {1, 1, 0}}).isValidOccluder());
    // Pentagram: every turn goes the same way but the outline winds twice.
    std::vector<Vec3> star;
    for (int i = 0; i < 5; ++i)
    {
        const double a = 2.0 * 3.14159265358979323846 * (2 * i % 5) / 5.0;
        star.push_back({std::cos(a), std::sin(a), 0.0});
    }
    EXPECT_FALSE(ConvexPolygon(star).isValidOccluder());
}
