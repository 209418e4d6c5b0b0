// SPDX-License-Identifier: MIT
// Whether a region of eyes lies inside a union of view cells (src/multifocal/BoxCover.h).
#include "multifocal/BoxCover.h"

#include <gtest/gtest.h>

using namespace osgVis::core;

TEST(BoxCover, AUnionCoversWhatLiesInItsPiecesAndNotAGapOrAnOverhang)
{
    const std::vector<Aabb> cells{Aabb(Vec3(0, 0, 0), Vec3(4, 4, 2)), Aabb(Vec3(4, 0, 0), Vec3(8, 4, 2))};
    EXPECT_TRUE(boxCoveredBy(Aabb(Vec3(3, 1, 0.5), Vec3(5, 3, 1.5)), cells)); // across the shared face
    EXPECT_TRUE(boxCoveredBy(Aabb(Vec3(0, 0, 0), Vec3(8, 4, 2)), cells));     // the whole union, closed
    EXPECT_FALSE(boxCoveredBy(Aabb(Vec3(3, 1, 0.5), Vec3(9, 3, 1.5)), cells)); // past the end
    EXPECT_FALSE(boxCoveredBy(Aabb(Vec3(3, 3, 0.5), Vec3(5, 5, 1.5)), cells)); // past the side
    // An L of three cells leaves one corner out of its bounding box.
    const std::vector<Aabb> ell{Aabb(Vec3(0, 0, 0), Vec3(4, 4, 2)), Aabb(Vec3(4, 0, 0), Vec3(8, 4, 2)),
                                Aabb(Vec3(0, 4, 0), Vec3(4, 8, 2))};
    EXPECT_FALSE(boxCoveredBy(Aabb(Vec3(3, 3, 0.5), Vec3(5, 5, 1.5)), ell));
    EXPECT_TRUE(boxCoveredBy(Aabb(Vec3(3, 3, 0.5), Vec3(4, 5, 1.5)), ell));
    // A flat box on a cell's face.
    EXPECT_TRUE(boxCoveredBy(Aabb(Vec3(1, 1, 2), Vec3(2, 2, 2)), cells));
    EXPECT_FALSE(boxCoveredBy(Aabb(Vec3(1, 1, 0.5), Vec3(2, 2, 1.5)), {}));
}
