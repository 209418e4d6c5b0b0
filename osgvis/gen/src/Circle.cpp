// SPDX-License-Identifier: MIT
#include "Circle.h"

#include <cmath>
#include <utility>

namespace osgVis::gen
{
namespace
{
constexpr double halfPi = 1.5707963267948966;

// Taylor series in Horner form, |x| <= π/4: the first omitted terms are below 1e-16 of the result.
double sinNear0(double x)
{
    const double x2 = x * x;
    double p = 1.0 / 355687428096000.0; // 1/17!
    for (double d : {-1.0 / 1307674368000.0, 1.0 / 6227020800.0, -1.0 / 39916800.0, 1.0 / 362880.0, -1.0 / 5040.0,
                     1.0 / 120.0, -1.0 / 6.0, 1.0})
        p = p * x2 + d;
    return p * x;
}

double cosNear0(double x)
{
    const double x2 = x * x;
    double p = -1.0 / 6402373705728000.0; // -1/18!
    for (double d : {1.0 / 20922789888000.0, -1.0 / 87178291200.0, 1.0 / 479001600.0, -1.0 / 3628800.0, 1.0 / 40320.0,
                     -1.0 / 720.0, 1.0 / 24.0, -1.0 / 2.0})
        p = p * x2 + d;
    return p * x2 + 1.0;
}
} // namespace

osg::Vec2d unitCircle(double turns)
{
    // note: for turns in [0, 1) the reduction is exact (floor, × 4 and the subtractions), so only the
    // polynomial rounds.
    const double quarters = (turns - std::floor(turns)) * 4.0;
    int quadrant = int(quarters);
    const double f = quarters - quadrant;
    quadrant &= 3;
    const bool folded = f > 0.5; // cos x = sin(π/2 − x) keeps the argument within π/4
    const double x = (folded ? 1.0 - f : f) * halfPi;
    double c = cosNear0(x), s = sinNear0(x);
    if (folded)
        std::swap(c, s);
    switch (quadrant)
    {
    case 0:
        return {c, s};
    case 1:
        return {-s, c};
    case 2:
        return {-c, -s};
    default:
        return {s, -c};
    }
}

osg::Vec3d aroundAxis(const osg::Vec3d& axis, double turns)
{
    const osg::Vec3d helper = std::abs(axis.z()) < 0.9 ? osg::Vec3d(0.0, 0.0, 1.0) : osg::Vec3d(1.0, 0.0, 0.0);
    osg::Vec3d u = helper ^ axis;
    u.normalize();
    const osg::Vec3d v = axis ^ u; // u × v = axis: counter-clockwise seen from the tip
    const osg::Vec2d cs = unitCircle(turns);
    return u * cs.x() + v * cs.y();
}
} // namespace osgVis::gen
