// SPDX-License-Identifier: MIT
// 2-D convex regions: half-plane clipping, erosion and the difference of pieces and a region, which
// the multifocal coverage maps rest on (a pixel counts as covered only when nothing of it is left).
#include <osgVis/core/geometry/ConvexArea2.h>

#include <gtest/gtest.h>

using namespace osgVis::core;

namespace
{
ConvexArea2 rectangle(double x0, double y0, double x1, double y1)
{
    return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

double totalArea(const std::vector<ConvexArea2>& pieces)
{
    double sum = 0.0;
    for (const ConvexArea2& p : pieces)
        sum += signedArea(p);
    return sum;
}

std::vector<HalfPlane2> edges(const ConvexArea2& area, double erosion = 0.0)
{
    std::vector<HalfPlane2> out;
    halfPlanesOf(area, erosion, out);
    return out;
}
} // namespace

TEST(ConvexArea2, ClockwiseOutlinesAreReversedAndDegenerateOnesEmptied)
{
    ConvexArea2 clockwise{Vec2(0, 0), Vec2(0, 1), Vec2(1, 1), Vec2(1, 0)};
    makeCounterClockwise(clockwise);
    ASSERT_EQ(clockwise.size(), 4u);
    EXPECT_DOUBLE_EQ(signedArea(clockwise), 1.0);
    ConvexArea2 line{Vec2(0, 0), Vec2(1, 1), Vec2(2, 2)};
    makeCounterClockwise(line);
    EXPECT_TRUE(line.empty());
}

TEST(ConvexArea2, ErodedHalfPlanesLieInsideTheRegion)
{
    const ConvexArea2 square = rectangle(0, 0, 2, 2);
    ConvexArea2 eroded = square, next;
    for (const HalfPlane2& h : edges(square, 0.25))
    {
        clipInside(eroded, h, next);
        eroded.swap(next);
    }
    EXPECT_NEAR(signedArea(eroded), 1.5 * 1.5, 1e-12);
    for (const Vec2& p : eroded)
    {
        EXPECT_GE(p.x, 0.25 - 1e-12);
        EXPECT_LE(p.x, 1.75 + 1e-12);
    }
}

TEST(ConvexArea2, SubtractingTwoOverlappingHalvesLeavesNothing)
{
    std::vector<ConvexArea2> pieces{rectangle(0, 0, 1, 1)};
    ASSERT_TRUE(subtractConvex(pieces, edges(rectangle(-1, -1, 0.6, 2)), 16));
    EXPECT_NEAR(totalArea(pieces), 0.4, 1e-12);
    ASSERT_TRUE(subtractConvex(pieces, edges(rectangle(0.5, -1, 2, 2)), 16));
    EXPECT_TRUE(pieces.empty());
}

TEST(ConvexArea2, AHoleLeavesTheRingAndAGapLeavesTheStrip)
{
    std::vector<ConvexArea2> pieces{rectangle(0, 0, 1, 1)};
    ASSERT_TRUE(subtractConvex(pieces, edges(rectangle(0.25, 0.25, 0.75, 0.75)), 16));
    EXPECT_NEAR(totalArea(pieces), 0.75, 1e-12);
    // Two halves that leave a strip 1e-9 wide: the strip stays, so the square is not covered.
    pieces.assign(1, rectangle(0, 0, 1, 1));
    ASSERT_TRUE(subtractConvex(pieces, edges(rectangle(-1, -1, 0.5, 2)), 16));
    ASSERT_TRUE(subtractConvex(pieces, edges(rectangle(0.5 + 1e-9, -1, 2, 2)), 16));
    ASSERT_FALSE(pieces.empty());
    EXPECT_NEAR(totalArea(pieces), 1e-9, 1e-12);
}

TEST(ConvexArea2, TooManyPiecesLeavesThePiecesAsTheyWere)
{
    std::vector<ConvexArea2> pieces{rectangle(0, 0, 1, 1)};
    EXPECT_FALSE(subtractConvex(pieces, edges(rectangle(0.25, 0.25, 0.75, 0.75)), 2));
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_DOUBLE_EQ(signedArea(pieces[0]), 1.0);
}
