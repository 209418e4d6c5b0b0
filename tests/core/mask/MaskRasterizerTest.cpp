// SPDX-License-Identifier: MIT
// Conservative group rasterization: exact pixel sets worked out by hand, depths (max over the
// pixel, +inf at the horizon), and the key randomized property: every point of every covered
// pixel (grown by the shrink) lies inside the occluder, nearer than the stored depth, for the tile
// rasterizer and the reference. Also checks that the reference's SSE2 and scalar inner loops agree
// bit for bit (internal src/MaskRasterPaths.h). The tile rasterizer against the reference:
// MaskTileRasterizerTest.cpp.
#include "RandomOccluderGroups.h"
#include "mask/MaskRasterPaths.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using namespace osgVis::core;
using namespace maskTest;

namespace
{
using Pixel = std::pair<int, int>; // (x, y)
using PixelSet = std::vector<Pixel>;
constexpr double Inf = std::numeric_limits<double>::infinity();

DepthPlane constantDepth(double depth)
{
    DepthPlane plane;
    plane.c = 1.0 / depth;
    return plane;
}

ScreenPolygon polygon(std::vector<glm::dvec2> vertices, std::vector<bool> shared = {},
                      DepthPlane depth = constantDepth(10.0))
{
    ScreenPolygon result;
    result.vertices = std::move(vertices);
    result.sharedEdge = shared.empty() ? std::vector<bool>(result.vertices.size(), false) : std::move(shared);
    result.depth = depth;
    return result;
}

ScreenPolygon rectangle(double x0, double y0, double x1, double y1, DepthPlane depth = constantDepth(10.0))
{
    return polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}, depth);
}

PixelSet coveredPixels(const OcclusionMask& mask)
{
    PixelSet pixels;
    for (std::uint32_t y = 0; y < mask.height(); ++y)
        for (std::uint32_t x = 0; x < mask.width(); ++x)
            if (mask.depth(x, y) < std::numeric_limits<float>::infinity())
                pixels.emplace_back(int(x), int(y));
    std::sort(pixels.begin(), pixels.end());
    return pixels;
}

PixelSet block(int x0, int x1, int y0, int y1)
{
    PixelSet pixels;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            pixels.emplace_back(x, y);
    std::sort(pixels.begin(), pixels.end());
    return pixels;
}

PixelSet unite(PixelSet a, const PixelSet& b)
{
    a.insert(a.end(), b.begin(), b.end());
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    return a;
}

using GroupRasterizer = std::size_t (*)(OcclusionMask&, const ScreenPolygon*, std::size_t, double, MaskRasterScratch&);

std::size_t referenceRasterizer(OcclusionMask& mask, const ScreenPolygon* polygons, std::size_t count, double shrink,
                                MaskRasterScratch& scratch)
{
    return rasterizeOccluderGroupReference(MaskRasterPath::Simd, mask, polygons, count, shrink, scratch);
}

// Rasterizes one group into a fresh mask and returns the covered pixels.
PixelSet rasterize(std::uint32_t width, std::uint32_t height, const std::vector<ScreenPolygon>& group,
                   double shrink = 0.0, std::size_t* coveredCount = nullptr, OcclusionMask* out = nullptr,
                   GroupRasterizer rasterizer = rasterizeOccluderGroup)
{
    OcclusionMask mask;
    mask.reset(width, height);
    MaskRasterScratch scratch;
    const std::size_t covered = rasterizer(mask, group.data(), group.size(), shrink, scratch);
    if (coveredCount)
        *coveredCount = covered;
    if (out)
        *out = mask;
    return coveredPixels(mask);
}

// The right triangle (1,1) (9,1) (1,9): pixel (x, y) lies inside iff (x-1) + (y-1) ≤ 6 — 28 pixels.
PixelSet rightTriangleInterior()
{
    PixelSet pixels;
    for (int y = 1; y <= 7; ++y)
        for (int x = 1; x + y <= 8; ++x)
            pixels.emplace_back(x, y);
    std::sort(pixels.begin(), pixels.end());
    return pixels;
}
} // namespace

