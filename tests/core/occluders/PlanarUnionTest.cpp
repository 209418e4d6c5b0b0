// SPDX-License-Identifier: MIT
// The planar union of coplanar convex pieces (src/occluders/PlanarUnion.h): pieces lie inside the
// union and cover it, touching or overlapping inputs come out as few convex pieces, corners name
// the input vertices or edges they come from.
#include "occluders/PlanarUnion.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

using namespace osgVis::core;

namespace
{
UnionInput box(double x0, double y0, double x1, double y1, std::uint32_t firstId)
{
    return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {firstId, firstId + 1, firstId + 2, firstId + 3}};
}

bool inside(const Outline2& convex, const Point2& p, double slack = 0.0)
{
    for (std::size_t i = 0; i < convex.size(); ++i)
        if (cross2(convex[i], convex[(i + 1) % convex.size()], p) < -slack)
            return false;
    return true;
}

Outline2 outlineOf(const UnionPiece& piece)
{
    Outline2 o;
    for (const UnionCorner& c : piece.corners)
        o.push_back(c.point);
    return o;
}

double totalArea(const std::vector<UnionPiece>& pieces)
{
    return std::accumulate(pieces.begin(), pieces.end(), 0.0, [](double sum, const UnionPiece& p) { return sum + p.area; });
}
} // namespace

TEST(PlanarUnion, AbuttingAndTJunctionedRectanglesBecomeOneRectangle)
{
    // A wall of three faces: the bottom one spans both upper ones, so its top edge has a T-vertex.
    const std::vector<UnionInput> inputs{box(0, 0, 2, 1, 0), box(0, 1, 1, 2, 4), box(1, 1, 2, 2, 8)};
    const std::vector<UnionPiece> pieces = planarUnion(inputs, {});
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_DOUBLE_EQ(pieces[0].area, 4.0);
    EXPECT_EQ(pieces[0].corners.size(), 4u);
    EXPECT_EQ(pieces[0].sources, (std::vector<std::uint32_t>{0, 1, 2}));
    for (const UnionCorner& c : pieces[0].corners)
        EXPECT_NE(c.id, NoUnionId) << "every corner of the square is an input vertex";
}

TEST(PlanarUnion, AnLShapeGivesTwoConvexPiecesCoveringItExactly)
{
    const std::vector<UnionInput> inputs{box(0, 0, 2, 1, 0), box(0, 1, 1, 2, 4)};
    const std::vector<UnionPiece> pieces = planarUnion(inputs, {});
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(totalArea(pieces), 3.0, 1e-12);
    for (const UnionPiece& p : pieces)
        for (const UnionCorner& c : p.corners)
            EXPECT_TRUE(inside(inputs[0].points, c.point) || inside(inputs[1].points, c.point));
}

TEST(PlanarUnion, AGapIsBridgedOnlyWhenNarrowerThanTheGapAllowed)
{
    const std::vector<UnionInput> inputs{box(0, 0, 1, 1, 0), box(0, 1.001, 1, 2, 4)};
    EXPECT_EQ(planarUnion(inputs, {}).size(), 2u);
    PlanarUnionOptions wide;
    wide.gap = 0.01;
    const std::vector<UnionPiece> bridged = planarUnion(inputs, wide);
    ASSERT_EQ(bridged.size(), 1u);
    EXPECT_NEAR(bridged[0].area, 2.0, 1e-12);
}

TEST(PlanarUnion, OverlappingTrianglesPiecesLieInTheUnionAndCoverIt)
{
    // Random overlapping triangles (a badly drawn fan, as OSG's bsp plugin gives some faces):
    // every piece point sampled lies in some input, and the pieces cover what the inputs do.
    // (Pieces may overlap where two inputs meet at one end of a slab only; occluders may.)
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(0.0, 4.0), unit(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial)
    {
        std::vector<UnionInput> inputs;
        for (std::uint32_t k = 0; k < 6; ++k)
        {
            Point2 a(coordinate(random), coordinate(random)), b(coordinate(random), coordinate(random)),
                c(coordinate(random), coordinate(random));
            if (cross2(a, b, c) < 0.0)
                std::swap(b, c);
            if (cross2(a, b, c) < 1e-3)
                continue;
            inputs.push_back({{a, b, c}, {3 * k, 3 * k + 1, 3 * k + 2}});
        }
        const std::vector<UnionPiece> pieces = planarUnion(inputs, {});
        const auto inInput = [&](const Point2& p)
        {
            for (const UnionInput& in : inputs)
                if (inside(in.points, p, 1e-12))
                    return true;
            return false;
        };
        int covered = 0, inUnion = 0;
        for (int s = 0; s < 4000; ++s)
        {
            const Point2 p(4.0 * unit(random), 4.0 * unit(random));
            bool in = false;
            for (const UnionPiece& piece : pieces)
                in = in || inside(outlineOf(piece), p, -1e-12);
            if (in)
            {
                EXPECT_TRUE(inInput(p)) << "piece point outside every input, trial " << trial;
            }
            covered += in ? 1 : 0;
            inUnion += inInput(p) ? 1 : 0;
        }
        // Exact but for the samples that land on an edge.
        EXPECT_GE(covered, 0.995 * inUnion) << "trial " << trial;
        for (const UnionPiece& piece : pieces)
            for (const UnionCorner& c : piece.corners)
                EXPECT_TRUE(c.id != NoUnionId || (c.from != NoUnionId && c.t > 0.0 && c.t < 1.0));
    }
}

TEST(PlanarUnion, TooManyInputsAreLeftAlone)
{
    std::vector<UnionInput> inputs;
    for (std::uint32_t k = 0; k < 5; ++k)
        inputs.push_back(box(k, 0, k + 1, 1, 4 * k));
    PlanarUnionOptions few;
    few.maxInputs = 4;
    EXPECT_TRUE(planarUnion(inputs, few).empty());
    const std::vector<UnionPiece> one = planarUnion(inputs, {});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_DOUBLE_EQ(one[0].area, 5.0);
}
