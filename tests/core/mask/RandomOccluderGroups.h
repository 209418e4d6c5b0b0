// SPDX-License-Identifier: MIT
#pragma once
// Random occluder groups for the mask rasterizer tests: convex polygons (hulls of random points),
// cut along random chords into pieces that share the chords (one group, random windings), and
// random depth planes (perspective mostly, orthographic a quarter of the time).
#include <osgVis/core/mask/MaskRasterizer.h>

#include <glm/vec2.hpp>

#include <random>
#include <vector>

namespace maskTest
{
// Convex hull (counter-clockwise, no collinear points) of 3..12 random points around a centre in
// [-10, size + 10]².
std::vector<glm::dvec2> randomConvexPolygon(std::mt19937& random, double size);

osgVis::core::DepthPlane randomPlane(std::mt19937& random, glm::dvec2 around);

// `hull` cut `cuts` times along chords (shared edges of the pieces), each piece in a random winding,
// all on `plane`.
std::vector<osgVis::core::ScreenPolygon> randomCutGroup(std::mt19937& random, const std::vector<glm::dvec2>& hull,
                                                        int cuts, const osgVis::core::DepthPlane& plane);
} // namespace maskTest
