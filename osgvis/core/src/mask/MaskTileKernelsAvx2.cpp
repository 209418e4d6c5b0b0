// SPDX-License-Identifier: MIT
// The tile rasterizer's kernels (MaskTileKernels.h) with AVX2: a tile row of 8 pixels is one
// vector. Compiled for AVX2 by a target pragma after the includes, so that nothing this file
// shares with others (inline functions of the standard headers) is built for AVX2: the binary
// still runs without it, and MaskRasterizer.cpp calls these only where the CPU reports AVX2.
// Only "avx2" is targeted, never "fma", so no multiply-add is fused: the results are the SSE2
// kernels' bit for bit.
#include "MaskTileKernels.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

namespace osgVis::core::maskraster
{
namespace
{
alignas(32) constexpr float LaneIndices[TileSize] = {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f};

// One line per lane operation: a table to read across the two kernel files.
// clang-format off
struct Row
{
    __m256 v;
    static Row splat(float x) { return {_mm256_set1_ps(x)}; }
    static Row zero() { return {_mm256_setzero_ps()}; }
    static Row allSet() { return {_mm256_castsi256_ps(_mm256_set1_epi32(-1))}; }
    static Row load(const float* p) { return {_mm256_loadu_ps(p)}; }
    void store(float* p) const { _mm256_storeu_ps(p, v); }
};

inline Row add(Row a, Row b) { return {_mm256_add_ps(a.v, b.v)}; }
inline Row sub(Row a, Row b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline Row mul(Row a, Row b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline Row div(Row a, Row b) { return {_mm256_div_ps(a.v, b.v)}; }
inline Row min(Row a, Row b) { return {_mm256_min_ps(a.v, b.v)}; }
inline Row max(Row a, Row b) { return {_mm256_max_ps(a.v, b.v)}; }
inline Row less(Row a, Row b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OS)}; }
inline Row greater(Row a, Row b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OS)}; }
inline Row greaterEqual(Row a, Row b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OS)}; }
inline Row bitAnd(Row a, Row b) { return {_mm256_and_ps(a.v, b.v)}; }
inline Row bitOr(Row a, Row b) { return {_mm256_or_ps(a.v, b.v)}; }
inline Row andNot(Row a, Row b) { return {_mm256_andnot_ps(a.v, b.v)}; } // ~a & b
inline Row select(Row mask, Row a, Row b) { return {_mm256_blendv_ps(b.v, a.v, mask.v)}; }
inline int laneBits(Row m) { return _mm256_movemask_ps(m.v); }
inline Row fromLaneBits(unsigned bits)
{
    const __m256i single = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    const __m256i all = _mm256_set1_epi32(int(bits));
    return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(all, single), single))};
}
inline float largestLane(Row a)
{
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtss_f32(m);
}

// clang-format on
#include "MaskTileKernelsImpl.h"
} // namespace
} // namespace osgVis::core::maskraster

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

namespace osgVis::core::maskraster
{
const TileKernels* avx2TileKernels() // built for the baseline: callers ask before they know the CPU
{
    return &Kernels;
}
} // namespace osgVis::core::maskraster

#else
namespace osgVis::core::maskraster
{
const TileKernels* avx2TileKernels()
{
    return nullptr;
}
} // namespace osgVis::core::maskraster
#endif
