// SPDX-License-Identifier: MIT
#pragma once
// Internal to the tile rasterizer: the per-tile work on 8 × 8 pixels, once per instruction set
// (AVX2: a tile row is one vector; SSE2: two). Both are the same template (MaskTileKernelsImpl.h)
// over the same IEEE single-precision operations in the same order, with no fused multiply-add,
// so they agree bit for bit. Lane bit 8·r + j of a 64-bit mask is pixel (j, r) of the tile.
#include "MaskPolygonSetup.h"

#include <cstddef>
#include <cstdint>

namespace osgVis::core::maskraster
{
constexpr int TileSize = 8;

// The edges of one polygon a tile still has to test pixel by pixel. f0 is the edge function at the
// centre of the tile's pixel (0, 0); pixel (j, r) has f0 + ny·r + nx·j.
struct TileEdges
{
    std::size_t count = 0;
    float f0[MaxEdges], nx[MaxEdges], ny[MaxEdges], reach[MaxEdges], insideLimit[MaxEdges];
};

struct TileCoverage
{
    std::uint64_t touched = 0;   // every listed edge: f ≥ -reach
    std::uint64_t outside = 0;   // some listed edge: f < insideLimit
    std::uint64_t ambiguous = 0; // some listed edge within Ambiguity of ±reach: decide in double
};

// The largest depth of one polygon over each grown pixel of a tile: v = v0 + db·r + da·j is the
// corner value (smallest 1/depth, or largest depth), widened by margin = (|v| + spread)·rel + abs.
struct TileDepth
{
    float v0 = 0.0f, da = 0.0f, db = 0.0f, spread = 0.0f, absMargin = 0.0f;
    bool inverse = true;
};

struct TileKernels
{
    // Rows [rowBegin, rowEnd) only; other rows' bits stay zero.
    void (*coverage)(const TileEdges& edges, int rowBegin, int rowEnd, TileCoverage& out);
    // depth[8r + j] = max(depth[8r + j], polygon depth) where the lane bit is set.
    void (*depthMax)(const TileDepth& plane, int rowBegin, int rowEnd, std::uint64_t lanes, float* depth);
    // rows[r][j] = min(rows[r][j], depth[8r + j]) where the lane bit is set; returns the largest value
    // of the 64 after the merge and adds the number of lanes set with a finite depth to `covered`.
    float (*merge)(float* const rows[TileSize], std::uint64_t lanes, const float* depth, std::size_t& covered);
    // The same with one polygon's depths computed on the way (a tile only one polygon writes).
    float (*planeMerge)(float* const rows[TileSize], std::uint64_t lanes, const TileDepth& plane, std::size_t& covered);
};

// The relative depth margin of the tile kernels: it exceeds the float evaluation error of both the
// kernels and the reference (a few 2^-24 each, docs/mask.md), so no stored depth is nearer than the
// reference's.
constexpr float TileDepthRelativeMargin = 1.5e-6f;

const TileKernels& sse2TileKernels();
const TileKernels* avx2TileKernels(); // null where the compiler cannot target AVX2
} // namespace osgVis::core::maskraster
