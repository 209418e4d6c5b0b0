// SPDX-License-Identifier: MIT
// The CDT occlusion record: exact outcomes on small configurations (fusion, T-junctions, holes,
// depth, budget), random frames that keep every invariant, and a frame that allocates nothing.
#include "AllocationCounter.h"
#include "CdtTestShapes.h"

#include <osgVis/core/cdt/CoverageTriangulation.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace osgVis::core::cdt;
using osgVis::test::cdt::randomConvex;

namespace
{
std::vector<GridPoint> rect(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1)
{
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

bool insert(CoverageTriangulation& cdt, const std::vector<GridPoint>& p, CoverKind kind = CoverKind::DepthFree,
            AffineNearness w = {})
{
    const bool ok = cdt.insertOccluder(p.data(), p.size(), kind, w);
    EXPECT_EQ(cdt.validate(), "");
    return ok;
}

bool hidden(const CoverageTriangulation& cdt, const std::vector<GridPoint>& p, QueryMode mode = QueryMode::DepthFree,
            double nearestW = std::numeric_limits<double>::infinity())
{
    return cdt.hidden(p.data(), p.size(), mode, nearestW);
}
} // namespace

TEST(CoverageTriangulation, EmptyHidesNothing)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    EXPECT_EQ(cdt.validate(), "");
    EXPECT_FALSE(hidden(cdt, rect(0, 0, 10, 10)));
    EXPECT_EQ(cdt.triangles().size(), 2u);
}

//  +----+----+      +----+ +----+
//  | A  | B  |      | A  | | B  |   a query straddling x = 10: hidden on the left, not across the gap
//  +----+----+      +----+ +----+
TEST(CoverageTriangulation, AbuttingSquaresFuse)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    ASSERT_TRUE(insert(cdt, rect(0, 0, 10, 10)));
    ASSERT_TRUE(insert(cdt, rect(10, 0, 20, 10)));
    EXPECT_TRUE(hidden(cdt, rect(5, 2, 15, 8)));
    EXPECT_TRUE(hidden(cdt, rect(0, 0, 20, 10)));
    EXPECT_FALSE(hidden(cdt, rect(5, 2, 15, 11)));

    cdt.reset(-100, -100, 100, 100);
    ASSERT_TRUE(insert(cdt, rect(0, 0, 10, 10)));
    ASSERT_TRUE(insert(cdt, rect(11, 0, 21, 10)));
    EXPECT_FALSE(hidden(cdt, rect(5, 2, 15, 8)));
    EXPECT_TRUE(hidden(cdt, rect(1, 1, 9, 9)));
    EXPECT_TRUE(hidden(cdt, rect(12, 1, 20, 9)));
}

//  +----+----+
//  |    | C  |   B and C meet A's right edge at its middle (a T-junction at (10, 5))
//  | A  +----+
//  |    | B  |
//  +----+----+
TEST(CoverageTriangulation, TJunction)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    ASSERT_TRUE(insert(cdt, rect(0, 0, 10, 10)));
    ASSERT_TRUE(insert(cdt, rect(10, 0, 20, 5)));
    EXPECT_FALSE(hidden(cdt, rect(5, 1, 15, 9)));
    ASSERT_TRUE(insert(cdt, rect(10, 5, 20, 10)));
    EXPECT_TRUE(hidden(cdt, rect(5, 1, 15, 9)));
    EXPECT_TRUE(hidden(cdt, {{1, 1}, {19, 1}, {19, 9}}));
}

TEST(CoverageTriangulation, HoleInsideARingIsFound)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    ASSERT_TRUE(insert(cdt, rect(0, 0, 10, 30)));
    ASSERT_TRUE(insert(cdt, rect(20, 0, 30, 30)));
    ASSERT_TRUE(insert(cdt, rect(10, 0, 20, 10)));
    ASSERT_TRUE(insert(cdt, rect(10, 20, 20, 30)));
    EXPECT_TRUE(hidden(cdt, rect(1, 1, 9, 29)));
    EXPECT_FALSE(hidden(cdt, rect(2, 2, 28, 28))); // the hole [10, 20]^2 is inside it
    ASSERT_TRUE(insert(cdt, rect(10, 10, 20, 20)));
    EXPECT_TRUE(hidden(cdt, rect(2, 2, 28, 28)));
    EXPECT_TRUE(hidden(cdt, rect(0, 0, 30, 30)));
}

