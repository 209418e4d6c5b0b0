// SPDX-License-Identifier: MIT
// Area-angle metric, the octree of potential occluders (never missing one that reaches the
// threshold inside its leaf), and the per-frame choice of the k best.
#include "AllocationCounter.h"

#include <osgVis/core/occluders/OccluderSelector.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <gtest/gtest.h>
#include <new>
#include <random>
#include <thread>

using namespace osgVis::core;

namespace
{
// Square of side `side` centred at `centre`, in the plane with unit normal `normal`.
OccluderPolygon squarePolygon(const Vec3& centre, const Vec3& normal, double side, bool oneSided = false)
{
    const Vec3 n = glm::normalize(normal);
    const Vec3 helper = std::abs(n.z) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
    const Vec3 u = glm::normalize(glm::cross(helper, n)) * (side / 2);
    const Vec3 v = glm::cross(n, u);
    OccluderPolygon p;
    p.vertices = {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
    p.plane = Plane::fromPointNormal(centre, n);
    p.area = side * side;
    p.centroid = centre;
    p.neighbours.assign(4, NoNeighbour);
    p.oneSided = oneSided;
    return p;
}

std::vector<OccluderPolygon> randomPolygons(std::size_t count, unsigned seed, double spread)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-spread, spread);
    std::uniform_real_distribution<double> direction(-1.0, 1.0);
    std::uniform_real_distribution<double> side(0.5, 8.0);
    std::vector<OccluderPolygon> polygons;
    for (std::size_t i = 0; i < count; ++i)
    {
        Vec3 n(direction(rng), direction(rng), direction(rng));
        if (glm::length(n) < 1e-3)
            n = Vec3(0, 0, 1);
        polygons.push_back(
            squarePolygon(Vec3(position(rng), position(rng), position(rng) * 0.3), n, side(rng), i % 3 == 0));
    }
    return polygons;
}

double oracleMetric(const OccluderPolygon& p, const Vec3& eye)
{
    const Vec3 d = p.centroid - eye;
    const double length = glm::length(d);
    return p.area * std::abs(glm::dot(p.plane.normal, d / length)) / (length * length);
}
} // namespace

TEST(AreaAngle, HandComputedValues)
{
    const OccluderPolygon wall = squarePolygon(Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0); // area 4
    EXPECT_NEAR(areaAngle(wall, Vec3(0, 0, 5)), 4.0 / 25.0, 1e-15);                // facing
    EXPECT_NEAR(areaAngle(wall, Vec3(0, 0, -5)), 4.0 / 25.0, 1e-15);               // two-sided: from behind too
    EXPECT_NEAR(areaAngle(wall, Vec3(3, 0, 4)), 4.0 * 0.8 / 25.0, 1e-15);          // oblique, cos = 4/5
    EXPECT_NEAR(areaAngle(wall, Vec3(0, -6, 8)), 4.0 * 0.8 / 100.0, 1e-15);        // further, same cosine
    EXPECT_NEAR(areaAngle(wall, Vec3(-2, 7, 3)), oracleMetric(wall, Vec3(-2, 7, 3)), 1e-15);
    EXPECT_EQ(areaAngle(wall, Vec3(5, 0, 0)), 0.0);     // edge-on, on its plane
    EXPECT_EQ(areaAngle(wall, Vec3(0.5, 0.5, 0)), 0.0); // standing on it
    EXPECT_EQ(areaAngle(wall, Vec3(0, 0, 0)), 0.0);     // at the centroid

    const OccluderPolygon oneSided = squarePolygon(Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, true);
    EXPECT_NEAR(areaAngle(oneSided, Vec3(0, 0, 5)), 4.0 / 25.0, 1e-15);
    EXPECT_EQ(areaAngle(oneSided, Vec3(0, 0, -5)), 0.0); // culled side
    EXPECT_EQ(areaAngle(oneSided, Vec3(3, 0, -4)), 0.0);
    EXPECT_EQ(areaAngle(oneSided, Vec3(5, 0, 0)), 0.0);
}

TEST(OccluderSelector, SelectReturnsTheLargestInOrder)
{
    // Same-sized squares facing the origin at increasing distances; index order shuffled.
    const double distances[] = {9, 3, 7, 1.5, 5, 11, 2};
    std::vector<OccluderPolygon> polygons;
    for (double d : distances)
        polygons.push_back(squarePolygon(Vec3(d, 0, 0), Vec3(-1, 0, 0), 1.0));
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.threshold = 1.0 / 100.0; // 1/d²: reached up to d = 10
    selector.build(polygons, Aabb(Vec3(-20), Vec3(20)), options);

    std::vector<std::uint32_t> out;
    selector.select(Vec3(0, 0, 0), 3, out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{3, 6, 1}));
    selector.select(Vec3(0, 0, 0), 100, out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{3, 6, 1, 4, 2, 0})) << "d = 11 is below the threshold";
    selector.select(Vec3(0, 0, 0), 0, out);
    EXPECT_TRUE(out.empty());
}