TEST(MaskRasterizer, AxisAlignedRectangleCoversExactlyTheInnerPixels)
{
    std::size_t count = 0;
    EXPECT_EQ(rasterize(10, 6, {rectangle(2.0, 1.0, 6.0, 3.0)}, 0.0, &count), block(2, 5, 1, 2));
    EXPECT_EQ(count, 8u);
    // Column 2 is no longer wholly inside.
    EXPECT_EQ(rasterize(10, 6, {rectangle(2.1, 1.0, 6.0, 3.0)}), block(3, 5, 1, 2));
    // Clockwise winding: the same pixels.
    EXPECT_EQ(rasterize(10, 6, {polygon({{2.0, 1.0}, {2.0, 3.0}, {6.0, 3.0}, {6.0, 1.0}})}), block(2, 5, 1, 2));
    // Partly off the mask: the on-mask pixels inside.
    EXPECT_EQ(rasterize(10, 6, {rectangle(-5.0, -5.0, 3.0, 2.0)}), block(0, 2, 0, 1));
}

TEST(MaskRasterizer, ShrinkGrowsEveryPixelSquare)
{
    // Shrink 1: [x-1, x+2] ⊂ [2, 6] → x 3..4; [y-1, y+2] ⊂ [1, 3] → no row.
    std::size_t count = 1;
    EXPECT_EQ(rasterize(10, 6, {rectangle(2.0, 1.0, 6.0, 3.0)}, 1.0, &count), PixelSet{});
    EXPECT_EQ(count, 0u);
    // Taller ones keep rows y ≥ 2 with y + 2 ≤ top: row 2 under y = 4, rows 2..3 under y = 5.
    EXPECT_EQ(rasterize(10, 8, {rectangle(2.0, 1.0, 6.0, 4.0)}, 1.0), block(3, 4, 2, 2));
    EXPECT_EQ(rasterize(10, 8, {rectangle(2.0, 1.0, 6.0, 5.0)}, 1.0), block(3, 4, 2, 3));
    // Shrink 0.5: x ≥ 2.5 and x + 1.5 ≤ 6 → 3..4; y ≥ 1.5 and y + 1.5 ≤ 5 → 2..3.
    EXPECT_EQ(rasterize(10, 8, {rectangle(2.0, 1.0, 6.0, 5.0)}, 0.5), block(3, 4, 2, 3));
}

TEST(MaskRasterizer, TriangleCoversThePixelsInsideItsHypotenuse)
{
    EXPECT_EQ(rasterize(12, 12, {polygon({{1.0, 1.0}, {9.0, 1.0}, {1.0, 9.0}})}), rightTriangleInterior());
    EXPECT_EQ(rasterize(12, 12, {polygon({{1.0, 9.0}, {9.0, 1.0}, {1.0, 1.0}})}), rightTriangleInterior());
}

TEST(MaskRasterizer, SharedEdgeLetsPixelsStraddleIt)
{
    //   y=3 +-------+-----+
    //       |  L    |  R  |     split at x = 4.5: pixel 4 straddles it
    //   y=1 +-------+-----+
    //      x=2    4.5     6
    // Left: edges bottom, shared right, top, left. Right: bottom, right, top, shared left.
    const ScreenPolygon left = polygon({{2.0, 1.0}, {4.5, 1.0}, {4.5, 3.0}, {2.0, 3.0}}, {false, true, false, false});
    const ScreenPolygon right = polygon({{4.5, 1.0}, {6.0, 1.0}, {6.0, 3.0}, {4.5, 3.0}}, {false, false, false, true});
    EXPECT_EQ(rasterize(10, 6, {left, right}), block(2, 5, 1, 2));

    // Not marked shared: each polygon alone vouches for its own pixels only, leaving a crack.
    const ScreenPolygon leftOutline = polygon(left.vertices);
    const ScreenPolygon rightOutline = polygon(right.vertices);
    EXPECT_EQ(rasterize(10, 6, {leftOutline, rightOutline}), unite(block(2, 3, 1, 2), block(5, 5, 1, 2)));
}