TEST(CoverageTriangulation, OverlappingCollinearAndSharedVertices)
{
    CoverageTriangulation cdt;
    cdt.reset(-1000, -1000, 1000, 1000);
    ASSERT_TRUE(insert(cdt, rect(0, 0, 100, 100)));
    ASSERT_TRUE(insert(cdt, rect(50, 0, 150, 100)));                // overlapping, collinear edges
    ASSERT_TRUE(insert(cdt, rect(0, 0, 100, 100)));                 // duplicate
    ASSERT_TRUE(insert(cdt, rect(20, 20, 40, 40)));                 // inside
    ASSERT_TRUE(insert(cdt, {{150, 100}, {250, 100}, {200, 200}})); // meets at a vertex
    ASSERT_TRUE(insert(cdt, {{0, 0}, {100, 1}, {200, 3}, {0, 2}})); // nearly parallel edges
    EXPECT_TRUE(hidden(cdt, rect(0, 0, 150, 100)));
    EXPECT_FALSE(hidden(cdt, rect(0, 0, 151, 100)));
    EXPECT_TRUE(hidden(cdt, {{150, 100}, {250, 100}, {200, 200}}));
}

TEST(CoverageTriangulation, HugeCoordinates)
{
    const std::int32_t L = std::int32_t(GridLimit);
    CoverageTriangulation cdt;
    cdt.reset(-L, -L, L, L);
    ASSERT_TRUE(insert(cdt, rect(-L, -L, 0, L)));
    ASSERT_TRUE(insert(cdt, {{0, -L}, {L, -L + 1}, {L, L}, {0, L}}));
    EXPECT_TRUE(hidden(cdt, rect(-L + 7, -L + 7, L - 7, L - 7)));
    EXPECT_FALSE(hidden(cdt, rect(-L, -L, L, L)));                                // the corner (L, -L) is not covered
    ASSERT_TRUE(insert(cdt, {{L - 3, L - 3}, {-L + 1, L - 1}, {L - 1, -L + 5}})); // long, crossing
    EXPECT_LE(cdt.constraintDeviation(), 0.5);
}

TEST(CoverageTriangulation, DepthBoundsAndModes)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    AffineNearness plane;
    plane.c = 0.5;
    plane.valid = true;
    ASSERT_TRUE(insert(cdt, rect(0, 0, 20, 20), CoverKind::DepthOnly, plane));
    EXPECT_TRUE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthOnly, 0.4)); // behind the plane
    EXPECT_TRUE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthFree, 0.4));
    EXPECT_FALSE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthOnly, 0.6)); // in front of it
    EXPECT_FALSE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthFree, 0.6)); // depth-only cover
    EXPECT_FALSE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthOnly));

    // A sloped plane: w = 0.01 x + 1; its least w over a triangle is at a vertex.
    cdt.reset(-100, -100, 100, 100);
    AffineNearness slope;
    slope.a = 0.01, slope.c = 1.0, slope.valid = true;
    ASSERT_TRUE(insert(cdt, rect(0, 0, 50, 50), CoverKind::DepthOnly, slope));
    EXPECT_TRUE(hidden(cdt, rect(10, 10, 40, 40), QueryMode::DepthOnly, 0.99));
    EXPECT_FALSE(hidden(cdt, rect(10, 10, 40, 40), QueryMode::DepthOnly, 1.2));
    for (const auto& t : cdt.triangles())
    {
        if (t.depthBound > -std::numeric_limits<double>::infinity())
        {
            EXPECT_LE(t.depthBound, 1.0 + 0.01 * std::min({t.a.x, t.b.x, t.c.x}) + 1e-12);
        }
    }
}

TEST(CoverageTriangulation, DepthOnlyQueryIgnoresDepthFreeCover)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    ASSERT_TRUE(insert(cdt, rect(0, 0, 20, 20), CoverKind::DepthFree));
    EXPECT_TRUE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthFree));
    EXPECT_FALSE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthOnly, 0.0));
    AffineNearness none; // valid = false: no bound
    ASSERT_TRUE(insert(cdt, rect(0, 0, 20, 20), CoverKind::DepthOnly, none));
    EXPECT_FALSE(hidden(cdt, rect(2, 2, 18, 18), QueryMode::DepthOnly, -1e30));
}