TEST(OccluderSelector, TiesGoToTheLowerIndex)
{
    // Four identical copies and two smaller ones, picked from the middle of the list.
    std::vector<OccluderPolygon> polygons;
    polygons.push_back(squarePolygon(Vec3(0, 0, 4), Vec3(0, 0, 1), 1.0));
    for (int i = 0; i < 4; ++i)
        polygons.push_back(squarePolygon(Vec3(0, 0, 2), Vec3(0, 0, 1), 1.0));
    polygons.push_back(squarePolygon(Vec3(0, 0, 3), Vec3(0, 0, 1), 1.0));
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.threshold = 0.0;
    selector.build(polygons, Aabb(Vec3(-10), Vec3(10)), options);
    std::vector<std::uint32_t> out;
    selector.select(Vec3(0, 0, 0), 3, out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{1, 2, 3}));
    selector.select(Vec3(0, 0, 0), 6, out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 0}));
}

TEST(OccluderSelector, SelectMatchesABruteForceRanking)
{
    const auto polygons = randomPolygons(400, 11, 60.0);
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.threshold = 0.005;
    options.maxLeafPolygons = 16;
    const Aabb region(Vec3(-70), Vec3(70));
    selector.build(polygons, region, options);

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> coordinate(-70, 70);
    std::vector<std::uint32_t> out, expected;
    for (int trial = 0; trial < 300; ++trial)
    {
        const Vec3 eye(coordinate(rng), coordinate(rng), coordinate(rng));
        const std::uint32_t k = 1 + std::uint32_t(trial % 12);
        selector.select(eye, k, out);
        expected.clear();
        for (std::uint32_t i = 0; i < polygons.size(); ++i)
        {
            if (areaAngle(polygons[i], eye) >= options.threshold)
                expected.push_back(i);
        }
        std::stable_sort(expected.begin(), expected.end(),
                         [&](std::uint32_t a, std::uint32_t b)
                         { return areaAngle(polygons[a], eye) > areaAngle(polygons[b], eye); });
        if (expected.size() > k)
            expected.resize(k);
        ASSERT_EQ(out, expected) << "trial " << trial;
    }
}

TEST(OccluderSelector, LeafListsNeverMissAPolygonThatReachesTheThreshold)
{
    const auto polygons = randomPolygons(600, 21, 50.0);
    const Aabb region(Vec3(-60, -60, -25), Vec3(60, 60, 25));
    for (const double threshold : {0.002, 0.01, 0.05})
    {
        OccluderSelector selector;
        OccluderSelectorOptions options;
        options.threshold = threshold;
        options.maxLeafPolygons = 8;
        options.maxDepth = 6;
        selector.build(polygons, region, options);

        std::mt19937 rng(unsigned(threshold * 1e6));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::uniform_real_distribution<double> coordinate(-60, 60);
        std::size_t leavesSeen = 0, checked = 0;
        std::uint32_t lastLeaf = ~0u;
        for (int trial = 0; trial < 4000; ++trial)
        {
            // Random leaf (through a random point), then points spread over it, corners included.
            const std::uint32_t leaf = selector.leafOf(Vec3(coordinate(rng), coordinate(rng), 0.4 * coordinate(rng)));
            const Aabb& box = selector.leafBounds(leaf);
            leavesSeen += leaf != lastLeaf;
            lastLeaf = leaf;
            Vec3 eye = box.min + Vec3(unit(rng), unit(rng), unit(rng)) * box.extent();
            if (trial % 5 == 0)
                eye = box.corner(trial / 5 % 8);
            ASSERT_TRUE(box.contains(eye));
            const auto& listed = selector.potentialOccluders(leaf);
            const auto& bounds = selector.potentialOccluderBounds(leaf);
            // A leaf lists its polygons by their bound, largest first: a search stops on it.
            if (leaf != 0)
            {
                ASSERT_EQ(bounds.size(), listed.size());
                ASSERT_TRUE(std::is_sorted(bounds.rbegin(), bounds.rend()));
            }
            for (std::uint32_t i = 0; i < polygons.size(); ++i)
            {
                const double metric = areaAngle(polygons[i], eye);
                if (!(metric >= threshold))
                    continue;
                ++checked;
                const auto at = std::find(listed.begin(), listed.end(), i);
                ASSERT_TRUE(at != listed.end())
                    << "polygon " << i << " missing from leaf " << leaf << " at threshold " << threshold;
                if (leaf != 0)
                {
                    ASSERT_GE(bounds[std::size_t(at - listed.begin())], metric) << "polygon " << i << " leaf " << leaf;
                }
            }
        }
        EXPECT_GT(leavesSeen, 50u);
        EXPECT_GT(checked, 1000u);
    }
}

TEST(OccluderSelector, SplitsShortenTheLists)
{
    const auto polygons = randomPolygons(600, 31, 50.0);
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.threshold = 0.01;
    options.maxLeafPolygons = 32;
    selector.build(polygons, Aabb(Vec3(-60, -60, -25), Vec3(60, 60, 25)), options);
    const std::uint32_t leaf = selector.leafOf(Vec3(30, 30, 10));
    EXPECT_NE(leaf, 0u);
    EXPECT_LT(selector.potentialOccluders(leaf).size(), polygons.size() / 2);
}

