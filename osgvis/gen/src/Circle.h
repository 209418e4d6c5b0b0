// SPDX-License-Identifier: MIT
#pragma once
// Points on circles without libm: std::cos and std::sin are not specified to the last bit, and the
// generator promises the same bytes for the same seed on every IEEE-754 machine. The angle is given in
// turns (1 = 360°), reduced exactly to an eighth of a turn and evaluated by a Taylor polynomial with
// + − × only.
#include <osg/Vec2d>
#include <osg/Vec3d>

namespace osgVis::gen
{
// (cos 2πt, sin 2πt) for any finite t, each within 2e-16 of the exact value for t reduced to [0, 1)
// (a reduction that rounds only outside [0, 1)).
osg::Vec2d unitCircle(double turns);

// Unit vector perpendicular to the unit vector `axis`, at `turns` around it (counter-clockwise seen
// from the axis' tip). Turn 0 lies along (z, or x when the axis is nearly vertical) × axis.
osg::Vec3d aroundAxis(const osg::Vec3d& axis, double turns);
} // namespace osgVis::gen