TEST(MaskRasterizer, ThinSlitBetweenOccludersStaysOpen)
{
    // [2, 4.6] and [4.8, 7]: pixel 4's centre (4.5) is covered, pixel 5 wholly, yet the 0.2 px slit
    // crosses pixel 4, which must stay uncovered — in one group or as two.
    const PixelSet expected = unite(block(2, 3, 1, 2), block(5, 6, 1, 2));
    const ScreenPolygon left = rectangle(2.0, 1.0, 4.6, 3.0), right = rectangle(4.8, 1.0, 7.0, 3.0);
    EXPECT_EQ(rasterize(10, 6, {left, right}), expected);
    OcclusionMask mask;
    mask.reset(10, 6);
    MaskRasterScratch scratch;
    EXPECT_EQ(rasterizeOccluderGroup(mask, &left, 1, 0.0, scratch), 4u);
    EXPECT_EQ(rasterizeOccluderGroup(mask, &right, 1, 0.0, scratch), 4u);
    EXPECT_EQ(coveredPixels(mask), expected);
}

TEST(MaskRasterizer, FanAroundAVertexCoversLikeTheWholePolygon)
{
    // The right triangle cut into three around (3, 3); the edges to (3, 3) are shared.
    const glm::dvec2 a{1.0, 1.0}, b{9.0, 1.0}, c{1.0, 9.0}, centre{3.0, 3.0};
    const std::vector<ScreenPolygon> fan = {polygon({a, b, centre}, {false, true, true}),
                                            polygon({b, c, centre}, {false, true, true}),
                                            polygon({c, a, centre}, {false, true, true})};
    EXPECT_EQ(rasterize(12, 12, fan), rightTriangleInterior());
    // Unshared, every pixel crossing a cut is lost: fewer pixels, all of them inside the triangle.
    const std::vector<ScreenPolygon> pieces = {polygon({a, b, centre}), polygon({b, c, centre}),
                                               polygon({c, a, centre})};
    const PixelSet piecewise = rasterize(12, 12, pieces);
    const PixelSet whole = rightTriangleInterior();
    EXPECT_LT(piecewise.size(), whole.size());
    EXPECT_TRUE(std::includes(whole.begin(), whole.end(), piecewise.begin(), piecewise.end()));
}

TEST(MaskRasterizer, DegeneratePolygonsVetoWhatTheyTouch)
{
    // A zero-area polygon along y = 1.5, x 3..4, vetoes the pixels its box touches: x 2..4, y 1.
    const std::vector<ScreenPolygon> group = {rectangle(2.0, 1.0, 6.0, 3.0),
                                              polygon({{3.0, 1.5}, {4.0, 1.5}, {3.5, 1.5}})};
    EXPECT_EQ(rasterize(10, 6, group), unite(block(5, 5, 1, 1), block(2, 5, 2, 2)));
    // Two vertices: vetoes its box too (pixels 2..4 of rows 1 and 2 around x 3..4, y 1.5..2).
    EXPECT_EQ(rasterize(10, 6, {rectangle(2.0, 1.0, 6.0, 3.0), polygon({{3.0, 1.5}, {4.0, 2.0}})}), block(5, 5, 1, 2));
    // A non-finite vertex spoils the whole group.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::size_t count = 1;
    EXPECT_EQ(
        rasterize(10, 6, {rectangle(2.0, 1.0, 6.0, 3.0), polygon({{20.0, 1.0}, {nan, 2.0}, {21.0, 3.0}})}, 0.0, &count),
        PixelSet{});
    EXPECT_EQ(count, 0u);
    // Not convex (a dart) and a pentagram: never trusted.
    EXPECT_EQ(rasterize(12, 12, {polygon({{1.0, 1.0}, {9.0, 1.0}, {3.0, 3.0}, {1.0, 9.0}})}), PixelSet{});
    std::vector<glm::dvec2> star;
    for (int i = 0; i < 5; ++i)
    {
        const double angle = 2.0 * M_PI * (2 * i) / 5.0;
        star.push_back({20.0 + 15.0 * std::cos(angle), 20.0 + 15.0 * std::sin(angle)});
    }
    EXPECT_EQ(rasterize(40, 40, {polygon(star)}), PixelSet{});
    // A bad depth plane too.
    DepthPlane badPlane;
    badPlane.c = nan;
    EXPECT_EQ(rasterize(10, 6, {rectangle(2.0, 1.0, 6.0, 3.0, badPlane)}), PixelSet{});
}