TEST(OccluderSelector, EyeOutsideTheRegionUsesTheRoot)
{
    const auto polygons = randomPolygons(300, 41, 20.0);
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.maxLeafPolygons = 4;
    const Aabb region(Vec3(-25), Vec3(25));
    selector.build(polygons, region, options);
    EXPECT_EQ(selector.leafOf(Vec3(0, 0, 26)), 0u);
    EXPECT_EQ(selector.leafOf(Vec3(1e9, 0, 0)), 0u);
    EXPECT_EQ(selector.leafOf(Vec3(std::nan(""), 0, 0)), 0u);
    EXPECT_NE(selector.leafOf(Vec3(0, 0, 24)), 0u);
    EXPECT_EQ(selector.potentialOccluders(0).size(), polygons.size());
    EXPECT_EQ(selector.leafBounds(0).min, region.min);

    // Just outside, next to a polygon the eye almost touches: still found through the root.
    std::vector<OccluderPolygon> edge = polygons;
    edge.push_back(squarePolygon(Vec3(0, 0, 24.9), Vec3(0, 0, 1), 1.0));
    selector.build(edge, region, options);
    std::vector<std::uint32_t> out;
    selector.select(Vec3(0, 0, 25.5), 1, out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{std::uint32_t(edge.size() - 1)}));
}

TEST(OccluderSelector, EmptySelectorIsHarmless)
{
    OccluderSelector selector;
    std::vector<std::uint32_t> out{1, 2};
    selector.select(Vec3(0), 4, out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(selector.leafOf(Vec3(0)), 0u);
    EXPECT_TRUE(selector.potentialOccluders(0).empty());

    const std::vector<OccluderPolygon> none;
    selector.build(none, Aabb(Vec3(-1), Vec3(1)));
    selector.select(Vec3(0), 4, out);
    EXPECT_TRUE(out.empty());
}

TEST(OccluderSelector, BuildIsDeterministic)
{
    const auto polygons = randomPolygons(500, 51, 40.0);
    OccluderSelectorOptions options;
    options.maxLeafPolygons = 10;
    OccluderSelector a, b;
    a.build(polygons, Aabb(Vec3(-45), Vec3(45)), options);
    b.build(polygons, Aabb(Vec3(-45), Vec3(45)), options);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coordinate(-45, 45);
    for (int i = 0; i < 200; ++i)
    {
        const Vec3 eye(coordinate(rng), coordinate(rng), coordinate(rng));
        ASSERT_EQ(a.leafOf(eye), b.leafOf(eye));
        ASSERT_EQ(a.potentialOccluders(a.leafOf(eye)), b.potentialOccluders(b.leafOf(eye)));
    }
}

TEST(OccluderSelector, SelectAllocatesNothingOnceOutHasCapacity)
{
    const auto polygons = randomPolygons(400, 61, 30.0);
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.threshold = 0.001;
    selector.build(polygons, Aabb(Vec3(-35), Vec3(35)), options);
    std::vector<std::uint32_t> out;
    out.reserve(200); // beyond the metrics select keeps on its stack
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> coordinate(-35, 35);
    const std::size_t before = osgVis::test::allocationCount();
    std::size_t chosen = 0;
    for (int i = 0; i < 200; ++i)
    {
        selector.select(Vec3(coordinate(rng), coordinate(rng), coordinate(rng)), i % 2 ? 8u : 200u, out);
        chosen += out.size();
    }
    EXPECT_EQ(osgVis::test::allocationCount(), before);
    EXPECT_GT(chosen, 0u);
}

TEST(OccluderSelector, ConcurrentSelectsAgreeWithSerialOnes)
{
    const auto polygons = randomPolygons(500, 71, 40.0);
    OccluderSelector selector;
    OccluderSelectorOptions options;
    options.threshold = 0.003;
    options.maxLeafPolygons = 16;
    selector.build(polygons, Aabb(Vec3(-45), Vec3(45)), options);

    std::vector<Vec3> eyes;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(-45, 45);
    for (int i = 0; i < 400; ++i)
        eyes.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    std::vector<std::vector<std::uint32_t>> serial(eyes.size());
    for (std::size_t i = 0; i < eyes.size(); ++i)
        selector.select(eyes[i], 10, serial[i]);

    std::atomic<int> mismatches{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back(
            [&, t]
            {
                std::vector<std::uint32_t> out;
                for (int round = 0; round < 5; ++round)
                    for (std::size_t i = std::size_t(t); i < eyes.size(); ++i)
                    {
                        selector.select(eyes[i], 10, out);
                        if (out != serial[i])
                            ++mismatches;
                    }
            });
    for (std::thread& thread : threads)
        thread.join();
    EXPECT_EQ(mismatches.load(), 0);
}
