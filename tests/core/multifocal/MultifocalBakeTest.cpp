// SPDX-License-Identifier: MIT
// View cells and their bake: grids and cells along a walk, each cell's PVS independent of the
// thread count and of the range it was baked in (what merged ranges rely on), and bad sizes refused.
#include "BoxScenes.h"

#include <osgVis/core/multifocal/MultifocalBake.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>

using namespace osgVis::core;
using namespace osgVis::test;

TEST(MultifocalBake, AGridCoversTheBoxXFastest)
{
    const std::vector<Aabb> cells = gridViewCells(Aabb(Vec3(0, 0, 0), Vec3(10, 4, 2)), Vec3(4, 4, 2));
    ASSERT_EQ(cells.size(), 3u);
    EXPECT_EQ(cells[0].min, Vec3(0, 0, 0));
    EXPECT_EQ(cells[1].min, Vec3(4, 0, 0));
    EXPECT_EQ(cells[2].max, Vec3(12, 4, 2)); // the last column reaches past the box
}

TEST(MultifocalBake, CellsAlongAWalkHoldEveryEyeOnce)
{
    const std::vector<Vec3> eyes{{1, 1, 1}, {1.5, 1, 1}, {5, 1, 1}, {4, 1, 1}};
    const std::vector<Aabb> cells = viewCellsAlong(eyes, Vec3(4, 4, 2), Vec3(0, 0, 0));
    // (4, 1, 1) lies on the boundary of the first two cells; (5, 1, 1) in the second.
    ASSERT_EQ(cells.size(), 2u);
    EXPECT_EQ(cells[0].min, Vec3(0, 0, 0));
    EXPECT_EQ(cells[1].min, Vec3(4, 0, 0));
    for (const Vec3& eye : eyes)
        EXPECT_TRUE(cells[0].contains(eye) || cells[1].contains(eye));
}

TEST(MultifocalBake, RefusesCellsOfZeroNegativeOrNonFiniteSize)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3& size : {Vec3(0, 1, 1), Vec3(-1, 1, 1), Vec3(nan, 1, 1)})
    {
        EXPECT_THROW(gridViewCells(Aabb(Vec3(0), Vec3(1)), size), std::invalid_argument);
        EXPECT_THROW(viewCellsAlong({Vec3(0)}, size, Vec3(0)), std::invalid_argument);
    }
    EXPECT_THROW(gridViewCells(Aabb(Vec3(0), Vec3(nan)), Vec3(1)), std::invalid_argument);
    EXPECT_THROW(gridViewCells(Aabb(), Vec3(1)), std::invalid_argument);
}

TEST(MultifocalBake, EachCellsPvsIsTheSameWhateverTheThreadsAndRanges)
{
    const City city = makeCity();
    const std::vector<Aabb> cells = gridViewCells(Aabb(Vec3(80, 0, 0.5), Vec3(92, 24, 2.5)), Vec3(4, 4, 2));
    ASSERT_EQ(cells.size(), 18u);
    const MultifocalOptions options;
    ViewCellBake whole;
    {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        whole = bakeViewCells(city.scene, cells, 0, cells.size(), options);
    }
    std::size_t reports = 0;
    const ViewCellBake low = bakeViewCells(city.scene, cells, 0, 7, options, [&](std::size_t, std::size_t) { ++reports; });
    const ViewCellBake high = bakeViewCells(city.scene, cells, 7, cells.size(), options);
    EXPECT_EQ(reports, 7u);
    ASSERT_EQ(low.pvs.size() + high.pvs.size(), whole.pvs.size());
    std::size_t culledSomewhere = 0;
    for (std::size_t i = 0; i < cells.size(); ++i)
    {
        const VisibleSet& part = i < 7 ? low.pvs[i] : high.pvs[i - 7];
        EXPECT_EQ(part, whole.pvs[i]) << "cell " << i;
        culledSomewhere += whole.pvs[i].count() < city.scene.objects.size() ? 1 : 0;
    }
    EXPECT_GT(culledSomewhere, 0u);
    EXPECT_THROW(bakeViewCells(city.scene, cells, 5, 30, options), std::invalid_argument);
}