TEST(CoverageTriangulation, BudgetRefusesWholeOccluders)
{
    CoverageTriangulation cdt;
    cdt.reset(-100, -100, 100, 100);
    cdt.setConstraintBudget(8);
    EXPECT_TRUE(insert(cdt, rect(0, 0, 10, 10)));
    EXPECT_TRUE(insert(cdt, rect(20, 0, 30, 10)));
    EXPECT_FALSE(insert(cdt, rect(40, 0, 50, 10)));
    EXPECT_EQ(cdt.statistics().occludersRefused, 1u);
    EXPECT_EQ(cdt.statistics().occludersInserted, 2u);
    EXPECT_FALSE(hidden(cdt, rect(41, 1, 49, 9)));
    EXPECT_TRUE(hidden(cdt, rect(21, 1, 29, 9)));
    cdt.setConstraintBudget(0);
    cdt.reset(-100, -100, 100, 100);
    EXPECT_TRUE(insert(cdt, rect(40, 0, 50, 10)));
}

TEST(CoverageTriangulation, OutsideAndDegenerate)
{
    CoverageTriangulation cdt;
    cdt.reset(0, 0, 100, 100);
    ASSERT_TRUE(insert(cdt, rect(-50, -50, 150, 150))); // clipped to the rectangle
    EXPECT_TRUE(hidden(cdt, rect(0, 0, 100, 100)));
    EXPECT_FALSE(hidden(cdt, rect(-1, 0, 100, 100)));          // reaches beyond the rectangle
    EXPECT_FALSE(hidden(cdt, {{10, 10}, {20, 20}, {30, 30}})); // zero area
    EXPECT_FALSE(insert(cdt, {{10, 10}, {20, 20}, {30, 30}}));
    EXPECT_FALSE(insert(cdt, {{10, 10}, {10, 20}, {20, 10}})); // clockwise
    EXPECT_FALSE(insert(cdt, rect(200, 200, 300, 300)));       // wholly outside
}

TEST(CoverageTriangulation, RandomFramesKeepInvariants)
{
    std::mt19937_64 rng(21);
    CoverageTriangulation cdt;
    double worst = 0.0;
    std::uint32_t fallbacks = 0;
    for (int frame = 0; frame < 300; ++frame)
    {
        const bool huge = frame % 5 == 4;
        const std::int64_t L = huge ? GridLimit : 1000;
        cdt.reset(std::int32_t(-L), std::int32_t(-L), std::int32_t(L), std::int32_t(L));
        std::uniform_int_distribution<std::int64_t> centre(-L + L / 4, L - L / 4);
        for (int k = 0; k < 12; ++k)
        {
            const auto poly = randomConvex(rng, centre(rng), centre(rng), L / 4, 3 + int(rng() % 6), k % 4 == 3);
            cdt.insertOccluder(poly.data(), poly.size(), CoverKind::DepthFree, {});
            ASSERT_EQ(cdt.validate(), "") << "frame " << frame << " occluder " << k;
        }
        worst = std::max(worst, cdt.constraintDeviation());
        fallbacks += cdt.statistics().roundingFallbacks;
    }
    std::printf("worst constraint deviation %.4f grid units (L-inf), %u rounding fallbacks\n", worst, fallbacks);
    EXPECT_LE(worst, 0.5 + 1e-9); // docs/cdt.md: the rounding bound (measured in doubles)
}

TEST(CoverageTriangulation, SteadyFrameAllocatesNothing)
{
    std::mt19937_64 rng(5);
    std::vector<std::vector<GridPoint>> polys;
    for (int k = 0; k < 64; ++k)
        polys.push_back(
            randomConvex(rng, std::int64_t(rng() % 1600) - 800, std::int64_t(rng() % 1600) - 800, 150, 4, false));
    const auto query = rect(-50, -50, 50, 50);
    CoverageTriangulation cdt;
    const auto frame = [&]
    {
        cdt.reset(-1000, -1000, 1000, 1000);
        for (const auto& p : polys)
            cdt.insertOccluder(p.data(), p.size(), CoverKind::DepthFree, {});
        return cdt.hidden(query.data(), query.size(), QueryMode::DepthFree);
    };
    frame();
    frame();
    const std::size_t before = osgVis::test::allocationCount();
    frame();
    EXPECT_EQ(osgVis::test::allocationCount() - before, 0u);
}