TEST(MaskRasterizer, KeepsTheNearerDepthOfEarlierGroups)
{
    OcclusionMask mask;
    mask.reset(10, 6);
    MaskRasterScratch scratch;
    const ScreenPolygon near = rectangle(2.0, 1.0, 4.0, 3.0, constantDepth(5.0));
    const ScreenPolygon far = rectangle(2.0, 1.0, 6.0, 3.0, constantDepth(20.0));
    rasterizeOccluderGroup(mask, &near, 1, 0.0, scratch);
    rasterizeOccluderGroup(mask, &far, 1, 0.0, scratch);
    EXPECT_NEAR(mask.depth(3, 1), 5.0f, 1e-4f);
    EXPECT_NEAR(mask.depth(4, 1), 20.0f, 1e-3f);
}

TEST(MaskRasterizer, PixelDepthIsTheLargestOverTheGroupPolygonsItTouches)
{
    // Left piece at depth 10, right at 20, sharing x = 4.5: pixel 4 touches both.
    const ScreenPolygon left =
        polygon({{2.0, 1.0}, {4.5, 1.0}, {4.5, 3.0}, {2.0, 3.0}}, {false, true, false, false}, constantDepth(10.0));
    const ScreenPolygon right =
        polygon({{4.5, 1.0}, {6.0, 1.0}, {6.0, 3.0}, {4.5, 3.0}}, {false, false, false, true}, constantDepth(20.0));
    OcclusionMask mask;
    rasterize(10, 6, {left, right}, 0.0, nullptr, &mask);
    for (int x = 2; x <= 5; ++x)
    {
        const double expected = x <= 3 ? 10.0 : 20.0;
        EXPECT_GE(mask.depth(x, 1), expected) << x;
        EXPECT_LE(mask.depth(x, 1), expected * (1.0 + 1e-5)) << x;
    }
}

TEST(MaskRasterizer, SlantedPlaneStoresTheCornerMaximumNotTheCentre)
{
    // 1/depth = 0.1 + 0.05 x: over pixel x the farthest point is its left edge, depth 1/(0.1+0.05x);
    // at the centre it would be 1/(0.1+0.05(x+0.5)) (pixel 2: 5 against 4.44).
    DepthPlane plane;
    plane.a = 0.05;
    plane.c = 0.1;
    OcclusionMask mask;
    EXPECT_EQ(rasterize(10, 4, {rectangle(0.0, 0.0, 8.0, 2.0, plane)}, 0.0, nullptr, &mask), block(0, 7, 0, 1));
    for (int x = 0; x <= 7; ++x)
    {
        const double expected = 1.0 / (0.1 + 0.05 * x);
        EXPECT_GE(mask.depth(x, 0), expected) << x;
        EXPECT_LE(mask.depth(x, 0), expected * (1.0 + 1e-5)) << x;
    }
    // Shrink 1: pixel 3 stands for [2, 5] × …, farthest at x = 2.
    rasterize(10, 8, {rectangle(0.0, 0.0, 8.0, 6.0, plane)}, 1.0, nullptr, &mask);
    EXPECT_GE(mask.depth(3, 2), 5.0f);
    EXPECT_LE(mask.depth(3, 2), 5.0f * (1.0f + 1e-5f));

    // Orthographic: depth = 2 + 0.5 x + 0.25 y itself, largest at the pixel's (x+1, y+1) corner.
    DepthPlane orthographic;
    orthographic.inverse = false;
    orthographic.a = 0.5;
    orthographic.b = 0.25;
    orthographic.c = 2.0;
    rasterize(10, 4, {rectangle(0.0, 0.0, 8.0, 2.0, orthographic)}, 0.0, nullptr, &mask);
    const double expected = 2.0 + 0.5 * 4 + 0.25 * 2;
    EXPECT_GE(mask.depth(3, 1), expected);
    EXPECT_LE(mask.depth(3, 1), expected * (1.0 + 1e-5));
}

