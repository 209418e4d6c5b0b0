// SPDX-License-Identifier: MIT
// OcclusionMask: covering, the max-depth pyramid and its hierarchical rectangle test and the
// earlier one kept as the reference (both checked against a brute-force scan of level 0), and the erosion of mask-approx (against brute force).
#include <osgVis/core/mask/OcclusionMask.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using osgVis::core::OcclusionMask;

namespace
{
constexpr float Inf = std::numeric_limits<float>::infinity();

// Every pixel covered at `depth`, except the listed ones.
OcclusionMask filledMask(std::uint32_t width, std::uint32_t height, float depth)
{
    OcclusionMask mask;
    mask.reset(width, height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            mask.cover(x, y, depth);
    return mask;
}

// The definition: pixels floor(x0)..floor(x1) (clipped to the mask) all strictly nearer.
bool bruteRectHidden(const OcclusionMask& mask, double x0, double y0, double x1, double y1, float nearest)
{
    if (!(x0 >= 0.0 && y0 >= 0.0 && x1 <= mask.width() && y1 <= mask.height() && x0 <= x1 && y0 <= y1))
        return false;
    const auto lastX = std::min<std::uint32_t>(std::uint32_t(std::floor(x1)), mask.width() - 1);
    const auto lastY = std::min<std::uint32_t>(std::uint32_t(std::floor(y1)), mask.height() - 1);
    for (std::uint32_t y = std::uint32_t(std::floor(y0)); y <= lastY; ++y)
        for (std::uint32_t x = std::uint32_t(std::floor(x0)); x <= lastX; ++x)
            if (!(mask.depth(x, y) < nearest))
                return false;
    return true;
}

// Mostly covered (so that hidden answers are common), with holes and a spread of depths.
OcclusionMask randomMask(std::mt19937& random, std::uint32_t width, std::uint32_t height, double holeRate)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<float> depth(1.0f, 2.0f);
    OcclusionMask mask;
    mask.reset(width, height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            if (unit(random) >= holeRate)
                mask.cover(x, y, depth(random));
    return mask;
}

// A coordinate in [-0.5, size + 0.5], on a pixel boundary a third of the time.
double randomCoordinate(std::mt19937& random, std::uint32_t size)
{
    std::uniform_real_distribution<double> coordinate(-0.5, size + 0.5);
    const double value = coordinate(random);
    return random() % 3 == 0 ? std::round(value) : value;
}
} // namespace

TEST(OcclusionMask, ResetLeavesEveryPixelUncovered)
{
    OcclusionMask mask;
    mask.reset(5, 3);
    EXPECT_EQ(mask.width(), 5u);
    EXPECT_EQ(mask.height(), 3u);
    EXPECT_EQ(mask.coveredPixels(), 0u);
    EXPECT_EQ(mask.levelCount(), 0u);
    EXPECT_EQ(mask.depth(4, 2), Inf);
}

TEST(OcclusionMask, CoverKeepsTheNearestDepth)
{
    OcclusionMask mask;
    mask.reset(4, 4);
    mask.cover(1, 2, 5.0f);
    mask.cover(1, 2, 7.0f);
    EXPECT_EQ(mask.depth(1, 2), 5.0f);
    mask.cover(1, 2, 3.0f);
    EXPECT_EQ(mask.depth(1, 2), 3.0f);
    mask.cover(2, 2, std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(mask.depth(2, 2), Inf);
    EXPECT_EQ(mask.coveredPixels(), 1u);
    EXPECT_EQ(mask.baseRow(2)[1], 3.0f);
}

TEST(OcclusionMask, PyramidHalvesDownToOneTexel)
{
    OcclusionMask mask = filledMask(5, 3, 1.0f); // 5×3 → 3×2 → 2×1 → 1×1
    mask.buildPyramid();
    EXPECT_EQ(mask.levelCount(), 4u);
    EXPECT_EQ(mask.depth(4, 2), 1.0f);
    mask = filledMask(8, 8, 1.0f); // 8 → 4 → 2 → 1
    mask.buildPyramid();
    EXPECT_EQ(mask.levelCount(), 4u);
    mask = filledMask(1, 1, 1.0f);
    mask.buildPyramid();
    EXPECT_EQ(mask.levelCount(), 1u);
    // Covering again drops the stale pyramid; level 0 still answers.
    mask.cover(0, 0, 0.5f);
    EXPECT_EQ(mask.levelCount(), 0u);
    EXPECT_EQ(mask.depth(0, 0), 0.5f);
    EXPECT_TRUE(mask.rectHidden(0.2, 0.2, 0.8, 0.8, 0.6f));
    EXPECT_FALSE(mask.rectHidden(0.2, 0.2, 0.8, 0.8, 0.5f));
}

TEST(OcclusionMask, RectangleOverlapsFloorX0ToFloorX1)
{
    // 8×8 at depth 1, hole at pixel (4, 1).
    OcclusionMask mask = filledMask(8, 8, 1.0f);
    OcclusionMask holed;
    holed.reset(8, 8);
    for (std::uint32_t y = 0; y < 8; ++y)
        for (std::uint32_t x = 0; x < 8; ++x)
            if (x != 4 || y != 1)
                holed.cover(x, y, 1.0f);
    holed.buildPyramid();
    // x1 = 4.0 lies on the boundary of pixel 4: it still counts (conservative).
    EXPECT_FALSE(holed.rectHidden(2.0, 1.0, 4.0, 1.5, 2.0f));
    EXPECT_TRUE(holed.rectHidden(2.0, 1.0, 3.999, 1.5, 2.0f));
    // x0 = 5.0: pixels 5.. only.
    EXPECT_TRUE(holed.rectHidden(5.0, 0.0, 8.0, 8.0, 2.0f));
    EXPECT_FALSE(holed.rectHidden(4.999, 0.0, 8.0, 8.0, 2.0f));
    // y1 = 1.0 touches row 1; y0 = 2.0 starts at row 2.
    EXPECT_FALSE(holed.rectHidden(4.2, 0.0, 4.8, 1.0, 2.0f));
    EXPECT_TRUE(holed.rectHidden(4.2, 0.0, 4.8, 0.999, 2.0f));
    EXPECT_TRUE(holed.rectHidden(4.2, 2.0, 4.8, 8.0, 2.0f));
    // A point rectangle in the hole.
    EXPECT_FALSE(holed.rectHidden(4.5, 1.5, 4.5, 1.5, 2.0f));

    mask.buildPyramid();
    EXPECT_TRUE(mask.rectHidden(0.0, 0.0, 8.0, 8.0, 2.0f));  // the whole mask, right edge on the border
    EXPECT_FALSE(mask.rectHidden(0.0, 0.0, 8.0, 8.0, 1.0f)); // strictly nearer only
    EXPECT_TRUE(mask.rectHidden(0.0, 0.0, 8.0, 8.0, std::nextafter(1.0f, 2.0f)));
}

TEST(OcclusionMask, RectangleOutsideOrInvalidIsNeverHidden)
{
    OcclusionMask mask = filledMask(8, 8, 1.0f);
    mask.buildPyramid();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(mask.rectHidden(-0.1, 1.0, 3.0, 3.0, 2.0f));
    EXPECT_FALSE(mask.rectHidden(1.0, 1.0, 8.01, 3.0, 2.0f));
    EXPECT_FALSE(mask.rectHidden(1.0, 1.0, 3.0, 8.01, 2.0f));
    EXPECT_FALSE(mask.rectHidden(nan, 1.0, 3.0, 3.0, 2.0f));
    EXPECT_FALSE(mask.rectHidden(1.0, 1.0, 3.0, nan, 2.0f));
    EXPECT_FALSE(mask.rectHidden(1.0, 1.0, 3.0, 3.0, std::numeric_limits<float>::quiet_NaN()));
    EXPECT_FALSE(mask.rectHidden(3.0, 1.0, 1.0, 3.0, 2.0f)); // empty
    EXPECT_TRUE(mask.rectHidden(1.0, 1.0, 3.0, 3.0, Inf));
    OcclusionMask empty;
    empty.reset(0, 0);
    empty.buildPyramid();
    EXPECT_FALSE(empty.rectHidden(0.0, 0.0, 0.0, 0.0, Inf));
}

TEST(OcclusionMask, OddSizesCountMissingChildrenAsUncoveredYetStayExact)
{
    // 5×5 fully covered: the coarse texels over column/row 4 have missing children (+inf), yet
    // a rectangle over the real pixels there is hidden.
    OcclusionMask mask = filledMask(5, 5, 1.0f);
    mask.buildPyramid();
    EXPECT_TRUE(mask.rectHidden(3.5, 3.5, 5.0, 5.0, 2.0f));
    EXPECT_TRUE(mask.rectHidden(0.0, 0.0, 5.0, 5.0, 2.0f));
    EXPECT_TRUE(mask.rectHidden(4.0, 0.0, 5.0, 5.0, 2.0f));
}

TEST(OcclusionMask, HierarchicalTestEqualsBruteForce)
{
    std::mt19937 random(20240517);
    int hidden = 0, visible = 0;
    for (int maskIndex = 0; maskIndex < 300; ++maskIndex)
    {
        const std::uint32_t width = 1 + random() % 70, height = 1 + random() % 70;
        const double holeRate = maskIndex % 3 == 0 ? 0.0 : std::pow(10.0, -1.0 - 2.0 * (maskIndex % 7) / 6.0);
        OcclusionMask mask = randomMask(random, width, height, holeRate);
        mask.buildPyramid();
        std::uniform_real_distribution<float> nearest(0.9f, 2.2f);
        for (int query = 0; query < 100; ++query)
        {
            double x0 = randomCoordinate(random, width), x1 = randomCoordinate(random, width);
            double y0 = randomCoordinate(random, height), y1 = randomCoordinate(random, height);
            if (query % 4 != 0) // mostly ordered; some empty ones too
            {
                if (x0 > x1)
                    std::swap(x0, x1);
                if (y0 > y1)
                    std::swap(y0, y1);
            }
            if (query % 2 == 0) // small rectangles, where the fine levels matter
            {
                x1 = std::min(x1, x0 + std::abs(randomCoordinate(random, 4)));
                y1 = std::min(y1, y0 + std::abs(randomCoordinate(random, 4)));
            }
            const float depth = nearest(random);
            const bool expected = bruteRectHidden(mask, x0, y0, x1, y1, depth);
            ASSERT_EQ(mask.rectHidden(x0, y0, x1, y1, depth), expected)
                << "mask " << maskIndex << " (" << width << "x" << height << ") rect [" << x0 << ", " << x1 << "]x["
                << y0 << ", " << y1 << "] nearest " << depth;
            ASSERT_EQ(mask.rectHiddenReference(x0, y0, x1, y1, depth), expected) << "reference, mask " << maskIndex;
            (expected ? hidden : visible)++;
        }
    }
    // Both answers are common, so the comparison means something.
    EXPECT_GT(hidden, 3000);
    EXPECT_GT(visible, 3000);
}

TEST(OcclusionMask, ShrinkUnionErodesByChebyshevDistanceAndTakesTheMaxDepth)
{
    // 7×5 covered but for (3, 2); Δ = 1 keeps pixels at distance ≥ 2 from the hole and ≥ 1 from
    // the border: x ∈ {1, 5}, y ∈ 1..3.
    OcclusionMask mask;
    mask.reset(7, 5);
    for (std::uint32_t y = 0; y < 5; ++y)
        for (std::uint32_t x = 0; x < 7; ++x)
            if (x != 3 || y != 2)
                mask.cover(x, y, float(1 + x + 10 * y));
    mask.buildPyramid();
    mask.shrinkUnion(1);
    EXPECT_EQ(mask.levelCount(), 0u);
    EXPECT_EQ(mask.coveredPixels(), 6u);
    for (std::uint32_t y = 1; y <= 3; ++y)
    {
        EXPECT_EQ(mask.depth(1, y), float(1 + 2 + 10 * (y + 1))) << y; // the neighbourhood's max
        EXPECT_EQ(mask.depth(5, y), float(1 + 6 + 10 * (y + 1))) << y;
    }
}

TEST(OcclusionMask, ShrinkUnionEqualsBruteForceErosion)
{
    std::mt19937 random(77);
    for (int maskIndex = 0; maskIndex < 120; ++maskIndex)
    {
        const std::uint32_t width = 1 + random() % 40, height = 1 + random() % 40;
        const OcclusionMask original = randomMask(random, width, height, 0.01 * (maskIndex % 5));
        const std::uint32_t radius = random() % 5;
        OcclusionMask eroded = original;
        eroded.shrinkUnion(radius);
        const int r = int(radius);
        for (int y = 0; y < int(height); ++y)
            for (int x = 0; x < int(width); ++x)
            {
                float expected = -Inf;
                for (int ny = y - r; ny <= y + r; ++ny)
                    for (int nx = x - r; nx <= x + r; ++nx)
                    {
                        const bool inside = nx >= 0 && ny >= 0 && nx < int(width) && ny < int(height);
                        expected = std::max(expected, inside ? original.depth(nx, ny) : Inf);
                    }
                ASSERT_EQ(eroded.depth(x, y), expected) << maskIndex << " at " << x << "," << y << " r " << r;
            }
    }
}
