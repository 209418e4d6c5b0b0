// SPDX-License-Identifier: MIT
// The small dense LP behind the portal-stabbing tests: exact optima of textbook problems,
// infeasible, unbounded and cycling-prone (degenerate) cases, equality rows and variable bounds.
#include <osgVis/core/geometry/SmallLp.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace osgVis::core;

TEST(SmallLp, TextbookOptimum)
{
    // Chvátal's first example: max 5x1 + 4x2 + 3x3, optimum 13 at (2, 0, 1).
    SmallLp lp;
    lp.reset(3);
    for (int i = 0; i < 3; ++i)
        lp.setBounds(i, 0.0, SmallLp::Infinity);
    lp.setObjective(0, 5);
    lp.setObjective(1, 4);
    lp.setObjective(2, 3);
    const double r0[3] = {2, 3, 1}, r1[3] = {4, 1, 2}, r2[3] = {3, 4, 2};
    lp.addLessEqual(r0, 5);
    lp.addLessEqual(r1, 11);
    lp.addLessEqual(r2, 8);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.objectiveValue(), 13.0, 1e-12);
    EXPECT_NEAR(lp.upperBound(), 13.0, 1e-12); // the duals (1, 0, 1) prove it
    EXPECT_NEAR(lp.solution(0), 2.0, 1e-12);
    EXPECT_NEAR(lp.solution(1), 0.0, 1e-12);
    EXPECT_NEAR(lp.solution(2), 1.0, 1e-12);
}

TEST(SmallLp, InfeasibleOriginNeedsFirstPhase)
{
    // max -x - y s.t. x + y >= 3, x <= 2, y <= 2 (free variables): optimum -3.
    SmallLp lp;
    lp.reset(2);
    lp.setObjective(0, -1);
    lp.setObjective(1, -1);
    const double sum[2] = {1, 1}, onlyX[2] = {1, 0}, onlyY[2] = {0, 1};
    lp.addGreaterEqual(sum, 3);
    lp.addLessEqual(onlyX, 2);
    lp.addLessEqual(onlyY, 2);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.objectiveValue(), -3.0, 1e-12);
    EXPECT_NEAR(lp.solution(0) + lp.solution(1), 3.0, 1e-12);
}

TEST(SmallLp, Infeasible)
{
    SmallLp lp;
    lp.reset(2);
    lp.setBounds(0, 0, 1);
    lp.setBounds(1, 0, 1);
    lp.setObjective(0, 1);
    const double sum[2] = {1, 1};
    lp.addGreaterEqual(sum, 2.5);
    EXPECT_EQ(lp.maximize(), SmallLp::Status::Infeasible);

    lp.reset(1);
    lp.setBounds(0, 2, 1);
    EXPECT_EQ(lp.maximize(), SmallLp::Status::Infeasible);
}

TEST(SmallLp, Unbounded)
{
    SmallLp lp;
    lp.reset(2);
    lp.setBounds(0, 0, SmallLp::Infinity);
    lp.setObjective(0, 1);
    lp.setObjective(1, 1);
    const double diff[2] = {1, -1};
    lp.addLessEqual(diff, 1);
    const double onlyY[2] = {0, 1};
    lp.addGreaterEqual(onlyY, -4);
    EXPECT_EQ(lp.maximize(), SmallLp::Status::Unbounded);

    // Unbounded below in a free variable is fine when the objective pushes the other way.
    lp.reset(1);
    lp.setObjective(0, 1);
    const double one[1] = {1};
    lp.addLessEqual(one, 7);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.solution(0), 7.0, 1e-12);
}

TEST(SmallLp, DegenerateCyclingExample)
{
    // Beale's example, which cycles under the largest-coefficient rule without anti-cycling:
    // max 3/4 x4 - 20 x5 + 1/2 x6 - 6 x7, optimum 5/4 at x4 = 1, x6 = 1 (first rows degenerate
    // at the origin).
    SmallLp lp;
    lp.reset(4);
    for (int i = 0; i < 4; ++i)
        lp.setBounds(i, 0.0, SmallLp::Infinity);
    lp.setObjective(0, 0.75);
    lp.setObjective(1, -20);
    lp.setObjective(2, 0.5);
    lp.setObjective(3, -6);
    const double r0[4] = {0.25, -8, -1, 9}, r1[4] = {0.5, -12, -0.5, 3}, r2[4] = {0, 0, 1, 0};
    lp.addLessEqual(r0, 0);
    lp.addLessEqual(r1, 0);
    lp.addLessEqual(r2, 1);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.objectiveValue(), 1.25, 1e-12);
    EXPECT_NEAR(lp.solution(0), 1.0, 1e-12);
    EXPECT_NEAR(lp.solution(1), 0.0, 1e-12);
    EXPECT_NEAR(lp.solution(3), 0.0, 1e-12);
    EXPECT_NEAR(lp.solution(2), 1.0, 1e-12);
}

