// SPDX-License-Identifier: MIT
// Occlusion mask and its max-depth pyramid, after Zhang et al.'s hierarchical occlusion maps as
// used by Wang, Agarwal & Har-Peled's on-line mask method (max depth per texel instead of opacity).
#include <osgVis/core/mask/OcclusionMask.h>

#include <algorithm>
#include <cmath>
#include <limits>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace osgVis::core
{
namespace
{
constexpr float Uncovered = std::numeric_limits<float>::infinity();

// out[i] = max(in[i-r .. i+r]) over `count` items of `itemSize` contiguous floats each (item i at
// i·itemSize), +inf where the window reaches past either end (beyond the mask is uncovered). Van
// Herk / Gil–Werman: per block of 2r+1 items a running max from the block's start (g) and from
// its end (h); any window spans at most two blocks, so out[i] = max(h[i-r], g[i+r]) — three max
// operations per element whatever r is.
void windowMax(const float* in, float* out, std::size_t count, std::size_t itemSize, std::size_t radius, float* g,
               float* h)
{
    const std::size_t window = 2 * radius + 1;
    if (count < window)
    {
        std::fill(out, out + count * itemSize, Uncovered);
        return;
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        const float* item = in + i * itemSize;
        float* running = g + i * itemSize;
        if (i % window == 0)
            std::copy(item, item + itemSize, running);
        else
            for (std::size_t j = 0; j < itemSize; ++j)
                running[j] = std::max(running[j - itemSize], item[j]);
    }
    for (std::size_t i = count; i-- > 0;)
    {
        const float* item = in + i * itemSize;
        float* running = h + i * itemSize;
        if (i + 1 == count || (i + 1) % window == 0)
            std::copy(item, item + itemSize, running);
        else
            for (std::size_t j = 0; j < itemSize; ++j)
                running[j] = std::max(running[j + itemSize], item[j]);
    }
    std::fill(out, out + radius * itemSize, Uncovered);
    for (std::size_t i = radius; i + radius < count; ++i)
    {
        const float* fromLeft = h + (i - radius) * itemSize;
        const float* toRight = g + (i + radius) * itemSize;
        for (std::size_t j = 0; j < itemSize; ++j)
            out[i * itemSize + j] = std::max(fromLeft[j], toRight[j]);
    }
    std::fill(out + (count - radius) * itemSize, out + count * itemSize, Uncovered);
}

// out[x] = max(row0[2x], row0[2x+1], row1[2x], row1[2x+1]) for x < count: the 2 × 2 max of a
// pyramid level where all four children exist.
void halveRows(const float* row0, const float* row1, float* out, std::uint32_t count)
{
    std::uint32_t x = 0;
#ifdef __SSE2__
    for (; x + 4 <= count; x += 4)
    {
        const __m128 a = _mm_max_ps(_mm_loadu_ps(row0 + 2 * x), _mm_loadu_ps(row1 + 2 * x));
        const __m128 b = _mm_max_ps(_mm_loadu_ps(row0 + 2 * x + 4), _mm_loadu_ps(row1 + 2 * x + 4));
        _mm_storeu_ps(out + x, _mm_max_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0)),
                                          _mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1))));
    }
#endif
    for (; x < count; ++x)
        out[x] = std::max(std::max(row0[2 * x], row0[2 * x + 1]), std::max(row1[2 * x], row1[2 * x + 1]));
}
} // namespace

void OcclusionMask::reset(std::uint32_t width, std::uint32_t height)
{
    dropPyramid();
    _width = width;
    _height = height;
    _base.assign(std::size_t(width) * height, Uncovered);
    _tileBound.assign(std::size_t(tileColumns()) * tileRows(), Uncovered);
    _blockBound.assign(std::size_t(blockColumns()) * blockRows(), Uncovered);
}

