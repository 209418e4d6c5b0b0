// SPDX-License-Identifier: MIT
#pragma once
// Views and regions for tests of region answers (ViewRegion, volume PVS): 90° cube faces around an
// eye, a region of eyes around a point, and the objects the ray-cast reference sees from sampled
// eyes of a region (its corners, centre and random points) that an answer lacks.
#include "RayCastVisibility.h"

#include <osgVis/core/scene/ViewRegion.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <string>
#include <vector>

namespace osgVis::test
{
constexpr double Near = 0.1;

core::Mat4 perspective(double fovyDegrees, double aspect);
core::View lookFrom(const core::Vec3& eye, const core::Vec3& direction, const core::Vec3& up, double fovy = 60.0,
                    std::uint32_t width = 96, std::uint32_t height = 72);
// A view of `fovy` degrees vertically, width/height wide, near plane at `nearPlane`, depth buffer of
// `depthBits`, whose ray through `fraction` of the way from the frame's centre to its upper right
// corner passes through `target`: a wide view's steep rays, for the depth-tie margins.
core::View lookThroughCorner(const core::Vec3& eye, const core::Vec3& target, double fovy, std::uint32_t width,
                             std::uint32_t height, double nearPlane, double fraction, std::uint32_t depthBits);
// The six 90° cube faces around `eye`: together they see every direction.
std::vector<core::View> cubeFaces(const core::Vec3& eye);
core::ViewRegion regionAround(const core::Vec3& center, const core::Vec3& halfExtent);
// One line per object seen from a sampled eye of the region that `answer` lacks; empty when none.
std::string missedFromRegion(const RayCastVisibility& rays, const core::Scene& scene, const core::ViewRegion& region,
                             const core::VisibleSet& answer, int randomEyes = 4);
} // namespace osgVis::test
