// SPDX-License-Identifier: MIT
#pragma once
// The union of convex polygons lying in one plane, cut into few large convex pieces: what a wall
// made of many faces (split by the modeller or a BSP compiler, overlapping, with T-junctions,
// spread over several drawables) covers, as occluders that cover it whole. docs/occluders.md
// derives why every piece lies inside the union.
//
// Method: a slab decomposition (the trapezoidal decomposition of the computational-geometry
// textbooks, de Berg et al., "Computational Geometry", ch. 6, cut along vertical lines through
// every vertex): within a slab each convex input covers one interval between two of its edges,
// overlapping intervals join, and each joined interval is a trapezoid bounded by input edges.
// Trapezoids continuing the same straight boundaries across slabs join into one, then pieces
// whose union is exactly convex join greedily (Hertel & Mehlhorn's idea of removing diagonals,
// applied to the trapezoids).
#include "Outline2.h"

#include <cstdint>
#include <vector>

namespace osgVis::core
{
constexpr std::uint32_t NoUnionId = ~std::uint32_t(0);

/// One input polygon: convex, counter-clockwise, with an id per vertex (the caller's vertex ids).
struct UnionInput
{
    Outline2 points;
    std::vector<std::uint32_t> ids;
};

/// A corner of a piece: an input vertex (`id`), or the point at parameter `t` of the input edge
/// from vertex `from` to vertex `to` (id is NoUnionId then).
struct UnionCorner
{
    Point2 point;
    std::uint32_t id = NoUnionId;
    std::uint32_t from = NoUnionId, to = NoUnionId;
    double t = 0.0;
};

struct UnionPiece
{
    std::vector<UnionCorner> corners;  ///< convex, counter-clockwise
    std::vector<std::uint32_t> sources; ///< the inputs it covers part of, ascending
    double area = 0.0;
};

struct PlanarUnionOptions
{
    /// Intervals closer than this join (a crack narrower than the welding tolerance is closed,
    /// as welding closes it); 0 joins only what touches or overlaps.
    double gap = 0.0;
    std::size_t maxCorners = 32;
    /// Inputs beyond this are not united (the decomposition grows with inputs × slabs).
    std::size_t maxInputs = 1024;
};

/// Pieces covering the union of `inputs` (x is the slab direction: pick it along the walls'
/// edges). Empty when there are more inputs than options.maxInputs. Deterministic.
std::vector<UnionPiece> planarUnion(const std::vector<UnionInput>& inputs, const PlanarUnionOptions& options);
} // namespace osgVis::core
