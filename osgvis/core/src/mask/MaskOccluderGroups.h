// SPDX-License-Identifier: MIT
#pragma once
// Turns the critical frame's occluder polygons into rasterizer groups: polygons that face the eye
// the same way from every point of their δ-ball (δ from each polygon's nearest point), connected through shared edges, clipped to the
// near depth and the grown frame (clip edges become outline edges), projected to the mask.
// A polygon whose plane passes within δ of the eye could turn edge-on or flip inside the ball,
// so it is left out; so is a one-sided polygon seen from behind.
#include "MaskProjection.h"

#include <osgVis/core/occluders/OccluderPolygon.h>

#include <vector>

namespace osgVis::core
{
struct MaskGroups
{
    std::vector<ScreenPolygon> polygons;
    std::vector<std::uint32_t> groupStart; // group g = polygons[groupStart[g], groupStart[g+1])
    // Per group: the eye's freedom δ for which its image moves by at most the shift (from its
    // nearest point), and its bounding rectangle in mask coordinates.
    std::vector<double> groupDelta;
    std::vector<glm::dvec4> groupRect; // x0, y0, x1, y1
    std::size_t groupCount() const { return groupStart.empty() ? 0 : groupStart.size() - 1; }
};

// `selected` are indices into `polygons`. `nearDepth` is the clipping depth; `shift` the image
// shift Δ (mask pixels) that fixes each polygon's δ from its nearest point. A polygon whose plane
// passes within its δ of the eye is left out. Deterministic.
void buildMaskGroups(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& selected,
                     const MaskProjection& projection, double nearDepth, double shift, MaskGroups& out);
} // namespace osgVis::core