TEST(SmallLp, ManyRedundantRowsThroughOneVertex)
{
    // 200 tangent rows of the unit disc at angles around (1,1)/sqrt2, plus 50 copies of the
    // same row: highly degenerate at the optimum. max x + y = sqrt(2).
    SmallLp lp;
    lp.reset(2);
    lp.setObjective(0, 1);
    lp.setObjective(1, 1);
    for (int i = 0; i < 200; ++i)
    {
        const double angle = 6.283185307179586 * i / 200.0;
        const double row[2] = {std::cos(angle), std::sin(angle)};
        lp.addLessEqual(row, 1.0);
    }
    const double diagonal[2] = {std::sqrt(0.5), std::sqrt(0.5)};
    for (int i = 0; i < 50; ++i)
        lp.addLessEqual(diagonal, 1.0);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.objectiveValue(), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(lp.upperBound(), std::sqrt(2.0), 1e-12);
}

TEST(SmallLp, EqualityRowsAndBounds)
{
    // max x + 2y + 3z, x + y + z = 1, x - y = 0, bounds z in [0, 0.5], x, y >= 0:
    // z = 0.5, x = y = 0.25: 0.25 + 0.5 + 1.5 = 2.25.
    SmallLp lp;
    lp.reset(3);
    lp.setBounds(0, 0, SmallLp::Infinity);
    lp.setBounds(1, 0, SmallLp::Infinity);
    lp.setBounds(2, 0, 0.5);
    lp.setObjective(0, 1);
    lp.setObjective(1, 2);
    lp.setObjective(2, 3);
    const double sum[3] = {1, 1, 1}, diff[3] = {1, -1, 0};
    lp.addEqual(sum, 1);
    lp.addEqual(diff, 0);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.objectiveValue(), 2.25, 1e-12);
    EXPECT_NEAR(lp.upperBound(), 2.25, 1e-12);
    EXPECT_NEAR(lp.solution(0), 0.25, 1e-12);
    EXPECT_NEAR(lp.solution(1), 0.25, 1e-12);
    EXPECT_NEAR(lp.solution(2), 0.5, 1e-12);

    // Upper-bounded only, and a fixed variable.
    lp.reset(2);
    lp.setBounds(0, -SmallLp::Infinity, -3);
    lp.setBounds(1, 4, 4);
    lp.setObjective(0, 1);
    lp.setObjective(1, 1);
    ASSERT_EQ(lp.maximize(), SmallLp::Status::Optimal);
    EXPECT_NEAR(lp.objectiveValue(), 1.0, 1e-12);
}

TEST(SmallLp, RandomProblemsMatchVertexEnumeration)
{
    // Random 2-variable problems inside a box: the optimum equals the best feasible vertex of
    // all pairs of constraint lines (brute force).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    for (int trial = 0; trial < 300; ++trial)
    {
        const int rows = 3 + trial % 8;
        std::vector<std::array<double, 3>> lines; // a, b, rhs of a x + b y <= rhs
        for (int i = 0; i < rows; ++i)
            lines.push_back({coefficient(rng), coefficient(rng), coefficient(rng) * 0.5});
        lines.push_back({1, 0, 1});
        lines.push_back({-1, 0, 1});
        lines.push_back({0, 1, 1});
        lines.push_back({0, -1, 1});
        const double cx = coefficient(rng), cy = coefficient(rng);
        SmallLp lp;
        lp.reset(2);
        lp.setObjective(0, cx);
        lp.setObjective(1, cy);
        for (const auto& l : lines)
            lp.addLessEqual(l.data(), l[2]);
        const SmallLp::Status status = lp.maximize();

        double best = -1e300;
        for (std::size_t i = 0; i < lines.size(); ++i)
            for (std::size_t j = i + 1; j < lines.size(); ++j)
            {
                const double det = lines[i][0] * lines[j][1] - lines[i][1] * lines[j][0];
                if (std::fabs(det) < 1e-12)
                    continue;
                const double x = (lines[i][2] * lines[j][1] - lines[i][1] * lines[j][2]) / det;
                const double y = (lines[i][0] * lines[j][2] - lines[i][2] * lines[j][0]) / det;
                bool feasible = true;
                for (const auto& l : lines)
                    feasible = feasible && l[0] * x + l[1] * y <= l[2] + 1e-9;
                if (feasible)
                    best = std::max(best, cx * x + cy * y);
            }
        if (best == -1e300)
        {
            EXPECT_EQ(status, SmallLp::Status::Infeasible) << trial;
        }
        else
        {
            ASSERT_EQ(status, SmallLp::Status::Optimal) << trial;
            EXPECT_NEAR(lp.objectiveValue(), best, 1e-9) << trial;
            EXPECT_GE(lp.upperBound(), best - 1e-12) << trial;
            EXPECT_NEAR(lp.upperBound(), best, 1e-9) << trial;
        }
    }
}