void OcclusionMask::setTileBound(std::uint32_t tx, std::uint32_t ty, float largestDepth)
{
    float& tile = _tileBound[std::size_t(ty) * tileColumns() + tx];
    const float block = blockBound(tx / BlockTiles, ty / BlockTiles);
    const bool wasLargest = !(tile < block);
    tile = largestDepth;
    // A block's bound changes only when this tile held its largest value or now exceeds it.
    if (wasLargest || !(largestDepth <= block))
        recomputeBlockBound(tx / BlockTiles, ty / BlockTiles);
}

void OcclusionMask::recomputeBlockBound(std::uint32_t bx, std::uint32_t by)
{
    const std::uint32_t columns = tileColumns();
    const std::uint32_t x0 = bx * BlockTiles, x1 = std::min(x0 + BlockTiles, columns);
    const std::uint32_t y0 = by * BlockTiles, y1 = std::min(y0 + BlockTiles, tileRows());
    float largest = -Uncovered;
    for (std::uint32_t y = y0; y < y1; ++y)
        for (std::uint32_t x = x0; x < x1; ++x)
            largest = std::max(largest, _tileBound[std::size_t(y) * columns + x]);
    _blockBound[std::size_t(by) * blockColumns() + bx] = largest;
}

void OcclusionMask::recomputeTileBounds()
{
    std::fill(_tileBound.begin(), _tileBound.end(), -Uncovered);
    const std::uint32_t columns = tileColumns();
    for (std::uint32_t y = 0; y < _height; ++y)
    {
        float* bound = _tileBound.data() + std::size_t(y / TileSize) * columns;
        const float* row = _base.data() + std::size_t(y) * _width;
        for (std::uint32_t x = 0; x < _width; ++x)
            bound[x / TileSize] = std::max(bound[x / TileSize], row[x]);
    }
    for (std::uint32_t by = 0; by < blockRows(); ++by)
        for (std::uint32_t bx = 0; bx < blockColumns(); ++bx)
            recomputeBlockBound(bx, by);
}

void OcclusionMask::dropPyramid()
{
    if (!_levels.empty())
        std::swap(_base, _levels[0]); // level 0 holds the mask while the pyramid stands
    for (std::vector<float>& level : _levels)
        _spareLevels.push_back(std::move(level));
    _levels.clear();
    _levelWidth.clear();
    _levelHeight.clear();
}

void OcclusionMask::cover(std::uint32_t x, std::uint32_t y, float depth)
{
    if (!_levels.empty())
        dropPyramid();
    float& stored = _base[std::size_t(y) * _width + x];
    if (depth < stored) // note: false for NaN, which therefore covers nothing
        stored = depth;
}

std::size_t OcclusionMask::coveredPixels() const
{
    const std::vector<float>& base = levelZero();
    return std::size_t(std::count_if(base.begin(), base.end(), [](float depth) { return depth < Uncovered; }));
}

void OcclusionMask::shrinkUnion(std::uint32_t pixels)
{
    dropPyramid();
    if (pixels == 0 || _base.empty())
        return;
    // The eroded depth is the max over the (2Δ+1)² neighbourhood: any uncovered (+inf) pixel in it,
    // or the border, makes the result +inf. Max is separable: rows, then columns (rows as items).
    const std::size_t size = _base.size();
    _erosionScratch.resize(3 * size);
    float* rowsDone = _erosionScratch.data();
    float* g = rowsDone + size;
    float* h = g + size;
    for (std::uint32_t y = 0; y < _height; ++y)
    {
        const std::size_t row = std::size_t(y) * _width;
        windowMax(_base.data() + row, rowsDone + row, _width, 1, pixels, g + row, h + row);
    }
    windowMax(rowsDone, _base.data(), _height, _width, pixels, g, h);
    recomputeTileBounds(); // erosion makes depths farther
}

