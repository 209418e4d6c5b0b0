// SPDX-License-Identifier: MIT
#include "PvsViewCellCodec.h"

#include "PvsBitsetCodec.h"

#include <string>

namespace osgVis::core
{
void checkViewCellsEncodable(const ViewCellPvs& v, std::uint32_t objectCount)
{
    encodableCount(v.cellIndices.size(), "view cells");
    if (v.cells.size() != v.cellIndices.size() || v.pvs.size() != v.cellIndices.size())
        throw PvsFormatError("cannot encode .pvs: " + std::to_string(v.cellIndices.size()) + " view cell indices, " +
                             std::to_string(v.cells.size()) + " boxes and " + std::to_string(v.pvs.size()) +
                             " sets (one of each per cell)");
    for (std::size_t c = 0; c < v.pvs.size(); ++c)
        if (v.pvs[c].capacity() != objectCount)
            throw PvsFormatError("cannot encode .pvs: view cell " + std::to_string(c) + " has a set of " +
                                 std::to_string(v.pvs[c].capacity()) + " bits for " + std::to_string(objectCount) +
                                 " objects");
}

void writeViewCells(PvsByteWriter& out, const ViewCellPvs& v)
{
    out.u32(v.totalCells);
    out.u32(static_cast<std::uint32_t>(v.cellIndices.size()));
    for (std::size_t c = 0; c < v.cellIndices.size(); ++c)
    {
        out.u32(v.cellIndices[c]);
        out.box(v.cells[c]);
        encodeBitset(v.pvs[c], out);
    }
}

ViewCellPvs readViewCells(PvsByteReader& s, std::uint32_t objectCount)
{
    ViewCellPvs v;
    v.totalCells = s.u32();
    const std::uint32_t count = s.u32();
    if (count > v.totalCells)
        s.fail(std::to_string(count) + " view cells of a bake of " + std::to_string(v.totalCells));
    // note: the smallest cell is an index, a box and a one-byte bitset.
    s.requireItems(count, 4 + 6 * 8 + 1);
    v.cellIndices.reserve(count);
    v.cells.reserve(count);
    v.pvs.reserve(count);
    for (std::uint32_t c = 0; c < count; ++c)
    {
        const std::uint32_t index = s.u32();
        if (index >= v.totalCells)
            s.fail("view cell " + std::to_string(c) + " with index " + std::to_string(index) + " of " +
                   std::to_string(v.totalCells));
        if (c > 0 && index <= v.cellIndices.back())
            s.fail("view cell " + std::to_string(c) + " with index " + std::to_string(index) + " after " +
                   std::to_string(v.cellIndices.back()) + " (indices ascend strictly)");
        v.cellIndices.push_back(index);
        v.cells.push_back(s.finiteBox());
        if (v.cells.back().empty())
            s.fail("view cell " + std::to_string(c) + " (index " + std::to_string(index) + ") with min above max");
        v.pvs.push_back(decodeBitset(s, objectCount));
    }
    return v;
}
} // namespace osgVis::core