TEST(MaskRasterizer, PlaneReachingTheHorizonCoversNothingThere)
{
    // 1/depth = 0.05 x - 0.1 is ≤ 0 over pixels 0..2 (pixel 2's left edge at x = 2 gives 0).
    DepthPlane plane;
    plane.a = 0.05;
    plane.c = -0.1;
    EXPECT_EQ(plane.maxOverSquare(2.0, 0.0, 3.0, 1.0), Inf);
    EXPECT_EQ(plane.maxOverSquare(1.0, 0.0, 5.0, 1.0), Inf);
    EXPECT_DOUBLE_EQ(plane.maxOverSquare(3.0, 0.0, 4.0, 1.0), 20.0);
    std::size_t count = 0;
    OcclusionMask mask;
    EXPECT_EQ(rasterize(10, 4, {rectangle(0.0, 0.0, 8.0, 2.0, plane)}, 0.0, &count, &mask), block(3, 7, 0, 1));
    EXPECT_EQ(count, 10u);
    EXPECT_GE(mask.depth(3, 0), 20.0f);
}

TEST(MaskRasterizer, DepthPlaneMaxOverSquareUsesTheCorners)
{
    DepthPlane perspective; // 1/depth = 0.01 x - 0.02 y + 0.5
    perspective.a = 0.01;
    perspective.b = -0.02;
    perspective.c = 0.5;
    EXPECT_DOUBLE_EQ(perspective.maxOverSquare(1.0, 2.0, 3.0, 5.0), 1.0 / (0.01 * 1.0 - 0.02 * 5.0 + 0.5));
    DepthPlane orthographic;
    orthographic.inverse = false;
    orthographic.a = -1.0;
    orthographic.b = 2.0;
    orthographic.c = 3.0;
    EXPECT_DOUBLE_EQ(orthographic.maxOverSquare(1.0, 2.0, 3.0, 5.0), -1.0 + 10.0 + 3.0);
    orthographic.c = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(orthographic.maxOverSquare(1.0, 2.0, 3.0, 5.0), Inf);
}

namespace
{
double signedDistanceInside(const std::vector<glm::dvec2>& ccw, glm::dvec2 point)
{
    double distance = Inf;
    for (std::size_t i = 0; i < ccw.size(); ++i)
    {
        const glm::dvec2 a = ccw[i], d = ccw[(i + 1) % ccw.size()] - a;
        distance = std::min(distance, (d.x * (point.y - a.y) - d.y * (point.x - a.x)) / std::sqrt(glm::dot(d, d)));
    }
    return distance;
}

double depthAt(const DepthPlane& plane, glm::dvec2 p)
{
    const double value = plane.a * p.x + plane.b * p.y + plane.c;
    return plane.inverse ? (value > 0.0 ? 1.0 / value : Inf) : value;
}
} // namespace

