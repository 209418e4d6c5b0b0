// SPDX-License-Identifier: MIT
#pragma once
// Ray casting by brute force over every triangle of a scene, sharing no code with apps/common's
// RayScene: the tests' independent measure of "inside solid geometry".
#include <osgVis/core/scene/Scene.h>

#include <random>

namespace osgVis::test
{
// Möller–Trumbore over every triangle: +1 when every triangle at the nearest hit along the ray is
// seen from its back (the ray runs along its counter-clockwise normal), 0 when one is seen from the
// front (a surface covered both ways is two-sided), -1 nothing.
int firstHitIsBack(const core::Scene& scene, const core::Vec3& origin, const core::Vec3& direction);
// 64 random directions (not the walk's Fibonacci set): more than half meet a back face first.
bool insideByBruteForce(const core::Scene& scene, const core::Vec3& eye, std::mt19937& random);
} // namespace osgVis::test
