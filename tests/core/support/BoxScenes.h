// SPDX-License-Identifier: MIT
#pragma once
// Scenes of axial boxes for core tests: box objects with their triangles, and a small city of
// blocks, buildings and street furniture.
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/View.h>

#include <string>
#include <vector>

namespace osgVis::test
{
// The 12 triangles of an axial box, counter-clockwise seen from outside.
std::vector<core::Triangle> boxTriangles(const core::Vec3& lo, const core::Vec3& hi);
core::Aabb boundsOf(const std::vector<core::Triangle>& triangles);
core::ObjectId addTriangles(core::Scene& scene, const std::vector<core::Triangle>& triangles, const std::string& name,
                            std::uint32_t flags = core::OBJECT_NONE);
core::ObjectId addBox(core::Scene& scene, const core::Vec3& lo, const core::Vec3& hi, const std::string& name,
                      std::uint32_t flags = core::OBJECT_NONE);

// The shell of a row of `rooms` rooms 4 m wide (x) and 4 m deep (y), 3 m tall: floor and ceiling
// slabs and the four outer walls, 0.2 m thick (the cell-portal tests put inner walls and doors in).
void addRoomRowShell(core::Scene& scene, int rooms);

// 6×6 blocks of 20×20 (streets 10 wide between them, street centres at x, y = -5 + 30·k), each block
// four buildings of 8×8 with 4-wide alleys and deterministic heights, and street furniture
// (1×1×1.5 boxes) along the kerbs.
struct City
{
    core::Scene scene;
    std::vector<core::ObjectId> buildings;
};

City makeCity();

// Six eyes walking up the city's street at x = 85 at a person's height, each turned a little more
// (-20° to +20° from looking along it), 320 × 240, 60° high: the budget tests' views.
std::vector<core::View> cityStreetViews();
} // namespace osgVis::test
