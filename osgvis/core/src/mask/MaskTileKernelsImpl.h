// SPDX-License-Identifier: MIT
// Internal to MaskTileKernelsSse2.cpp and MaskTileKernelsAvx2.cpp, each of which includes it once
// inside an anonymous namespace after defining `Row`: eight float lanes (one tile row) with
// splat/load/store, add/sub/mul/div/min/max, the comparisons as lane masks, and/or/andNot, select,
// a mask from 8 lane bits and back. Written once so the two instruction sets cannot drift apart.
// No include guard: it is a template body, not a header.

// Lane j holds float(j).
inline Row laneIndex()
{
    return Row::load(LaneIndices);
}

inline Row absolute(Row a)
{
    return andNot(Row::splat(-0.0f), a);
}

void tileCoverage(const TileEdges& edges, int rowBegin, int rowEnd, TileCoverage& out)
{
    const Row lanes = laneIndex();
    const Row ambiguity = Row::splat(Ambiguity);
    out = TileCoverage{};
    for (int r = rowBegin; r < rowEnd; ++r)
    {
        Row touched = Row::allSet(), outside = Row::zero(), ambiguous = Row::zero();
        const float rowF = float(r);
        for (std::size_t e = 0; e < edges.count; ++e)
        {
            const Row start = add(Row::splat(edges.f0[e]), mul(Row::splat(edges.ny[e]), Row::splat(rowF)));
            const Row f = add(start, mul(Row::splat(edges.nx[e]), lanes));
            touched = bitAnd(touched, greaterEqual(f, Row::splat(-edges.reach[e])));
            outside = bitOr(outside, less(f, Row::splat(edges.insideLimit[e])));
            ambiguous = bitOr(ambiguous, less(absolute(sub(absolute(f), Row::splat(edges.reach[e]))), ambiguity));
        }
        const int shift = TileSize * r;
        out.touched |= std::uint64_t(laneBits(touched)) << shift;
        out.outside |= std::uint64_t(laneBits(outside)) << shift;
        out.ambiguous |= std::uint64_t(laneBits(ambiguous)) << shift;
    }
}

// Row r of a polygon's depths over the tile.
inline Row planeDepthRow(const TileDepth& plane, int r)
{
    const Row start = add(Row::splat(plane.v0), mul(Row::splat(plane.db), Row::splat(float(r))));
    const Row v = add(start, mul(Row::splat(plane.da), laneIndex()));
    const Row margin = add(mul(add(absolute(v), Row::splat(plane.spread)), Row::splat(TileDepthRelativeMargin)),
                           Row::splat(plane.absMargin));
    if (!plane.inverse)
        return add(v, margin);
    const Row w = sub(v, margin);
    return select(greater(w, Row::zero()), div(Row::splat(1.0f), w), Row::splat(InfiniteDepth));
}

void tileDepthMax(const TileDepth& plane, int rowBegin, int rowEnd, std::uint64_t lanes, float* depth)
{
    for (int r = rowBegin; r < rowEnd; ++r)
    {
        const unsigned bits = unsigned(lanes >> (TileSize * r)) & 0xffu;
        if (bits == 0)
            continue;
        float* out = depth + TileSize * r;
        const Row old = Row::load(out);
        select(fromLaneBits(bits), max(old, planeDepthRow(plane, r)), old).store(out);
    }
}

// Keeps the nearer of row r's stored depths and `d` where `bits` says; returns the merged row.
inline Row mergeRow(float* row, unsigned bits, Row d, std::size_t& covered)
{
    const Row stored = Row::load(row);
    const Row set = fromLaneBits(bits);
    const Row merged = select(set, min(stored, d), stored);
    merged.store(row);
    covered += std::size_t(__builtin_popcount(unsigned(laneBits(bitAnd(set, less(d, Row::splat(InfiniteDepth)))))));
    return merged;
}

float tileMerge(float* const rows[TileSize], std::uint64_t lanes, const float* depth, std::size_t& covered)
{
    Row largest = Row::splat(-InfiniteDepth);
    for (int r = 0; r < TileSize; ++r)
    {
        const unsigned bits = unsigned(lanes >> (TileSize * r)) & 0xffu;
        largest = max(largest, bits == 0 ? Row::load(rows[r])
                                         : mergeRow(rows[r], bits, Row::load(depth + TileSize * r), covered));
    }
    return largestLane(largest);
}

float tilePlaneMerge(float* const rows[TileSize], std::uint64_t lanes, const TileDepth& plane, std::size_t& covered)
{
    Row largest = Row::splat(-InfiniteDepth);
    for (int r = 0; r < TileSize; ++r)
    {
        const unsigned bits = unsigned(lanes >> (TileSize * r)) & 0xffu;
        largest =
            max(largest, bits == 0 ? Row::load(rows[r]) : mergeRow(rows[r], bits, planeDepthRow(plane, r), covered));
    }
    return largestLane(largest);
}

const TileKernels Kernels{tileCoverage, tileDepthMax, tileMerge, tilePlaneMerge};
