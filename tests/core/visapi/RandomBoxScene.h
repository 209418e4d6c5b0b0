// SPDX-License-Identifier: MIT
#pragma once
// A seeded scene of random boxes and random perspective views over it, shared by the C interface
// and plugin tests.
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/View.h>

#include <vector>

namespace osgVis::test
{
// `count` boxes (0.1 to 10 wide) in [-100, 100]^3, each with its 12 triangles.
core::Scene randomBoxScene(unsigned seed, int count);
// `count` views: eyes in [-120, 120]^3 looking at points in [-50, 50]^3, 30 to 90 degree fields of
// view, near 0.1, far 50 to 300.
std::vector<core::View> randomViews(unsigned seed, int count);
} // namespace osgVis::test
