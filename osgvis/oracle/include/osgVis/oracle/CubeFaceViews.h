// SPDX-License-Identifier: MIT
#pragma once

#include <osg/Matrixd>
#include <osg/Vec3d>

#include <array>

namespace osgVis::oracle
{
// The six 90° views that together see every direction from an eye: looking along +x, −x, +y, −y, +z,
// −z (z up for the horizontal four, +y up for the vertical two). With cubeFaceProjection, every
// direction falls in exactly one face's image, edges shared, so a square image per face samples the
// whole sphere around the eye.
std::array<osg::Matrixd, 6> cubeFaceViews(const osg::Vec3d& eye);

// Square perspective frustum of exactly 90° (left/right/bottom/top = ∓near), the given clip planes.
osg::Matrixd cubeFaceProjection(double zNear, double zFar);
} // namespace osgVis::oracle
