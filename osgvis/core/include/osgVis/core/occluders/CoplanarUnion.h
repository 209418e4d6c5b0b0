// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Larger occluders from coplanar polygons of different objects: two wall pieces that abut or
/// overlap in one plane (adjacent rooms' walls, a wall and its neighbour's corner) hide together
/// what neither hides alone, but share no edge to fuse through. Where their union is exactly a
/// convex polygon, that union is an occluder of its own.
#include <osgVis/core/occluders/OccluderPolygon.h>

#include <vector>

namespace osgVis::core
{
// The unions (of two or more of `polygons`) that are convex, found greedily per plane. Only
// polygons facing the same way with the same sidedness combine; the union covers exactly the
// area of its parts (no gap is ever bridged). The originals are not repeated in the result.
std::vector<OccluderPolygon> coplanarUnions(const std::vector<OccluderPolygon>& polygons, double sceneSize);
} // namespace osgVis::core
