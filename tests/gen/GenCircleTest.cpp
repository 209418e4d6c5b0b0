// SPDX-License-Identifier: MIT
// The generator's own cos/sin (no libm, so the same bytes everywhere): exact at the quarter turns,
// within 2e-16 of the true values elsewhere, and aroundAxis perpendicular and counter-clockwise.
#include "Circle.h"

#include <gtest/gtest.h>

#include <cmath>

using osgVis::gen::aroundAxis;
using osgVis::gen::unitCircle;

TEST(GenCircle, QuarterTurnsAreExact)
{
    EXPECT_EQ(unitCircle(0.0), osg::Vec2d(1.0, 0.0));
    EXPECT_EQ(unitCircle(0.25), osg::Vec2d(0.0, 1.0));
    EXPECT_EQ(unitCircle(0.5), osg::Vec2d(-1.0, 0.0));
    EXPECT_EQ(unitCircle(0.75), osg::Vec2d(0.0, -1.0));
    EXPECT_EQ(unitCircle(-0.25), osg::Vec2d(0.0, -1.0));
    EXPECT_EQ(unitCircle(3.0), osg::Vec2d(1.0, 0.0));
}

TEST(GenCircle, MatchesTheTrueCircle)
{
    const long double pi = 3.14159265358979323846264338327950288L;
    long double worst = 0.0L;
    for (int i = -3000; i <= 3000; ++i)
    {
        const double turns = i / 1009.0;
        const osg::Vec2d p = unitCircle(turns);
        // The reference starts from the same reduction to [0, 1) (which rounds for negative turns), so
        // only the polynomials compare.
        const double reduced = turns - std::floor(turns);
        const long double angle = 2.0L * pi * (long double)reduced;
        worst = std::max({worst, std::fabs(p.x() - std::cos(angle)), std::fabs(p.y() - std::sin(angle))});
    }
    EXPECT_LT(double(worst), 2e-16);
}

TEST(GenCircle, AroundAxisIsPerpendicularAndCounterClockwise)
{
    for (osg::Vec3d axis : {osg::Vec3d(0, 0, 1), osg::Vec3d(1, 0, 0), osg::Vec3d(0.6, 0.0, 0.8), osg::Vec3d(0, -1, 0)})
    {
        const osg::Vec3d a = aroundAxis(axis, 0.0), b = aroundAxis(axis, 0.25);
        EXPECT_NEAR(a.length(), 1.0, 1e-15);
        EXPECT_NEAR(a * axis, 0.0, 1e-15);
        EXPECT_NEAR(b * axis, 0.0, 1e-15);
        EXPECT_NEAR((a ^ b) * axis, 1.0, 1e-15); // a quarter turn on, seen from the axis' tip
    }
}
