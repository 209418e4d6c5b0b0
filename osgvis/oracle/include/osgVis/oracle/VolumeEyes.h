// SPDX-License-Identifier: MIT
#pragma once

#include <osg/BoundingBox>
#include <osg/Vec3d>

#include <cstdint>
#include <vector>

namespace osgVis::oracle
{
// Eye positions standing for an axis-aligned box of viewpoints: its 8 corners, its 6 face centres,
// then `interior` points drawn uniformly inside it from `seed` (std::mt19937_64, 53 bits a
// coordinate, so the same seed gives the same eyes everywhere). Repeated positions (a flat or point
// box) are listed once. Throws std::invalid_argument for an invalid box.
std::vector<osg::Vec3d> volumeEyes(const osg::BoundingBoxd& box, unsigned interior, std::uint32_t seed);
} // namespace osgVis::oracle
