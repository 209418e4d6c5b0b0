// SPDX-License-Identifier: MIT
// The tile rasterizer's kernels (MaskTileKernels.h) with SSE2: a tile row of 8 pixels is two
// 4-lane vectors. SSE2 is the x86-64 baseline; elsewhere the same template runs on a portable
// 8-lane struct doing the identical IEEE operations lane by lane.
#include "MaskTileKernels.h"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace osgVis::core::maskraster
{
namespace
{
alignas(32) constexpr float LaneIndices[TileSize] = {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f};

// One line per lane operation: a table to read across the two kernel files.
// clang-format off
#ifdef __SSE2__
struct Row
{
    __m128 lo, hi;
    static Row splat(float v) { return {_mm_set1_ps(v), _mm_set1_ps(v)}; }
    static Row zero() { return {_mm_setzero_ps(), _mm_setzero_ps()}; }
    static Row allSet()
    {
        const __m128 ones = _mm_castsi128_ps(_mm_set1_epi32(-1));
        return {ones, ones};
    }
    static Row load(const float* p) { return {_mm_loadu_ps(p), _mm_loadu_ps(p + 4)}; }
    void store(float* p) const
    {
        _mm_storeu_ps(p, lo);
        _mm_storeu_ps(p + 4, hi);
    }
};

inline Row add(Row a, Row b) { return {_mm_add_ps(a.lo, b.lo), _mm_add_ps(a.hi, b.hi)}; }
inline Row sub(Row a, Row b) { return {_mm_sub_ps(a.lo, b.lo), _mm_sub_ps(a.hi, b.hi)}; }
inline Row mul(Row a, Row b) { return {_mm_mul_ps(a.lo, b.lo), _mm_mul_ps(a.hi, b.hi)}; }
inline Row div(Row a, Row b) { return {_mm_div_ps(a.lo, b.lo), _mm_div_ps(a.hi, b.hi)}; }
inline Row min(Row a, Row b) { return {_mm_min_ps(a.lo, b.lo), _mm_min_ps(a.hi, b.hi)}; }
inline Row max(Row a, Row b) { return {_mm_max_ps(a.lo, b.lo), _mm_max_ps(a.hi, b.hi)}; }
inline Row less(Row a, Row b) { return {_mm_cmplt_ps(a.lo, b.lo), _mm_cmplt_ps(a.hi, b.hi)}; }
inline Row greater(Row a, Row b) { return {_mm_cmpgt_ps(a.lo, b.lo), _mm_cmpgt_ps(a.hi, b.hi)}; }
inline Row greaterEqual(Row a, Row b) { return {_mm_cmpge_ps(a.lo, b.lo), _mm_cmpge_ps(a.hi, b.hi)}; }
inline Row bitAnd(Row a, Row b) { return {_mm_and_ps(a.lo, b.lo), _mm_and_ps(a.hi, b.hi)}; }
inline Row bitOr(Row a, Row b) { return {_mm_or_ps(a.lo, b.lo), _mm_or_ps(a.hi, b.hi)}; }
inline Row andNot(Row a, Row b) { return {_mm_andnot_ps(a.lo, b.lo), _mm_andnot_ps(a.hi, b.hi)}; } // ~a & b
inline Row select(Row mask, Row a, Row b) { return bitOr(bitAnd(mask, a), andNot(mask, b)); }
inline int laneBits(Row m) { return _mm_movemask_ps(m.lo) | _mm_movemask_ps(m.hi) << 4; }
inline Row fromLaneBits(unsigned bits)
{
    const __m128i all = _mm_set1_epi32(int(bits));
    const __m128i low = _mm_set_epi32(8, 4, 2, 1), high = _mm_set_epi32(128, 64, 32, 16);
    return {_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(all, low), low)),
            _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(all, high), high))};
}
inline float largestLane(Row a)
{
    __m128 m = _mm_max_ps(a.lo, a.hi);
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtss_f32(m);
}
#else
// Lane masks are all-ones or all-zero bit patterns, as in the vector registers.
struct Row
{
    float v[TileSize];
    static Row splat(float x)
    {
        Row r;
        for (float& lane : r.v)
            lane = x;
        return r;
    }
    static Row zero() { return splat(0.0f); }
    static Row allSet() { return fromBits(~0u); }
    static Row fromBits(unsigned pattern)
    {
        Row r;
        for (float& lane : r.v)
            __builtin_memcpy(&lane, &pattern, sizeof lane);
        return r;
    }
    static Row load(const float* p)
    {
        Row r;
        __builtin_memcpy(r.v, p, sizeof r.v);
        return r;
    }
    void store(float* p) const { __builtin_memcpy(p, v, sizeof v); }
};

template <class F> Row lanewise(Row a, Row b, F f)
{
    Row r;
    for (int j = 0; j < TileSize; ++j)
        r.v[j] = f(a.v[j], b.v[j]);
    return r;
}
inline unsigned bitsOf(float x)
{
    unsigned u;
    __builtin_memcpy(&u, &x, sizeof u);
    return u;
}
inline float floatOf(unsigned u)
{
    float x;
    __builtin_memcpy(&x, &u, sizeof x);
    return x;
}
inline float maskOf(bool b) { return floatOf(b ? ~0u : 0u); }
inline Row add(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return x + y; }); }
inline Row sub(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return x - y; }); }
inline Row mul(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return x * y; }); }
inline Row div(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return x / y; }); }
inline Row min(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return x < y ? x : y; }); }
inline Row max(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return x > y ? x : y; }); }
inline Row less(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return maskOf(x < y); }); }
inline Row greater(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return maskOf(x > y); }); }
inline Row greaterEqual(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return maskOf(x >= y); }); }
inline Row bitAnd(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return floatOf(bitsOf(x) & bitsOf(y)); }); }
inline Row bitOr(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return floatOf(bitsOf(x) | bitsOf(y)); }); }
inline Row andNot(Row a, Row b) { return lanewise(a, b, [](float x, float y) { return floatOf(~bitsOf(x) & bitsOf(y)); }); }
inline Row select(Row mask, Row a, Row b) { return bitOr(bitAnd(mask, a), andNot(mask, b)); }
inline int laneBits(Row m)
{
    int bits = 0;
    for (int j = 0; j < TileSize; ++j)
        bits |= int(bitsOf(m.v[j]) >> 31) << j;
    return bits;
}
inline Row fromLaneBits(unsigned bits)
{
    Row r;
    for (int j = 0; j < TileSize; ++j)
        r.v[j] = maskOf(bits >> j & 1u);
    return r;
}
inline float largestLane(Row a)
{
    float m = a.v[0];
    for (int j = 1; j < TileSize; ++j)
        m = a.v[j] > m ? a.v[j] : m;
    return m;
}
// clang-format on
#endif

#include "MaskTileKernelsImpl.h"
} // namespace

const TileKernels& sse2TileKernels()
{
    return Kernels;
}
} // namespace osgVis::core::maskraster
