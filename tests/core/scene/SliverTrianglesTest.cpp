// SPDX-License-Identifier: MIT
// Sliver triangles (docs/occluders.md, "Sliver triangles"): three distinct corners on one line up to
// their float storage are slivers; a repeated corner, a thin triangle modelled on purpose and a
// non-finite one are not.
#include <osgVis/core/scene/Scene.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace osgVis::core;

TEST(SliverTriangles, DistinctCornersOnOneLineUpToFloatStorage)
{
    EXPECT_TRUE(isSliverTriangle({Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(2, 0, 0)})) << "a fan's straight corner";
    EXPECT_TRUE(isSliverTriangle({Vec3f(0, 0, 0), Vec3f(10, 0, 0), Vec3f(5, 5e-6f, 0)})) << "below 1e-6 of the edge";
    // Corners meant to lie on the line y = x / 3 far from the origin, each rounded to float.
    const float far = 98304.0f;
    EXPECT_TRUE(isSliverTriangle({Vec3f(far, far / 3, 0), Vec3f(far + 1, (far + 1) / 3, 0), Vec3f(far + 2, (far + 2) / 3, 0)}));
}

TEST(SliverTriangles, RepeatedCornersThinModelsAndNonFiniteOnesAreNot)
{
    EXPECT_FALSE(isSliverTriangle({Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 0, 0)})) << "draws nothing";
    EXPECT_FALSE(isSliverTriangle({Vec3f(0, 0, 0), Vec3f(10, 0, 0), Vec3f(5, 1e-3f, 0)})) << "thin on purpose";
    EXPECT_FALSE(isSliverTriangle({Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0)}));
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(isSliverTriangle({Vec3f(0, 0, 0), Vec3f(inf, 0, 0), Vec3f(2, 0, 0)}));
}

TEST(SliverTriangles, AListHasOneWhenAnyTriangleIs)
{
    std::vector<Triangle> triangles{{Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0)},
                                    {Vec3f(0, 0, 1), Vec3f(1, 0, 1), Vec3f(0, 1, 1)}};
    EXPECT_FALSE(hasSliverTriangle(triangles.data(), triangles.size()));
    EXPECT_FALSE(hasSliverTriangle(nullptr, 0));
    triangles.push_back({Vec3f(0, 0, 2), Vec3f(0, 0.5f, 2), Vec3f(0, 1, 2)});
    EXPECT_TRUE(hasSliverTriangle(triangles.data(), triangles.size()));
    EXPECT_FALSE(hasSliverTriangle(triangles.data(), 2));
}
