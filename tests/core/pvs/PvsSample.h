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
#include "pvs/Checksum.h"

#include <osgVis/core/pvs/PvsFormat.h>

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

inline core::PvsFile makeSamplePvs()
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
    st.averageVisibleCells = 8.0 / 3.0, st.averagePvsObjects = 15.0, st.seconds = 0.003125;
    return file;
}

// Byte offset of the body of the section with tag `tag` (after its tag and u64 length).
inline std::size_t sectionBody(const std::vector<std::uint8_t>& bytes, const char* tag)
{
    std::size_t at = 20;
    while (at + 12 <= bytes.size())
    {
        std::uint64_t length = 0;
        for (int i = 0; i < 8; ++i)
            length |= std::uint64_t(bytes[at + 4 + i]) << (8 * i);
        if (std::memcmp(&bytes[at], tag, 4) == 0)
            return at + 12;
        at += 12 + length;
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
} // namespace osgVis::test
