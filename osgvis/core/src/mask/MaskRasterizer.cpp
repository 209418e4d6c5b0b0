// SPDX-License-Identifier: MIT
// The tile rasterizer of occluder groups into the occlusion mask: the conservative "fully covered
// pixels only" contract of Wang, Agarwal & Har-Peled's mask (MaskRasterizer.h), organised like the
// fast software occlusion rasterizers (Hasselgren, Andersson & Akenine-Möller, "Masked Software
// Occlusion Culling", HPG 2016): 8 × 8-pixel tiles classified against each edge at their corners
// as inside, outside or partial, coverage as 64-bit lane masks, a per-tile depth bound that rejects
// a group where the mask is already covered no farther than anything the group could write, and
// AVX2 or SSE2 kernels for the pixels of partial tiles and for depths (MaskTileKernels.h). Unlike
// theirs it samples no pixel centres: every decision is the reference's grown-square test, and
// lanes near a threshold are decided in double exactly as the reference decides them. Why each
// shortcut can only keep or lose coverage and only raise depths: docs/mask.md, "The tile
// rasterizer".
#include "MaskRasterPaths.h"
#include "MaskTileKernels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
struct MaskRasterScratch::Tiles
{
    std::vector<maskraster::PolygonSetup> setups;
    std::vector<maskraster::Shape> shapes;
    std::vector<float> nearest;
    std::vector<int> spans;
    std::vector<std::uint32_t> rowPolygons; // the polygons touching the current tile row
};

MaskRasterScratch::MaskRasterScratch() = default;
MaskRasterScratch::~MaskRasterScratch() = default;
MaskRasterScratch::MaskRasterScratch(const MaskRasterScratch&) {}
MaskRasterScratch& MaskRasterScratch::operator=(const MaskRasterScratch&)
{
    return *this;
}
MaskRasterScratch::MaskRasterScratch(MaskRasterScratch&&) noexcept = default;
MaskRasterScratch& MaskRasterScratch::operator=(MaskRasterScratch&&) noexcept = default;

