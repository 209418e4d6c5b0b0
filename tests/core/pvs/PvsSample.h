// SPDX-License-Identifier: MIT
#pragma once
// A small but complete hand-made .pvs content for the format and fuzz tests, and helpers that
// know the documented byte layout (docs/pvs-format.md) to reach into encoded files.
//
//   three unit cells in a row along x, two portals:
//   +-------+-------+-------+
//   | 0 hall| 1     | 2     |     portal 0 at x = 1 (cells 0|1), portal 1 at x = 2 (cells 1|2)
//   +-------+-------+-------+
//   0       1       2       3
//
//   and view cells 1, 2 and 4 of a bake of 6: boxes of eyes over the same floor, on their own.
#include "pvs/Checksum.h"

#include <osgVis/core/pvs/PvsFormat.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace osgVis::test
{
inline core::VisibleSet makeSet(std::size_t capacity, std::initializer_list<core::ObjectId> ids)
{
    core::VisibleSet set(capacity);
    for (core::ObjectId id : ids)
        set.set(id);
    return set;
}

// What a version 1 file holds: cell-portal data and the model path.
inline core::PvsFile makeCellPortalSample()
{
    using namespace osgVis::core;
    PvsFile file;
    file.modelPath = "models/zwei Räume.osgb"; // non-ASCII on purpose: the path is UTF-8
    CellPortalData& d = file.data;
    d.fingerprint = 0x0123456789abcdefull;
    d.objectCount = 37;
    CellGraph& g = d.graph;
    g.bounds = Aabb({-0.125, -0.25, -0.5}, {3.125, 1.25, 1.5});
    for (int c = 0; c < 3; ++c)
        g.cells.push_back(Aabb({double(c), 0.0, 0.0}, {double(c + 1), 1.0, 1.0}));
    g.cellNames = {"hall", "Küche", ""};
    CellPortal p0, p1;
    p0.rect = {0, 1.0, 0.0, 1.0, 0.25, 0.75};
    p0.lowCell = 0, p0.highCell = 1;
    p1.rect = {0, 2.0, 0.5, 1.0, 0.0, 1.0};
    p1.lowCell = 1, p1.highCell = 2;
    g.portals = {p0, p1};
    g.cellPortals = {{0}, {0, 1}, {1}};
    // kd-tree in preorder: root splits at x = 1, its high child at x = 2.
    g.nodes.resize(5);
    g.nodes[0] = {0, 1.0, {1, 2}};
    g.nodes[1] = {3, 0.0, {0, NoCell}};
    g.nodes[2] = {0, 2.0, {3, 4}};
    g.nodes[3] = {3, 0.0, {1, NoCell}};
    g.nodes[4] = {3, 0.0, {2, NoCell}};

    d.sources.resize(3);
    d.sources[0].stabTree = {{0, 1, NoStabParent, 2}, {1, 2, 0, 2}};
    d.sources[0].cellToCell = makeSet(3, {0, 1, 2});
    d.sources[0].cellToObject = makeSet(37, {0, 1, 2, 3, 10, 11, 36});
    d.sources[1].stabTree = {{0, 0, NoStabParent, 1}, {1, 2, NoStabParent, 2}};
    d.sources[1].cellToCell = makeSet(3, {0, 1, 2});
    d.sources[1].cellToObject = VisibleSet(37, true);
    d.sources[2].stabTree = {{1, 1, NoStabParent, 2}, {0, 0, 0, 2}};
    d.sources[2].budgetExceeded = true;
    d.sources[2].cellToCell = makeSet(3, {1, 2});
    d.sources[2].cellToObject = makeSet(37, {20});

    BakeStatistics& st = d.statistics;
    st.cells = 3, st.portals = 2, st.budgetExceededCells = 1, st.stabNodes = 6;
    st.averageVisibleCells = 8.0 / 3.0, st.averagePvsObjects = 15.0;
    return file;
}

// The view cells of the sample: a range of three cells (1, 2, 4) of a bake of six.
inline core::ViewCellPvs makeSampleViewCells()
{
    using namespace osgVis::core;
    ViewCellPvs cells;
    cells.totalCells = 6;
    cells.cellIndices = {1, 2, 4};
    cells.cells = {Aabb({0, 0, 0}, {1.5, 1, 1}), Aabb({1.5, 0, 0}, {3, 1, 1}),
                   Aabb({0.5, 0.25, 0.5}, {0.5, 0.75, 0.5})};
    cells.pvs = {makeSet(37, {0, 1, 2, 36}), makeSet(37, {}), makeSet(37, {5, 6, 7, 8, 9})};
    return cells;
}

// Every kind of section version 2 has: the cell-portal sample with its build identity, geometry
// fingerprint and view cells.
inline core::PvsFile makeSamplePvs()
{
    core::PvsFile file = makeCellPortalSample();
    file.method = "cellportal";
    file.options = "min-coverage=0.3 stab-budget=50000";
    file.nearDistance = 0.0625;
    file.geometryFingerprint = 0xfedcba9876543210ull;
    file.hasViewCells = true;
    file.viewCells = makeSampleViewCells();
    return file;
}

// A whole view-cell bake of seven cells, a row of unit boxes along x, cell i seeing objects i..i+5
// of 37, for the merge tests.
inline core::PvsFile makeViewCellBake()
{
    using namespace osgVis::core;
    PvsFile file;
    file.modelPath = "office.osgb";
    file.method = "multifocal";
    file.options = "resolution=64";
    file.nearDistance = 0.05;
    file.geometryFingerprint = 0x1111222233334444ull;
    file.data.fingerprint = 0x5555666677778888ull;
    file.data.objectCount = 37;
    file.hasCellPortal = false;
    file.hasViewCells = true;
    file.viewCells.totalCells = 7;
    for (std::uint32_t c = 0; c < 7; ++c)
    {
        file.viewCells.cellIndices.push_back(c);
        file.viewCells.cells.push_back(Aabb({double(c), 0, 0}, {double(c + 1), 1, 1}));
        VisibleSet pvs(37);
        for (ObjectId id = c; id < c + 6; ++id)
            pvs.set(id);
        file.viewCells.pvs.push_back(pvs);
    }
    return file;
}

// The range file a bake of cells [begin, end) of the whole writes: read back from its bytes.
inline core::PvsFile viewCellRange(const core::PvsFile& whole, std::uint32_t begin, std::uint32_t end)
{
    using namespace osgVis::core;
    PvsFile range = whole;
    ViewCellPvs& v = range.viewCells;
    v.cellIndices.assign(whole.viewCells.cellIndices.begin() + begin, whole.viewCells.cellIndices.begin() + end);
    v.cells.assign(whole.viewCells.cells.begin() + begin, whole.viewCells.cells.begin() + end);
    v.pvs.assign(whole.viewCells.pvs.begin() + begin, whole.viewCells.pvs.begin() + end);
    const std::vector<std::uint8_t> bytes = encodePvs(range);
    return decodePvs(bytes.data(), bytes.size());
}

inline std::uint64_t readLittleEndian(const std::vector<std::uint8_t>& bytes, std::size_t at, int width)
{
    std::uint64_t value = 0;
    for (int i = 0; i < width; ++i)
        value |= std::uint64_t(bytes.at(at + i)) << (8 * i);
    return value;
}

inline bool isVersion2(const std::vector<std::uint8_t>& bytes)
{
    return bytes.size() >= 12 && readLittleEndian(bytes, 8, 4) == 2;
}

// One piece as the file frames it: a version 2 section (tag, flags, length) or a part (tag, length),
// as version 1's sections and the parts inside version 2's CPDT are.
struct FramedPiece
{
    std::size_t start = 0, body = 0; // offsets of the tag and of the body
    std::uint64_t length = 0;
    std::string tag;
};

// The pieces framed one after another from `at` to `end` (stopping where the framing breaks).
inline std::vector<FramedPiece> framedPieces(const std::vector<std::uint8_t>& bytes, std::size_t at, std::size_t end,
                                             bool withFlags)
{
    std::vector<FramedPiece> pieces;
    const std::size_t header = withFlags ? 16 : 12;
    while (at + header <= end && end <= bytes.size())
    {
        FramedPiece piece;
        piece.start = at;
        piece.tag.assign(reinterpret_cast<const char*>(&bytes[at]), 4);
        piece.length = readLittleEndian(bytes, at + header - 8, 8);
        piece.body = at + header;
        if (piece.length > end - piece.body)
            break;
        pieces.push_back(piece);
        at = piece.body + piece.length;
    }
    return pieces;
}

// The top-level sections of a file (without its checksum).
inline std::vector<FramedPiece> topLevelPieces(const std::vector<std::uint8_t>& bytes)
{
    return bytes.size() < 24 ? std::vector<FramedPiece>{}
                             : framedPieces(bytes, 20, bytes.size() - 4, isVersion2(bytes));
}

// Byte offset of the body of the section or part `tag`: at the top level, or inside version 2's CPDT.
inline std::size_t sectionBody(const std::vector<std::uint8_t>& bytes, const char* tag)
{
    for (const FramedPiece& piece : topLevelPieces(bytes))
    {
        if (piece.tag == tag)
            return piece.body;
        if (piece.tag == "CPDT" && isVersion2(bytes))
            for (const FramedPiece& part : framedPieces(bytes, piece.body, piece.body + piece.length, false))
                if (part.tag == tag)
                    return part.body;
    }
    return std::string::npos;
}

// Little-endian `width` bytes of `value` at `at` (the bytes must exist).
inline void putLittleEndian(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t value, int width)
{
    for (int i = 0; i < width; ++i)
        bytes.at(at + i) = static_cast<std::uint8_t>(value >> (8 * i));
}

inline void putU32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t value)
{
    putLittleEndian(bytes, at, value, 4);
}