void OcclusionMask::buildPyramid()
{
    dropPyramid();
    auto newLevel = [this](std::uint32_t width, std::uint32_t height) -> std::vector<float>&
    {
        if (_spareLevels.empty())
            _levels.emplace_back();
        else
        {
            _levels.push_back(std::move(_spareLevels.back()));
            _spareLevels.pop_back();
        }
        _levelWidth.push_back(width);
        _levelHeight.push_back(height);
        _levels.back().resize(std::size_t(width) * height);
        return _levels.back();
    };
    std::swap(newLevel(_width, _height), _base); // no copy: level 0 is the mask itself
    if (_width == 0 || _height == 0)
        return;
    while (_levelWidth.back() > 1 || _levelHeight.back() > 1)
    {
        const std::uint32_t fineWidth = _levelWidth.back(), fineHeight = _levelHeight.back();
        const std::uint32_t width = (fineWidth + 1) / 2, height = (fineHeight + 1) / 2;
        std::vector<float>& coarse = newLevel(width, height);
        const std::vector<float>& fine = _levels[_levels.size() - 2]; // valid: newLevel is done growing _levels
        for (std::uint32_t y = 0; y < height; ++y)
        {
            float* out = coarse.data() + std::size_t(y) * width;
            // A missing child (odd size) is uncovered, so the texel is too.
            if (2 * y + 1 >= fineHeight)
            {
                std::fill(out, out + width, Uncovered);
                continue;
            }
            const float* row0 = fine.data() + std::size_t(2 * y) * fineWidth;
            halveRows(row0, row0 + fineWidth, out, fineWidth / 2);
            if (fineWidth % 2 != 0)
                out[width - 1] = Uncovered;
        }
    }
}

bool OcclusionMask::texelHidden(std::size_t level, std::uint32_t tx, std::uint32_t ty, const std::uint32_t pixels[4],
                                float nearestDepth) const
{
    // A texel nearer than nearestDepth hides all its pixels (its max is over all of them, an
    // uncovered one being +inf). Otherwise one of its pixels (or a missing child beyond the mask)
    // is not nearer: decisive when the rectangle spans the texel's whole (unclipped) footprint,
    // else the children the rectangle overlaps decide.
    if (texel(level, tx, ty) < nearestDepth)
        return true;
    if (level == 0)
        return false;
    const std::uint64_t first[2] = {std::uint64_t(tx) << level, std::uint64_t(ty) << level};
    const std::uint64_t last[2] = {((std::uint64_t(tx) + 1) << level) - 1, ((std::uint64_t(ty) + 1) << level) - 1};
    if (pixels[0] <= first[0] && last[0] <= pixels[2] && pixels[1] <= first[1] && last[1] <= pixels[3])
        return false;
    const std::size_t child = level - 1;
    const std::uint32_t cx0 = std::max(2 * tx, pixels[0] >> child), cx1 = std::min(2 * tx + 1, pixels[2] >> child);
    const std::uint32_t cy0 = std::max(2 * ty, pixels[1] >> child), cy1 = std::min(2 * ty + 1, pixels[3] >> child);
    for (std::uint32_t cy = cy0; cy <= cy1; ++cy)
        for (std::uint32_t cx = cx0; cx <= cx1; ++cx)
            if (!texelHidden(child, cx, cy, pixels, nearestDepth))
                return false;
    return true;
}

bool OcclusionMask::rectPixels(double x0, double y0, double x1, double y1, float nearestDepth,
                               std::uint32_t pixels[4]) const
{
    // note: every comparison is written so that NaN makes it fail.
    if (!(x0 >= 0.0 && y0 >= 0.0 && x1 <= double(_width) && y1 <= double(_height) && x0 <= x1 && y0 <= y1))
        return false;
    if (_width == 0 || _height == 0 || std::isnan(nearestDepth))
        return false;
    pixels[0] = std::uint32_t(std::floor(x0));
    pixels[1] = std::uint32_t(std::floor(y0));
    pixels[2] = std::min(std::uint32_t(std::floor(x1)), _width - 1);
    pixels[3] = std::min(std::uint32_t(std::floor(y1)), _height - 1);
    return true;
}

