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
    // polygons[0, polygonCount()) are this frame's; the rest are kept so their buffers serve the
    // next critical frame (a warm frame allocates nothing).
    std::vector<ScreenPolygon> polygons;
    std::vector<std::uint32_t> groupStart; // group g = polygons[groupStart[g], groupStart[g+1])
    // Per group: the eye's freedom δ for which its image moves by at most the shift (from its
    // nearest point), and its bounding rectangle in mask coordinates.
    std::vector<double> groupDelta;
    std::vector<glm::dvec4> groupRect; // x0, y0, x1, y1
    // Per group: its rasterization work, Σ over its polygons of the 8 × 8 tiles their bounding
    // rectangles reach, plus one per polygon (the module's work measure, docs/mask.md "Budget").
    std::vector<std::uint64_t> groupWork;
    std::size_t groupCount() const { return groupStart.empty() ? 0 : groupStart.size() - 1; }
    std::size_t polygonCount() const { return groupStart.empty() ? 0 : groupStart.back(); }

    // Per occluder polygon (indexed like the module's polygon list), valid where `mark` equals
    // `frame`: a new frame invalidates them all at once, without clearing.
    struct PolygonState
    {
        std::uint32_t mark = 0;
        std::int8_t facing = 0;  // from every eye of the ball: +1 front, -1 back, 0 unusable
        bool emitted = false;    // made it to the mask this frame
        std::uint32_t component = ~0u;
        double delta = 0.0;
    };
    std::vector<PolygonState> state;
    std::uint32_t frame = 0;
    std::vector<std::uint32_t> order, stack, starts; // polygons by component; the search's stack
    std::vector<std::uint32_t> across;      // per emitted edge: the polygon across it in its group
    std::vector<std::uint32_t> acrossStart; // per emitted polygon: its first edge in `across`
    std::uint64_t emittedWork = 0;          // work of the polygon emitted last (emitPolygon)
    // A polygon being clipped: eye-space vertices and, per edge, the polygon across it in the group.
    struct ClippedPolygon
    {
        std::vector<Vec3> vertices;
        std::vector<std::uint32_t> neighbour;
    };
    ClippedPolygon work, spare;
};

// `selected` are indices into `polygons`. `nearDepth` is the clipping depth; `shift` the image
// shift Δ (mask pixels) that fixes each polygon's δ from its nearest point. A polygon whose plane
// passes within its δ of the eye is left out. Deterministic; allocates nothing once `out` has served
// as many polygons and vertices.
void buildMaskGroups(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& selected,
                     const MaskProjection& projection, double nearDepth, double shift, MaskGroups& out);
} // namespace osgVis::core
