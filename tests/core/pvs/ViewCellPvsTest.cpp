// SPDX-License-Identifier: MIT
// Point location in view cells: closed boxes, the first cell on a shared face, none outside.
#include "PvsSample.h"

#include <gtest/gtest.h>

using namespace osgVis::core;

TEST(ViewCellPvs, LocateFindsTheFirstCellWhoseClosedBoxHoldsThePoint)
{
    // Cells 0 [0, 1.5] and 1 [1.5, 3] along x share the face x = 1.5; cell 2 is a point-thin box.
    const ViewCellPvs cells = osgVis::test::makeSampleViewCells();
    EXPECT_EQ(cells.locate(Vec3(0.5, 0.5, 0.5)), 0u);
    EXPECT_EQ(cells.locate(Vec3(2.0, 0.5, 0.5)), 1u);
    EXPECT_EQ(cells.locate(Vec3(1.5, 0.5, 0.5)), 0u); // on the shared face: the first
    EXPECT_EQ(cells.locate(Vec3(3.0, 1.0, 1.0)), 1u); // a corner belongs to its box
    EXPECT_EQ(cells.locate(Vec3(3.0000001, 0.5, 0.5)), NoCell);
    EXPECT_EQ(cells.locate(Vec3(0.5, 0.5, -0.25)), NoCell);
    EXPECT_EQ(ViewCellPvs().locate(Vec3(0.0)), NoCell);

    ViewCellPvs thin;
    thin.cells = {Aabb({0.5, 0.25, 0.5}, {0.5, 0.75, 0.5})};
    EXPECT_EQ(thin.locate(Vec3(0.5, 0.5, 0.5)), 0u);
    EXPECT_EQ(thin.locate(Vec3(0.5, 0.8, 0.5)), NoCell);
}
