// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Whether a box lies inside a union of boxes (closed): a region of eyes inside the union of baked
/// view cells may take the union of their PVS, since each cell's PVS holds for every eye in it.
#include <osgVis/core/geometry/Aabb.h>

#include <vector>

namespace osgVis::core
{
/// Exact: the planes of every box split `box` into pieces each inside or outside every box, so
/// each piece's centre decides for the whole piece. Cost grows with the cube of boxes.size().
bool boxCoveredBy(const Aabb& box, const std::vector<Aabb>& boxes);
} // namespace osgVis::core