namespace
{
using namespace maskraster;

// Tile classification is done in double, against thresholds moved by this much (px) towards the
// undecided side: far above the double rounding of an edge function, so a decided edge is decided
// as the reference decides each of the tile's pixels.
constexpr double ClassifyMargin = 1e-6;

std::uint64_t rectBits(int x0, int x1, int y0, int y1) // tile-relative, inclusive
{
    const std::uint64_t row = (0xffu >> (TileSize - 1 - x1)) & (0xffu << x0);
    const std::uint64_t rows =
        (~std::uint64_t(0) >> (TileSize * (TileSize - 1 - y1))) & (~std::uint64_t(0) << (TileSize * y0));
    return row * 0x0101010101010101ull & rows;
}

PixelRange intersect(const PixelRange& a, const PixelRange& b)
{
    return PixelRange{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// The smallest depth the polygon's plane has over the grown squares of the pixels in `r`, rounded
// towards the viewer: no depth the polygon writes there (each ≥ the plane's largest over one grown
// square) is smaller.
float smallestDepth(const PolygonSetup& s, const PixelRange& r, double shrink)
{
    const DepthPlane& p = s.plane;
    const double x0 = r.x0 - shrink, x1 = r.x1 + 1 + shrink, y0 = r.y0 - shrink, y1 = r.y1 + 1 + shrink;
    const double ax = std::max(p.a * x0, p.a * x1), ay = std::max(p.b * y0, p.b * y1);
    const double slack = double(s.depthAbsMargin) + 1e-9 * (std::abs(p.a * x0) + std::abs(p.a * x1) +
                                                            std::abs(p.b * y0) + std::abs(p.b * y1) + std::abs(p.c));
    if (p.inverse)
    {
        const double largestInverse = ax + ay + p.c + slack;
        return largestInverse > 0.0 ? float(0.999999 / largestInverse) : InfiniteDepth;
    }
    const double least = std::min(p.a * x0, p.a * x1) + std::min(p.b * y0, p.b * y1) + p.c - slack;
    return float(least - 1e-6 * std::abs(least));
}

// Tile columns of tile row `ty` where the polygon may touch a grown pixel square: its pixel range,
// narrowed by each edge's touch condition f ≥ -reach over the row band's pixel centres, with a
// pixel of slack on either side (the kernels still test every pixel they are given).
bool tileSpan(const PolygonSetup& s, int ty, int& first, int& last)
{
    const int y0 = std::max(s.pixels.y0, ty * TileSize), y1 = std::min(s.pixels.y1, ty * TileSize + TileSize - 1);
    if (y0 > y1 || s.pixels.x0 > s.pixels.x1)
        return false;
    double low = s.pixels.x0, high = s.pixels.x1;
    for (std::size_t e = 0; e < s.edgeCount; ++e)
    {
        if (std::abs(s.nx[e]) < 1e-6)
            continue;
        const double nyCy = std::max(s.ny[e] * (y0 + 0.5), s.ny[e] * (y1 + 0.5));
        const double x = (-s.reach[e] - nyCy - s.offset[e]) / s.nx[e] - 0.5; // pixel x at the boundary
        if (s.nx[e] > 0.0)
            low = std::max(low, std::floor(x) - 1.0);
        else
            high = std::min(high, std::ceil(x) + 1.0);
    }
    if (!(low <= high))
        return false;
    first = int(low) / TileSize;
    last = int(high) / TileSize;
    return true;
}

// Tile columns of tile row `ty` (pixel rows y0..y1 inside the mask) whose every pixel lies inside
// every edge of the polygon (outline edges: f ≥ reach at every pixel centre of the whole 8 × 8 tile;
// shared edges: f ≥ -reach), with a margin of 1e-4 px over the rounding of this division. Such a
// tile needs no classification: each of its pixels touches the polygon and is beyond none of its
// outline edges, exactly as the reference decides (each decision clears its threshold by the margin).
void insideSpan(const PolygonSetup& s, int y0, int y1, int& first, int& last)
{
    constexpr double Margin = 1e-4;
    double low = -1.0, high = 1e9;
    for (std::size_t e = 0; e < s.edgeCount && low <= high; ++e)
    {
        const double threshold = (s.outline[e] ? s.reach[e] : -s.reach[e]) + Margin;
        const double rest = threshold - std::min(s.ny[e] * (y0 + 0.5), s.ny[e] * (y1 + 0.5)) - s.offset[e];
        if (s.nx[e] == 0.0) // need 0 ≥ rest whatever the column
            high = rest <= 0.0 ? high : -2.0;
        else if (s.nx[e] > 0.0) // the tile's leftmost centre 8tx + 0.5 decides
            low = std::max(low, std::ceil((rest / s.nx[e] - 0.5) / TileSize));
        else // the rightmost centre 8tx + 7.5
            high = std::min(high, std::floor((rest / s.nx[e] - 7.5) / TileSize));
    }
    if (!(low <= high)) // NaN included
    {
        first = 0;
        last = -1;
        return;
    }
    first = int(std::max(low, -1.0));
    last = int(std::min(high, 1e9));
}

// What a group has put into one tile so far. While one polygon alone gives depths, its plane is
// kept instead of depths (merged on the way into the mask); a second one fills `depth`.
struct TileWork
{
    std::uint64_t touched = 0, vetoed = 0;
    int contributors = 0;
    TileDepth first;
    std::uint64_t firstLanes = 0;
    alignas(32) float depth[TileSize * TileSize];
    TileEdges edges;
};

// One convex polygon over one tile: adds what it touches and vetoes, and its depths where it may
// count. `tileRange` is the tile's pixels inside the mask; `inside`: all of them lie inside the
// polygon (insideSpan), so no edge needs classifying.
void polygonInTile(const TileKernels& kernels, const PolygonSetup& s, const PixelRange& tileRange, int tx, int ty,
                   bool inside, TileWork& work)
{
    const PixelRange r = intersect(tileRange, s.pixels);
    const int ox = tx * TileSize, oy = ty * TileSize;
    const std::uint64_t range = rectBits(r.x0 - ox, r.x1 - ox, r.y0 - oy, r.y1 - oy);
    const double cx = r.x0 + 0.5, cy = r.y0 + 0.5, wx = r.x1 - r.x0, wy = r.y1 - r.y0;
    const double tileCx = ox + 0.5, tileCy = oy + 0.5;
    bool allOutside = false;
    TileEdges& edges = work.edges;
    edges.count = 0;
    for (std::size_t e = 0; e < (inside ? 0 : s.edgeCount); ++e)
    {
        // The edge function over the range's pixel centres is extreme at its corners.
        const double f = s.nx[e] * cx + s.ny[e] * cy + s.offset[e];
        const double low = f + std::min(0.0, s.nx[e] * wx) + std::min(0.0, s.ny[e] * wy);
        const double high = f + std::max(0.0, s.nx[e] * wx) + std::max(0.0, s.ny[e] * wy);
        if (high < -s.reach[e] - ClassifyMargin)
            return; // no grown square of the range touches the polygon
        const bool touchesAll = low >= -s.reach[e] + ClassifyMargin;
        const bool insideAll = !s.outline[e] || low >= s.reach[e] + ClassifyMargin;
        const bool outsideAll = s.outline[e] && high < s.reach[e] - ClassifyMargin;
        if (touchesAll && (insideAll || outsideAll))
        {
            allOutside = allOutside || outsideAll;
            continue;
        }
        const std::size_t k = edges.count++;
        edges.f0[k] = float(s.nx[e] * tileCx + s.ny[e] * tileCy + s.offset[e]);
        edges.nx[k] = s.slope[e];
        edges.ny[k] = s.slopeY[e];
        edges.reach[k] = s.reachF[e];
        edges.insideLimit[k] = s.insideLimit[e];
    }
    std::uint64_t touched = range, outside = allOutside ? range : 0;
    if (edges.count != 0)
    {
        TileCoverage c;
        kernels.coverage(edges, r.y0 - oy, r.y1 - oy + 1, c);
        touched = c.touched & range;
        outside = allOutside ? range : c.outside;
        for (std::uint64_t pending = c.ambiguous & range; pending != 0; pending &= pending - 1)
        {
            const int lane = __builtin_ctzll(pending);
            bool laneTouched = false, laneOutside = false;
            decidePixel(s, ox + lane % TileSize, oy + lane / TileSize, laneTouched, laneOutside);
            const std::uint64_t bit = std::uint64_t(1) << lane;
            touched = laneTouched ? touched | bit : touched & ~bit;
            outside = laneOutside ? outside | bit : outside & ~bit;
        }
    }
    work.touched |= touched;
    work.vetoed |= touched & outside;
    const std::uint64_t counts = touched & ~work.vetoed;
    if (counts == 0)
        return;
    TileDepth plane;
    plane.v0 = float(s.da * tileCx + s.db * tileCy + s.dc);
    plane.da = s.depthSlope;
    plane.db = s.depthSlopeY;
    plane.spread = float(TileSize) * (std::fabs(s.depthSlope) + std::fabs(s.depthSlopeY));
    plane.absMargin = 2.0f * s.depthAbsMargin;
    plane.inverse = s.inverse;
    if (work.contributors++ == 0)
    {
        work.first = plane;
        work.firstLanes = counts;
        return;
    }
    if (work.contributors == 2)
    {
        std::fill(work.depth, work.depth + TileSize * TileSize, -InfiniteDepth);
        kernels.depthMax(work.first, 0, TileSize, work.firstLanes, work.depth);
    }
    kernels.depthMax(plane, r.y0 - oy, r.y1 - oy + 1, counts, work.depth);
}

// Writes the covered lanes of a tile into the mask and refreshes the tile's bound. Tiles that reach
// beyond the mask go through a padded copy (-inf beyond: it never raises the bound).
std::size_t mergeTile(const TileKernels& kernels, OcclusionMask& mask, int tx, int ty, const PixelRange& tileRange,
                      std::uint64_t covered, const TileWork& work)
{
    const int ox = tx * TileSize, oy = ty * TileSize;
    float* rows[TileSize];
    alignas(32) float padded[TileSize * TileSize];
    const bool whole = tileRange.x1 - ox == TileSize - 1 && tileRange.y1 - oy == TileSize - 1;
    const int width = tileRange.x1 - ox + 1, height = tileRange.y1 - oy + 1;
    float* const first = mask.nearerRow(std::uint32_t(oy)) + ox; // rows are mask.width() apart
    const std::size_t stride = mask.width();
    for (int r = 0; r < TileSize; ++r)
    {
        if (whole)
        {
            rows[r] = first + r * stride;
            continue;
        }
        rows[r] = padded + TileSize * r;
        std::fill(rows[r], rows[r] + TileSize, -InfiniteDepth);
        if (r < height)
            std::copy_n(first + r * stride, width, rows[r]);
    }
    std::size_t count = 0;
    // note: with one contributor every covered lane is one of its lanes (a covered pixel's touching
    // polygons all gave depths there), so its plane stands for the maximum.
    const float largest = work.contributors == 1 ? kernels.planeMerge(rows, covered, work.first, count)
                                                 : kernels.merge(rows, covered, work.depth, count);
    if (!whole)
        for (int r = 0; r < height; ++r)
            std::copy_n(rows[r], width, first + r * stride);
    mask.setTileBound(std::uint32_t(tx), std::uint32_t(ty), largest);
    return count;
}

bool cpuHasAvx2()
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

const TileKernels& kernelsFor(MaskTileKernel kernel)
{
    const TileKernels* avx2 =
        kernel == MaskTileKernel::Avx2 && maskTileKernelAvailable(kernel) ? avx2TileKernels() : nullptr;
    return avx2 ? *avx2 : sse2TileKernels();
}

// Sets up the group's polygons in `tiles` (setups, shapes) and the pixels they reach together;
// false when a polygon is not finite.
bool setupGroup(const ScreenPolygon* polygons, std::size_t count, double shrink, const OcclusionMask& mask,
                MaskRasterScratch::Tiles& tiles, PixelRange& region)
{
    std::vector<PolygonSetup>& setups = tiles.setups;
    std::vector<Shape>& shapes = tiles.shapes;
    if (setups.size() < count)
        setups.resize(count);
    shapes.resize(count);

    region = PixelRange{int(mask.width()), int(mask.height()), -1, -1};
    for (std::size_t i = 0; i < count; ++i)
    {
        shapes[i] = setupPolygon(polygons[i], shrink, mask, setups[i]);
        if (shapes[i] == Shape::NonFinite)
            return false; // any non-finite polygon spoils the group
        unite(region, setups[i].pixels);
    }
    return true;
}

// Fills tiles.nearest: each convex polygon's smallest depth over its pixel range (infinite for the
// others); returns the least of them.
float fillNearestDepths(MaskRasterScratch::Tiles& tiles, std::size_t count, double shrink)
{
    std::vector<float>& nearest = tiles.nearest;
    nearest.assign(count, InfiniteDepth);
    float groupNearest = InfiniteDepth;
    for (std::size_t i = 0; i < count; ++i)
        if (tiles.shapes[i] == Shape::Convex && !tiles.setups[i].pixels.empty())
        {
            nearest[i] = smallestDepth(tiles.setups[i], tiles.setups[i].pixels, shrink);
            groupNearest = std::min(groupNearest, nearest[i]);
        }
    return groupNearest;
}

// True when some block of the mask over `region` may hold a depth farther than groupNearest (its bound
// is), so that the group may change it.
bool mayBeNearerThanMask(const OcclusionMask& mask, const PixelRange& region, float groupNearest)
{
    const int blocks = int(TileSize * OcclusionMask::BlockTiles);
    float regionBound = -InfiniteDepth;
    for (int by = region.y0 / blocks; by <= region.y1 / blocks && !(groupNearest < regionBound); ++by)
        for (int bx = region.x0 / blocks; bx <= region.x1 / blocks; ++bx)
            regionBound = std::max(regionBound, mask.blockBound(std::uint32_t(bx), std::uint32_t(by)));
    return groupNearest < regionBound;
}

// One group being rasterized: what its tile rows and tiles read and write.
struct GroupRaster
{
    const TileKernels& kernels;
    OcclusionMask& mask;
    MaskRasterScratch::Tiles& tiles;
    std::size_t count;
    float groupNearest;   // the least of tiles.nearest
    PixelRange maskRange; // the mask's pixels
};

// Fills tiles.spans for tile row `ty` and lists the polygons touching the row in tiles.rowPolygons;
// rowFirst..rowLast: the tile columns the convex ones may touch (empty when none does).
void collectRowPolygons(const GroupRaster& group, int ty, int& rowFirst, int& rowLast)
{
    const std::vector<PolygonSetup>& setups = group.tiles.setups;
    const std::vector<Shape>& shapes = group.tiles.shapes;
    std::vector<int>& spans = group.tiles.spans;
    std::vector<std::uint32_t>& rowPolygons = group.tiles.rowPolygons;
    rowFirst = std::numeric_limits<int>::max();
    rowLast = -1;
    // Tiles of the row look only at the polygons touching the row: a large group spans many
    // rows, each of its polygons few.
    rowPolygons.clear();
    for (std::size_t i = 0; i < group.count; ++i)
    {
        int& first = spans[4 * i];
        int& last = spans[4 * i + 1];
        spans[4 * i + 2] = 0;
        spans[4 * i + 3] = -1;
        const PixelRange& p = setups[i].pixels;
        if (shapes[i] == Shape::Convex ? !tileSpan(setups[i], ty, first, last)
                                       : p.empty() || p.y1 < ty * TileSize || p.y0 >= (ty + 1) * TileSize)
        {
            first = 0;
            last = -1;
            continue;
        }
        if (shapes[i] != Shape::Convex)
        {
            first = p.x0 / TileSize;
            last = p.x1 / TileSize;
        }
        else
        {
            rowFirst = std::min(rowFirst, first);
            rowLast = std::max(rowLast, last);
            insideSpan(setups[i], ty * TileSize, std::min(ty * TileSize + TileSize, int(group.mask.height())) - 1,
                       spans[4 * i + 2], spans[4 * i + 3]);
        }
        rowPolygons.push_back(std::uint32_t(i));
    }
}

// Tile (tx, ty) of the current row: the row's polygons over it, merged into the mask unless the
// tile's bound shows that nothing they write could change it. Returns the pixels it covered.
std::size_t rasterizeTile(const GroupRaster& group, int tx, int ty, TileWork& work)
{
    const std::vector<PolygonSetup>& setups = group.tiles.setups;
    const std::vector<Shape>& shapes = group.tiles.shapes;
    const std::vector<int>& spans = group.tiles.spans;
    const float bound = group.mask.tileBound(std::uint32_t(tx), std::uint32_t(ty));
    if (!(group.groupNearest < bound))
        return 0;
    const PixelRange tile =
        intersect(group.maskRange,
                  PixelRange{tx * TileSize, ty * TileSize, tx * TileSize + TileSize - 1, ty * TileSize + TileSize - 1});
    if (group.count > 1)
    {
        // The tighter test over the tile alone, for groups whose polygons lie at different depths.
        float tileNearest = InfiniteDepth;
        for (std::uint32_t i : group.tiles.rowPolygons)
            if (shapes[i] == Shape::Convex && spans[4 * i] <= tx && tx <= spans[4 * i + 1])
                tileNearest = std::min(tileNearest, group.tiles.nearest[i]);
        if (!(tileNearest < bound))
            return 0;
    }
    work.touched = work.vetoed = 0;
    work.contributors = 0;
    for (std::uint32_t i : group.tiles.rowPolygons)
    {
        if (tx < spans[4 * i] || tx > spans[4 * i + 1])
            continue;
        const PixelRange r = intersect(tile, setups[i].pixels);
        if (r.empty())
            continue;
        if (shapes[i] == Shape::Convex)
            polygonInTile(group.kernels, setups[i], tile, tx, ty, spans[4 * i + 2] <= tx && tx <= spans[4 * i + 3],
                          work);
        else // degenerate: vetoes what it touches
            work.vetoed |=
                rectBits(r.x0 - tx * TileSize, r.x1 - tx * TileSize, r.y0 - ty * TileSize, r.y1 - ty * TileSize);
    }
    const std::uint64_t lanes = work.touched & ~work.vetoed;
    return lanes != 0 ? mergeTile(group.kernels, group.mask, tx, ty, tile, lanes, work) : 0;
}
} // namespace

bool maskTileKernelAvailable(MaskTileKernel kernel)
{
    // The AVX2 kernels exist where the compiler could build them; they run where the CPU says so.
    static const bool avx2 = avx2TileKernels() != nullptr && cpuHasAvx2();
    return kernel == MaskTileKernel::Sse2 || avx2;
}

std::size_t rasterizeOccluderGroupTiled(MaskTileKernel kernel, OcclusionMask& mask, const ScreenPolygon* polygons,
                                        std::size_t count, double shrink, MaskRasterScratch& scratch)
{
    if (!prepareGroup(count, mask, shrink))
        return 0;
    if (!scratch.tiles)
        scratch.tiles = std::make_unique<MaskRasterScratch::Tiles>();
    MaskRasterScratch::Tiles& tiles = *scratch.tiles;
    PixelRange region;
    if (!setupGroup(polygons, count, shrink, mask, tiles, region) || region.empty())
        return 0;

    const TileKernels& kernels = kernelsFor(kernel);
    // Every depth a polygon writes is at least its smallest depth over its pixel range; where the
    // mask already holds nothing farther, nothing would change (min keeps the stored depth).
    const float groupNearest = fillNearestDepths(tiles, count, shrink);
    // The whole group at once, by blocks of tiles (front-to-back occluders behind the mask so far).
    if (!mayBeNearerThanMask(mask, region, groupNearest))
        return 0;
    // Per polygon, for the current tile row: the first and last tile column it may touch, and the
    // first and last wholly inside it.
    tiles.spans.resize(4 * count);
    const PixelRange maskRange{0, 0, int(mask.width()) - 1, int(mask.height()) - 1};
    const GroupRaster group{kernels, mask, tiles, count, groupNearest, maskRange};
    TileWork work;
    std::size_t covered = 0;
    for (int ty = region.y0 / TileSize; ty <= region.y1 / TileSize; ++ty)
    {
        int rowFirst = 0, rowLast = -1;
        collectRowPolygons(group, ty, rowFirst, rowLast);
        for (int tx = rowFirst; tx <= rowLast; ++tx)
        {
            const int blockTiles = int(OcclusionMask::BlockTiles);
            if ((tx == rowFirst || tx % blockTiles == 0) &&
                !(groupNearest < mask.blockBound(std::uint32_t(tx / blockTiles), std::uint32_t(ty / blockTiles))))
            {
                tx = (tx / blockTiles + 1) * blockTiles - 1; // the rest of the block
                continue;
            }
            covered += rasterizeTile(group, tx, ty, work);
        }
    }
    return covered;
}

std::size_t rasterizeOccluderGroup(OcclusionMask& mask, const ScreenPolygon* polygons, std::size_t count, double shrink,
                                   MaskRasterScratch& scratch)
{
    return rasterizeOccluderGroupTiled(MaskTileKernel::Avx2, mask, polygons, count, shrink, scratch);
}
} // namespace osgVis::core
