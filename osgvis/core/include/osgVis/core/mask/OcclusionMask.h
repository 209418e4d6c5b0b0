// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The occlusion mask of the online mask method (Wang, Agarwal & Har-Peled, after hierarchical
/// occlusion maps): per mask pixel, whether fused occluders cover the pixel's whole area and the
/// largest view depth they have over it, plus the max-depth pyramid M0…Mm that answers "is this
/// screen rectangle hidden behind everything nearer than depth d?" in a few texel reads.
///
/// Pixel (x, y) is the unit square [x, x+1] × [y, y+1] in mask coordinates (origin at the bottom
/// left of the frame, x right, y up). Depth is the view-space distance along the view axis
/// (-z in eye coordinates), larger = farther; an uncovered pixel holds +infinity.
#include <cstdint>
#include <vector>

namespace osgVis::core
{
class OcclusionMask
{
public:
    /// All pixels uncovered; the pyramid is dropped until buildPyramid().
    void reset(std::uint32_t width, std::uint32_t height);
    std::uint32_t width() const { return _width; }
    std::uint32_t height() const { return _height; }

    /// Level 0, row-major from the bottom row. +infinity = not covered.
    float depth(std::uint32_t x, std::uint32_t y) const { return levelZero()[std::size_t(y) * _width + x]; }
    const float* baseRow(std::uint32_t y) const { return levelZero().data() + std::size_t(y) * _width; }
    /// Keeps the nearer of the stored and the given depth (a pixel fully covered by several occluders
    /// is hidden behind the nearest of them). Drops the pyramid. A NaN depth covers nothing.
    void cover(std::uint32_t x, std::uint32_t y, float depth);
    std::size_t coveredPixels() const;

    /// Level 0 in tiles of TileSize × TileSize pixels, tile (tx, ty) = pixels [8tx, 8tx+8) × [8ty, 8ty+8).
    static constexpr std::uint32_t TileSize = 8;
    std::uint32_t tileColumns() const { return (_width + TileSize - 1) / TileSize; }
    std::uint32_t tileRows() const { return (_height + TileSize - 1) / TileSize; }
    /// An upper bound of the depths stored in a tile, over its pixels inside the mask (+infinity while
    /// one of them is uncovered). A rasterizer may skip a tile where everything it could write is no
    /// nearer than this: nothing there would change.
    float tileBound(std::uint32_t tx, std::uint32_t ty) const { return _tileBound[std::size_t(ty) * tileColumns() + tx]; }
    /// For a rasterizer that writes a tile at a time: row y of level 0, to be written with nearer
    /// depths only (a bound must stay an upper bound), then setTileBound() with the tile's new largest
    /// depth over its pixels inside the mask. Drops the pyramid.
    /// The largest tileBound() over the BlockTiles × BlockTiles tiles of block (bx, by), for skipping
    /// a block of tiles at once.
    static constexpr std::uint32_t BlockTiles = 4;
    std::uint32_t blockColumns() const { return (tileColumns() + BlockTiles - 1) / BlockTiles; }
    std::uint32_t blockRows() const { return (tileRows() + BlockTiles - 1) / BlockTiles; }
    float blockBound(std::uint32_t bx, std::uint32_t by) const { return _blockBound[std::size_t(by) * blockColumns() + bx]; }
    float* nearerRow(std::uint32_t y)
    {
        if (!_levels.empty())
            dropPyramid();
        return _base.data() + std::size_t(y) * _width;
    }
    void setTileBound(std::uint32_t tx, std::uint32_t ty, float largestDepth);

    /// mask-approx only: the paper's shrinking of the fused union. A pixel stays covered only when
    /// every pixel within Chebyshev distance `pixels` is covered; its depth becomes the largest
    /// depth over that neighbourhood. Not conservative across separate occluders (parallax opens
    /// gaps between them as the eye moves); `mask` shrinks each occluder group on its own instead.
    /// Pixels beyond the mask's border count as uncovered (what lies there was never rasterized, and
    /// an occluder edge just off screen moves in as the eye moves). Drops the pyramid.
    void shrinkUnion(std::uint32_t pixels);

    /// M0 = the mask, M(k+1) texel = max of its 2×2 children (odd sizes: the missing child counts
    /// as uncovered), up to a 1×1 level.
    void buildPyramid();
    std::size_t levelCount() const { return _levels.size(); }

    /// True only when every pixel that the rectangle [x0, x1] × [y0, y1] (mask coordinates, closed)
    /// overlaps is covered with a stored depth strictly less than `nearestDepth`. A rectangle
    /// reaching outside the mask is never hidden. Needs buildPyramid(): the (at most 2×2) coarse
    /// texels first, then two levels finer the texels wholly inside the rectangle (an early visible
    /// answer), and the border texels refined only where they are inconclusive.
    /// It overlaps pixels floor(x0)..floor(x1) (and likewise in y): an edge lying exactly on a pixel
    /// boundary still counts the pixel beyond it (conservative). Empty (x0 > x1), NaN or partly
    /// outside rectangles and a NaN `nearestDepth` give false. Without a pyramid, level 0 is scanned.
    bool rectHidden(double x0, double y0, double x1, double y1, float nearestDepth) const;
    /// The same answer by the earlier query (the coarse texels refined depth-first, without the
    /// finer level's early visible answer): the reference of the tests and benchmarks.
    bool rectHiddenReference(double x0, double y0, double x1, double y1, float nearestDepth) const;

private:
    void dropPyramid();
    /// The mask: _base, or _levels[0] while the pyramid stands (moved there, not copied).
    const std::vector<float>& levelZero() const { return _levels.empty() ? _base : _levels[0]; }
    void recomputeTileBounds();
    void recomputeBlockBound(std::uint32_t bx, std::uint32_t by);
    float texel(std::size_t level, std::uint32_t tx, std::uint32_t ty) const
    {
        return _levels[level][std::size_t(ty) * _levelWidth[level] + tx];
    }
    bool rectPixels(double x0, double y0, double x1, double y1, float nearestDepth, std::uint32_t pixels[4]) const;
    bool scanHidden(const std::uint32_t pixels[4], float nearestDepth) const;
    bool query(double x0, double y0, double x1, double y1, float nearestDepth, bool depthFirst) const;
    /// Invalid rectangles (false) and masks without a pyramid (scanned) are decided here.
    bool decidedWithoutPyramid(double x0, double y0, double x1, double y1, float nearestDepth, std::uint32_t pixels[4],
                               bool& hidden) const;
    std::size_t spanLevel(const std::uint32_t pixels[4]) const;
    bool texelHidden(std::size_t level, std::uint32_t tx, std::uint32_t ty, const std::uint32_t pixels[4],
                     float nearestDepth) const;

    std::uint32_t _width = 0, _height = 0;
    std::vector<float> _base;
    std::vector<float> _tileBound; ///< per tile, row-major; cover() only lowers depths, so it keeps them
    std::vector<float> _blockBound; ///< per block of tiles, row-major
    std::vector<std::vector<float>> _levels; ///< _levels[0] is the mask (moved out of _base) once built
    std::vector<std::uint32_t> _levelWidth, _levelHeight;
    std::vector<std::vector<float>> _spareLevels; ///< dropped levels keep their memory for the next build
    std::vector<float> _erosionScratch;
};
} // namespace osgVis::core