inline void putU64(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t value)
{
    putLittleEndian(bytes, at, value, 8);
}

// Makes the body size and the trailing CRC-32 agree with the bytes again, so that a mutation
// reaches the parser instead of dying at the checksum.
inline void fixFraming(std::vector<std::uint8_t>& bytes)
{
    if (bytes.size() < 24)
        return;
    putU64(bytes, 12, bytes.size() - 24);
    putU32(bytes, bytes.size() - 4, core::crc32(bytes.data(), bytes.size() - 4));
}

// A version 2 file with the section `tag` (flags, payload) inserted before the top-level section
// `before` ("" for after the last one), framing repaired.
inline std::vector<std::uint8_t> withSection(std::vector<std::uint8_t> bytes, const char* tag, std::uint32_t flags,
                                             const std::vector<std::uint8_t>& payload, const std::string& before)
{
    std::size_t at = bytes.size() - 4;
    for (const FramedPiece& piece : topLevelPieces(bytes))
        if (piece.tag == before)
            at = piece.start;
    std::vector<std::uint8_t> section(16 + payload.size());
    std::memcpy(section.data(), tag, 4);
    putU32(section, 4, flags);
    putU64(section, 8, payload.size());
    std::copy(payload.begin(), payload.end(), section.begin() + 16);
    bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), section.begin(), section.end());
    fixFraming(bytes);
    return bytes;
}

