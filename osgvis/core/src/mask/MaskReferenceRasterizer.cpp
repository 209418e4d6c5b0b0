// SPDX-License-Identifier: MIT
// The reference rasterizer of occluder groups into the occlusion mask (the "fully covered pixels
// only" mask of Wang, Agarwal & Har-Peled), pixel by pixel: the tile rasterizer (MaskRasterizer.cpp)
// is tested against it. Per polygon, signed edge distances decide for every
// pixel square (grown by the shrink) whether it touches the polygon (separating-axis test on the
// polygon's edge normals plus its bounding box, exact for a convex polygon and a square) and
// whether it lies inside each outline edge; a pixel is covered when it touches some polygon and
// no touched polygon has it beyond an outline edge.
//
// Precision: the inner loop runs in float, 4 pixels at a time. Each 4-pixel block starts from a
// value computed in double, so a lane's float error is ~1e-6 px near a threshold; lanes within
// 1e-4 px of any threshold are re-decided in double, so coverage is the double-precision answer.
// Depths are rounded away from the viewer by a relative margin that exceeds the float error.
#include "MaskPolygonSetup.h"
#include "MaskRasterPaths.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace osgVis::core
{
namespace
{
using namespace maskraster;

constexpr std::uint8_t Touched = 1;
constexpr std::uint8_t Vetoed = 2;
constexpr int Lanes = 4;
// Exceeds the float lanes' relative depth error (a few 2^-24) with room for the final rounding.
constexpr float DepthRelativeMargin = 1e-6f;

// One block of 4 pixels of a row, for one polygon: f0 per edge and v0 are the lane-0 values.
struct BlockInput
{
    const float* f0;
    const PolygonSetup* polygon;
    float v0;
};

struct BlockResult
{
    int touched = 0, outside = 0, ambiguous = 0; // lane bit masks
    alignas(16) float depth[Lanes];
};

void scalarBlock(const BlockInput& in, BlockResult& out)
{
    const PolygonSetup& s = *in.polygon;
    bool touched[Lanes] = {true, true, true, true};
    bool outside[Lanes] = {}, ambiguous[Lanes] = {};
    for (std::size_t e = 0; e < s.edgeCount; ++e)
    {
        const float negativeReach = -s.reachF[e];
        for (int j = 0; j < Lanes; ++j)
        {
            const float f = in.f0[e] + s.slope[e] * float(j);
            touched[j] = touched[j] && f >= negativeReach;
            outside[j] = outside[j] || f < s.insideLimit[e];
            ambiguous[j] = ambiguous[j] || std::fabs(std::fabs(f) - s.reachF[e]) < Ambiguity;
        }
    }
    out = BlockResult{};
    const float depthSlopeReach = float(Lanes) * std::fabs(s.depthSlope);
    for (int j = 0; j < Lanes; ++j)
    {
        out.touched |= int(touched[j]) << j;
        out.outside |= int(outside[j]) << j;
        out.ambiguous |= int(ambiguous[j]) << j;
        const float value = in.v0 + s.depthSlope * float(j);
        const float margin = (std::fabs(value) + depthSlopeReach) * DepthRelativeMargin + s.depthAbsMargin;
        if (s.inverse)
        {
            const float w = value - margin;
            out.depth[j] = w > 0.0f ? 1.0f / w : InfiniteDepth;
        }
        else
            out.depth[j] = value + margin;
    }
}

#ifdef __SSE2__
// The same operations as scalarBlock, four lanes at once (IEEE single precision either way).
void simdBlock(const BlockInput& in, BlockResult& out)
{
    const PolygonSetup& s = *in.polygon;
    const __m128 lanes = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f);
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 ambiguity = _mm_set1_ps(Ambiguity);
    __m128 touched = _mm_castsi128_ps(_mm_set1_epi32(-1));
    __m128 outside = _mm_setzero_ps(), ambiguous = _mm_setzero_ps();
    for (std::size_t e = 0; e < s.edgeCount; ++e)
    {
        const __m128 reach = _mm_set1_ps(s.reachF[e]);
        const __m128 f = _mm_add_ps(_mm_set1_ps(in.f0[e]), _mm_mul_ps(_mm_set1_ps(s.slope[e]), lanes));
        touched = _mm_and_ps(touched, _mm_cmpge_ps(f, _mm_set1_ps(-s.reachF[e])));
        outside = _mm_or_ps(outside, _mm_cmplt_ps(f, _mm_set1_ps(s.insideLimit[e])));
        const __m128 distance = _mm_sub_ps(_mm_andnot_ps(sign, f), reach);
        ambiguous = _mm_or_ps(ambiguous, _mm_cmplt_ps(_mm_andnot_ps(sign, distance), ambiguity));
    }
    out.touched = _mm_movemask_ps(touched);
    out.outside = _mm_movemask_ps(outside);
    out.ambiguous = _mm_movemask_ps(ambiguous);
    const float depthSlopeReach = float(Lanes) * std::fabs(s.depthSlope);
    const __m128 value = _mm_add_ps(_mm_set1_ps(in.v0), _mm_mul_ps(_mm_set1_ps(s.depthSlope), lanes));
    const __m128 margin = _mm_add_ps(_mm_mul_ps(_mm_add_ps(_mm_andnot_ps(sign, value), _mm_set1_ps(depthSlopeReach)),
                                                _mm_set1_ps(DepthRelativeMargin)),
                                     _mm_set1_ps(s.depthAbsMargin));
    __m128 depth;
    if (s.inverse)
    {
        const __m128 w = _mm_sub_ps(value, margin);
        const __m128 positive = _mm_cmpgt_ps(w, _mm_setzero_ps());
        depth = _mm_or_ps(_mm_and_ps(positive, _mm_div_ps(_mm_set1_ps(1.0f), w)),
                          _mm_andnot_ps(positive, _mm_set1_ps(InfiniteDepth)));
    }
    else
        depth = _mm_add_ps(value, margin);
    _mm_store_ps(out.depth, depth);
}
#endif

// Region of the group: scratch buffers cover it, row-major.
struct GroupBuffers
{
    PixelRange region;
    std::size_t stride = 0;
    std::uint8_t* state = nullptr;
    float* depth = nullptr;
    std::size_t index(int x, int y) const { return std::size_t(y - region.y0) * stride + std::size_t(x - region.x0); }
};

void vetoRange(const PixelRange& pixels, GroupBuffers& buffers)
{
    for (int y = pixels.y0; y <= pixels.y1; ++y)
        for (int x = pixels.x0; x <= pixels.x1; ++x)
            buffers.state[buffers.index(x, y)] |= Vetoed;
}

void rasterizePolygon(const PolygonSetup& s, bool simd, GroupBuffers& buffers)
{
    std::array<double, MaxEdges> rowF;
    alignas(16) std::array<float, MaxEdges> f0;
    const PixelRange& p = s.pixels;
    const double firstCentreX = p.x0 + 0.5;
    for (int y = p.y0; y <= p.y1; ++y)
    {
        const double cy = y + 0.5;
        for (std::size_t e = 0; e < s.edgeCount; ++e)
            rowF[e] = s.nx[e] * firstCentreX + s.ny[e] * cy + s.offset[e];
        const double rowV = s.da * firstCentreX + s.db * cy + s.dc;
        // Only the row's stretch between the edges can touch: f_e(cx) ≥ -reach_e bounds cx on
        // one side for each edge not parallel to the row. One pixel of slack absorbs rounding
        // (the lanes still test every pixel they visit).
        double lowX = p.x0, highX = p.x1;
        for (std::size_t e = 0; e < s.edgeCount; ++e)
        {
            if (std::abs(s.nx[e]) < 1e-6)
                continue;
            const double bound = (-s.reach[e] - s.ny[e] * cy - s.offset[e]) / s.nx[e] - 0.5; // pixel x of cx
            if (s.nx[e] > 0.0)
                lowX = std::max(lowX, std::floor(bound) - 1.0);
            else
                highX = std::min(highX, std::ceil(bound) + 1.0);
        }
        if (!(lowX <= highX))
            continue;
        const int spanStart = p.x0 + (int(lowX) - p.x0) / Lanes * Lanes; // stays on the polygon's lane grid
        const int spanEnd = int(highX);
        for (int x = spanStart; x <= spanEnd; x += Lanes)
        {
            const double dx = x - p.x0;
            for (std::size_t e = 0; e < s.edgeCount; ++e)
                f0[e] = float(rowF[e] + s.nx[e] * dx);
            const BlockInput in{f0.data(), &s, float(rowV + s.da * dx)};
            BlockResult result;
#ifdef __SSE2__
            if (simd)
                simdBlock(in, result);
            else
#endif
                scalarBlock(in, result);
            const int lanes = std::min(Lanes, p.x1 - x + 1);
            const int valid = (1 << lanes) - 1;
            int touched = result.touched & valid;
            int outside = result.outside;
            const int ambiguous = result.ambiguous & valid;
            if (ambiguous != 0)
            {
                for (int j = 0; j < lanes; ++j)
                {
                    if (!(ambiguous >> j & 1))
                        continue;
                    bool laneTouched = false, laneOutside = false;
                    decidePixel(s, x + j, y, laneTouched, laneOutside);
                    touched = (touched & ~(1 << j)) | int(laneTouched) << j;
                    outside = (outside & ~(1 << j)) | int(laneOutside) << j;
                }
            }
            if (touched == 0)
                continue;
            const std::size_t row = buffers.index(x, y);
            for (int j = 0; j < lanes; ++j)
            {
                if (!(touched >> j & 1))
                    continue;
                buffers.state[row + j] |= Touched | (outside >> j & 1 ? Vetoed : 0);
                buffers.depth[row + j] = std::max(buffers.depth[row + j], result.depth[j]);
            }
        }
    }
}
} // namespace