bool OcclusionMask::scanHidden(const std::uint32_t pixels[4], float nearestDepth) const
{
    for (std::uint32_t y = pixels[1]; y <= pixels[3]; ++y)
        for (std::uint32_t x = pixels[0]; x <= pixels[2]; ++x)
            if (!(_base[std::size_t(y) * _width + x] < nearestDepth))
                return false;
    return true;
}

bool OcclusionMask::decidedWithoutPyramid(double x0, double y0, double x1, double y1, float nearestDepth,
                                          std::uint32_t pixels[4], bool& hidden) const
{
    hidden = false;
    if (!rectPixels(x0, y0, x1, y1, nearestDepth, pixels))
        return true;
    if (!_levels.empty())
        return false;
    hidden = scanHidden(pixels, nearestDepth);
    return true;
}

std::size_t OcclusionMask::spanLevel(const std::uint32_t pixels[4]) const
{
    // Finest level where the rectangle spans at most 2×2 texels.
    std::size_t level = 0;
    while (level + 1 < _levels.size() &&
           ((pixels[2] >> level) - (pixels[0] >> level) > 1 || (pixels[3] >> level) - (pixels[1] >> level) > 1))
        ++level;
    return level;
}

bool OcclusionMask::rectHidden(double x0, double y0, double x1, double y1, float nearestDepth) const
{
    return query(x0, y0, x1, y1, nearestDepth, false);
}

bool OcclusionMask::rectHiddenReference(double x0, double y0, double x1, double y1, float nearestDepth) const
{
    return query(x0, y0, x1, y1, nearestDepth, true);
}

bool OcclusionMask::query(double x0, double y0, double x1, double y1, float nearestDepth, bool depthFirst) const
{
    std::uint32_t pixels[4];
    bool answer = false;
    if (decidedWithoutPyramid(x0, y0, x1, y1, nearestDepth, pixels, answer))
        return answer;
    const std::size_t coarse = spanLevel(pixels);
    if (depthFirst) // the earlier order: each coarse texel refined in turn
    {
        for (std::uint32_t ty = pixels[1] >> coarse; ty <= pixels[3] >> coarse; ++ty)
            for (std::uint32_t tx = pixels[0] >> coarse; tx <= pixels[2] >> coarse; ++tx)
                if (!texelHidden(coarse, tx, ty, pixels, nearestDepth))
                    return false;
        return true;
    }
    // 1. At most 2×2 coarse texels: all nearer, hidden (the common answer, in four reads).
    bool nearer = true;
    for (std::uint32_t ty = pixels[1] >> coarse; nearer && ty <= pixels[3] >> coarse; ++ty)
        for (std::uint32_t tx = pixels[0] >> coarse; nearer && tx <= pixels[2] >> coarse; ++tx)
            nearer = texel(coarse, tx, ty) < nearestDepth;
    if (nearer)
        return true;
    // 2. Two levels finer (at most 8×8 texels): a texel wholly inside the rectangle that is not
    // nearer decides at once (visible), so those go first; the texels on its border that are not
    // nearer are refined down to the pixels they share with the rectangle.
    const std::size_t level = coarse >= 2 ? coarse - 2 : 0;
    const std::uint32_t tx0 = pixels[0] >> level, tx1 = pixels[2] >> level;
    const std::uint32_t ty0 = pixels[1] >> level, ty1 = pixels[3] >> level;
    auto inside = [&](std::uint32_t t, int axis)
    { return pixels[axis] <= (t << level) && ((std::uint64_t(t) + 1) << level) - 1 <= pixels[axis + 2]; };
    auto pass = [&](bool wholly)
    {
        for (std::uint32_t ty = ty0; ty <= ty1; ++ty)
            for (std::uint32_t tx = tx0; tx <= tx1; ++tx)
            {
                if ((inside(tx, 0) && inside(ty, 1)) != wholly)
                    continue;
                if (wholly ? !(texel(level, tx, ty) < nearestDepth) : !texelHidden(level, tx, ty, pixels, nearestDepth))
                    return false;
            }
        return true;
    };
    return pass(true) && pass(false);
}
} // namespace osgVis::core