// A version 2 file without its top-level sections whose tag is not in `keep`, framing repaired.
inline std::vector<std::uint8_t> withSectionsOnly(const std::vector<std::uint8_t>& bytes,
                                                  const std::vector<std::string>& keep)
{
    std::vector<std::uint8_t> out(bytes.begin(), bytes.begin() + 20);
    for (const FramedPiece& piece : topLevelPieces(bytes))
        if (std::find(keep.begin(), keep.end(), piece.tag) != keep.end())
            out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(piece.start),
                       bytes.begin() + static_cast<std::ptrdiff_t>(piece.body + piece.length));
    out.resize(out.size() + 4);
    fixFraming(out);
    return out;
}

// The same content as version 1 writes it, from a version 2 file holding cell-portal data and no
// view cells: the model header as a part, CPDT's parts as they are, and STAT with its bake seconds
// (0) appended; framing repaired. For tests of what version 1 files do.
inline std::vector<std::uint8_t> rewriteAsVersion1(const std::vector<std::uint8_t>& bytes)
{
    std::vector<std::uint8_t> out(bytes.begin(), bytes.begin() + 20);
    putU32(out, 8, 1);
    for (const FramedPiece& piece : topLevelPieces(bytes))
    {
        if (piece.tag == "HEAD")
        {
            out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(piece.start),
                       bytes.begin() + static_cast<std::ptrdiff_t>(piece.start + 4));
            out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(piece.start + 8),
                       bytes.begin() + static_cast<std::ptrdiff_t>(piece.body + piece.length));
        }
        if (piece.tag != "CPDT")
            continue;
        for (const FramedPiece& part : framedPieces(bytes, piece.body, piece.body + piece.length, false))
        {
            const std::size_t at = out.size();
            out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(part.start),
                       bytes.begin() + static_cast<std::ptrdiff_t>(part.body + part.length));
            if (part.tag == "STAT")
            {
                out.resize(out.size() + 8, 0); // f64 0.0
                putU64(out, at + 4, part.length + 8);
            }
        }
    }
    out.resize(out.size() + 4);
    fixFraming(out);
    return out;
}
} // namespace osgVis::test