namespace
{
void checkRandomGroupsCoverOnlyPointsInsideAndNearer(GroupRasterizer rasterizer)
{
    std::mt19937 random(5);
    const std::uint32_t size = 64;
    std::size_t coveredTotal = 0, compared = 0;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int groupIndex = 0; groupIndex < 400; ++groupIndex)
    {
        const std::vector<glm::dvec2> hull = randomConvexPolygon(random, size);
        const int cuts = 1 + int(random() % 3);
        const DepthPlane plane = randomPlane(random, hull[0]);
        const std::vector<ScreenPolygon> group = randomCutGroup(random, hull, cuts, plane);
        const double shrink = random() % 3 == 0 ? double(random() % 4) : 3.0 * unit(random);
        OcclusionMask mask;
        std::size_t count = 0;
        rasterize(size, size, group, shrink, &count, &mask, rasterizer);
        ASSERT_EQ(count, mask.coveredPixels());
        coveredTotal += count;

        for (std::uint32_t y = 0; y < size; ++y)
            for (std::uint32_t x = 0; x < size; ++x)
            {
                const glm::dvec2 low{x - shrink, y - shrink}, high{x + 1 + shrink, y + 1 + shrink};
                const bool covered = mask.depth(x, y) < std::numeric_limits<float>::infinity();
                if (covered)
                {
                    // The key property: sampled points of the grown pixel lie inside, nearer.
                    for (int sample = 0; sample < 24; ++sample)
                    {
                        glm::dvec2 p = glm::mix(low, high, glm::dvec2{unit(random), unit(random)});
                        if (sample < 4) // the corners
                            p = {sample & 1 ? high.x : low.x, sample & 2 ? high.y : low.y};
                        ASSERT_GE(signedDistanceInside(hull, p), -1e-9) << groupIndex << " pixel " << x << "," << y;
                        ASSERT_GE(double(mask.depth(x, y)), depthAt(plane, p)) << groupIndex << " " << x << "," << y;
                    }
                }
                // And nothing less: for a convex union the group test is exact (away from ties).
                double inside = Inf;
                for (int corner = 0; corner < 4; ++corner)
                    inside = std::min(
                        inside, signedDistanceInside(hull, {corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y}));
                const double farthest = plane.maxOverSquare(low.x, low.y, high.x, high.y);
                const double nearestInverse =
                    std::min({plane.a * low.x + plane.b * low.y, plane.a * high.x + plane.b * low.y,
                              plane.a * low.x + plane.b * high.y, plane.a * high.x + plane.b * high.y}) +
                    plane.c;
                const bool nearHorizon = plane.inverse && std::abs(nearestInverse) < 1e-5;
                if (std::abs(inside) < 1e-9 || nearHorizon)
                    continue;
                ASSERT_EQ(covered, inside >= 0.0 && farthest < Inf) << groupIndex << " pixel " << x << "," << y;
                ++compared;
            }
    }
    EXPECT_GT(coveredTotal, 50000u);
    EXPECT_GT(compared, 400u * 3500u);
}
} // namespace

TEST(MaskRasterizer, RandomGroupsCoverOnlyPointsInsideAndNearerThanStored)
{
    checkRandomGroupsCoverOnlyPointsInsideAndNearer(rasterizeOccluderGroup);
}

TEST(MaskRasterizer, ReferenceCoversOnlyPointsInsideAndNearerThanStored)
{
    checkRandomGroupsCoverOnlyPointsInsideAndNearer(referenceRasterizer);
}

TEST(MaskRasterizer, VectorAndScalarPathsAgreeBitForBit)
{
    if (!maskRasterHasSimd())
        GTEST_SKIP() << "no SSE2 in this build: only the scalar path exists";
    std::mt19937 random(99);
    std::uniform_real_distribution<double> coordinate(-20.0, 100.0), unit(0.0, 1.0);
    MaskRasterScratch scratch;
    for (int groupIndex = 0; groupIndex < 400; ++groupIndex)
    {
        // Unrelated polygons with random shared flags; on pixel boundaries half the time, so
        // the double re-check of near-threshold lanes runs too.
        std::vector<ScreenPolygon> group;
        const int count = 1 + int(random() % 4);
        for (int i = 0; i < count; ++i)
        {
            std::vector<glm::dvec2> vertices = randomConvexPolygon(random, 80.0);
            if (groupIndex % 2 == 0)
                for (glm::dvec2& v : vertices)
                    v = glm::round(v * 2.0) / 2.0;
            if (random() % 10 == 0)
                vertices.resize(2);
            std::vector<bool> shared(vertices.size());
            for (std::size_t e = 0; e < shared.size(); ++e)
                shared[e] = random() % 3 == 0;
            group.push_back(polygon(vertices, shared, randomPlane(random, vertices[0])));
        }
        const double shrink = groupIndex % 3 == 0 ? double(random() % 3) : 2.0 * unit(random);
        OcclusionMask scalar, vector;
        scalar.reset(96, 80);
        vector.reset(96, 80);
        const std::size_t scalarCount =
            rasterizeOccluderGroupReference(MaskRasterPath::Scalar, scalar, group.data(), group.size(), shrink, scratch);
        const std::size_t vectorCount =
            rasterizeOccluderGroupReference(MaskRasterPath::Simd, vector, group.data(), group.size(), shrink, scratch);
        ASSERT_EQ(scalarCount, vectorCount) << groupIndex;
        for (std::uint32_t y = 0; y < 80; ++y)
            ASSERT_EQ(std::memcmp(scalar.baseRow(y), vector.baseRow(y), 96 * sizeof(float)), 0)
                << groupIndex << " row " << y;
    }
}