bool maskRasterHasSimd()
{
#ifdef __SSE2__
    return true;
#else
    return false;
#endif
}

std::size_t rasterizeOccluderGroupReference(MaskRasterPath path, OcclusionMask& mask, const ScreenPolygon* polygons,
                                            std::size_t count, double shrink, MaskRasterScratch& scratch)
{
    if (!prepareGroup(count, mask, shrink))
        return 0;

    // Bounding region of the group's grown polygons; any non-finite polygon spoils the group.
    PixelRange region{int(mask.width()), int(mask.height()), -1, -1};
    PolygonSetup setup;
    for (std::size_t i = 0; i < count; ++i)
    {
        if (setupPolygon(polygons[i], shrink, mask, setup) == Shape::NonFinite)
            return 0;
        unite(region, setup.pixels);
    }
    if (region.empty())
        return 0;

    GroupBuffers buffers;
    buffers.region = region;
    buffers.stride = std::size_t(region.x1 - region.x0 + 1);
    const std::size_t pixelCount = buffers.stride * std::size_t(region.y1 - region.y0 + 1);
    scratch.state.assign(pixelCount, 0);
    scratch.depth.assign(pixelCount, -InfiniteDepth);
    buffers.state = scratch.state.data();
    buffers.depth = scratch.depth.data();

    const bool simd = path == MaskRasterPath::Simd;
    for (std::size_t i = 0; i < count; ++i)
    {
        const Shape shape = setupPolygon(polygons[i], shrink, mask, setup);
        if (setup.pixels.empty())
            continue;
        if (shape == Shape::Convex)
            rasterizePolygon(setup, simd, buffers);
        else
            vetoRange(setup.pixels, buffers);
    }

    std::size_t covered = 0;
    for (int y = region.y0; y <= region.y1; ++y)
        for (int x = region.x0; x <= region.x1; ++x)
        {
            const std::size_t i = buffers.index(x, y);
            // An infinite depth (the plane reaches the horizon over the pixel) hides nothing.
            if (buffers.state[i] == Touched && buffers.depth[i] < InfiniteDepth)
            {
                mask.cover(std::uint32_t(x), std::uint32_t(y), buffers.depth[i]);
                ++covered;
            }
        }
    return covered;
}

} // namespace osgVis::core
