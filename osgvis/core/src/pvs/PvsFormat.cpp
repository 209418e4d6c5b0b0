// SPDX-License-Identifier: MIT
// The `.pvs` file, version 1; docs/pvs-format.md is the byte-level description this code follows.
#include <osgVis/core/pvs/PvsFormat.h>

#include "Checksum.h"
#include "PvsBitsetCodec.h"
#include "PvsByteStream.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <utility>

namespace osgVis::core
{
namespace
{
constexpr std::uint8_t Magic[8] = {'O', 'S', 'G', 'V', 'P', 'V', 'S', '\0'};
constexpr std::uint32_t FormatVersion = 1;
constexpr std::size_t HeaderBytes = 20; // magic, version, body size
constexpr std::size_t ChecksumBytes = 4;

// Sections in the order version 1 stores them; `name` is what messages call them.
struct Section
{
    char tag[5];
    const char* name;
};
constexpr Section ModelSection{"HEAD", "model header"};
constexpr Section BoundsSection{"BNDS", "graph bounds"};
constexpr Section CellSection{"CELL", "cells"};
constexpr Section NameSection{"NAME", "cell names"};
constexpr Section KdSection{"KDTR", "kd nodes"};
constexpr Section PortalSection{"PORT", "portals"};
constexpr Section CellPortalSection{"CPRT", "cell portal lists"};
constexpr Section SourceSection{"SRCS", "source cells"};
constexpr Section StatisticsSection{"STAT", "bake statistics"};

std::uint32_t tagValue(const Section& section)
{
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
        value |= std::uint32_t(std::uint8_t(section.tag[i])) << (8 * i);
    return value;
}

std::string tagText(std::uint32_t value)
{
    std::string text;
    for (int i = 0; i < 4; ++i)
    {
        const char c = static_cast<char>(value >> (8 * i));
        text += (c >= 0x20 && c < 0x7F) ? c : '?';
    }
    return text;
}

std::uint32_t checkedCount(std::size_t count, const char* what)
{
    if (count > std::numeric_limits<std::uint32_t>::max())
        throw PvsFormatError(std::string("cannot encode .pvs: too many ") + what);
    return static_cast<std::uint32_t>(count);
}

// A section is its tag, the u64 length of its body, and the body; the length is known at its end.
std::size_t beginSection(PvsByteWriter& out, const Section& section)
{
    out.u32(tagValue(section));
    out.u64(0);
    return out.size();
}

void endSection(PvsByteWriter& out, std::size_t bodyStart)
{
    out.patchU64(bodyStart - 8, out.size() - bodyStart);
}

void writeAabb(PvsByteWriter& out, const Aabb& box)
{
    for (int i = 0; i < 3; ++i)
        out.f64(box.min[i]);
    for (int i = 0; i < 3; ++i)
        out.f64(box.max[i]);
}

// The writer refuses what the reader would refuse, so a bake bug shows when saving, not loading.
void checkEncodable(const PvsFile& file)
{
    const CellPortalData& d = file.data;
    const CellGraph& g = d.graph;
    checkedCount(g.cells.size(), "cells");
    checkedCount(g.portals.size(), "portals");
    checkedCount(g.nodes.size(), "kd nodes");
    if (!g.cellNames.empty() && g.cellNames.size() != g.cells.size())
        throw PvsFormatError("cannot encode .pvs: " + std::to_string(g.cellNames.size()) + " cell names for " +
                             std::to_string(g.cells.size()) + " cells");
    if (g.cellPortals.size() != g.cells.size())
        throw PvsFormatError("cannot encode .pvs: " + std::to_string(g.cellPortals.size()) + " portal lists for " +
                             std::to_string(g.cells.size()) + " cells");
    if (d.sources.size() != g.cells.size())
        throw PvsFormatError("cannot encode .pvs: " + std::to_string(d.sources.size()) + " source cells for " +
                             std::to_string(g.cells.size()) + " cells");
    for (std::size_t c = 0; c < d.sources.size(); ++c)
    {
        const SourceCellVisibility& s = d.sources[c];
        checkedCount(s.stabTree.size(), "stab nodes");
        if (s.cellToCell.capacity() != g.cells.size() || s.cellToObject.capacity() != d.objectCount)
            throw PvsFormatError("cannot encode .pvs: source cell " + std::to_string(c) +
                                 " has bitsets of the wrong capacity");
    }
}

// --- reading -------------------------------------------------------------------------------------

PvsByteReader openSection(PvsByteReader& in, const Section& section)
{
    in.setContext(section.name);
    const std::size_t at = in.position();
    const std::uint32_t tag = in.u32();
    if (tag != tagValue(section))
        throw PvsFormatError("section '" + tagText(tag) + "' at byte " + std::to_string(at) + " where '" + section.tag +
                             "' (" + section.name + ") was expected");
    return in.take(in.u64());
}

void closeSection(const PvsByteReader& body)
{
    if (body.remaining() != 0)
        body.fail(std::to_string(body.remaining()) + " unread bytes at the end of the section");
}

Aabb readAabb(PvsByteReader& in)
{
    Aabb box;
    for (int i = 0; i < 3; ++i)
        box.min[i] = in.finiteF64();
    for (int i = 0; i < 3; ++i)
        box.max[i] = in.finiteF64();
    return box;
}

std::string parentText(std::uint32_t parent)
{
    return parent == NoStabParent ? std::string("none") : std::to_string(parent);
}

// Checks preorder with parent/subtreeEnd consistent, and that every node's portal leads from the
// cell of its parent (the source cell for a first portal) into its own cell.
void checkStabTree(const PvsByteReader& in, const std::vector<StabNode>& nodes, std::uint32_t sourceCell,
                   const CellGraph& graph)
{
    std::vector<std::uint32_t> open; // ancestors of the next node, innermost last
    const auto n = static_cast<std::uint32_t>(nodes.size());
    for (std::uint32_t i = 0; i < n; ++i)
    {
        const StabNode& node = nodes[i];
        // note: built only for a message; a large bake has millions of nodes.
        const auto which = [&]
        { return "stab node " + std::to_string(i) + " of source cell " + std::to_string(sourceCell); };
        while (!open.empty() && nodes[open.back()].subtreeEnd <= i)
            open.pop_back();
        const std::uint32_t expectedParent = open.empty() ? NoStabParent : open.back();
        if (node.parent != expectedParent)
            in.fail(which() + " names parent " + parentText(node.parent) + " where preorder gives " +
                    parentText(expectedParent));
        const std::uint32_t limit = open.empty() ? n : nodes[open.back()].subtreeEnd;
        if (node.subtreeEnd <= i || node.subtreeEnd > limit)
            in.fail(which() + " has subtree end " + std::to_string(node.subtreeEnd) + " outside (" + std::to_string(i) +
                    ", " + std::to_string(limit) + "]");
        if (node.portal >= graph.portals.size())
            in.fail(which() + " names portal " + std::to_string(node.portal) + " of " +
                    std::to_string(graph.portals.size()));
        const CellPortal& portal = graph.portals[node.portal];
        const std::uint32_t from = open.empty() ? sourceCell : nodes[open.back()].cell;
        if (!((portal.lowCell == from && portal.highCell == node.cell) ||
              (portal.highCell == from && portal.lowCell == node.cell)))
            in.fail(which() + " crosses portal " + std::to_string(node.portal) + " which does not join cells " +
                    std::to_string(from) + " and " + std::to_string(node.cell));
        open.push_back(i);
    }
}

void readModelHeader(PvsByteReader& s, PvsFile& file)
{
    CellPortalData& d = file.data;
    d.fingerprint = s.u64();
    d.objectCount = s.u32();
    file.modelPath = s.string();
}

void readBounds(PvsByteReader& s, PvsFile& file)
{
    file.data.graph.bounds = readAabb(s);
}

void readCells(PvsByteReader& s, PvsFile& file)
{
    CellGraph& g = file.data.graph;
    const std::uint32_t count = s.u32();
    s.requireItems(count, 6 * 8);
    g.cells.reserve(count);
    for (std::uint32_t c = 0; c < count; ++c)
    {
        g.cells.push_back(readAabb(s));
        if (g.cells.back().empty())
            s.fail("cell " + std::to_string(c) + " with min above max");
    }
}

void readCellNames(PvsByteReader& s, PvsFile& file)
{
    CellGraph& g = file.data.graph;
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = s.u32();
    if (count != 0 && count != cellCount)
        s.fail(std::to_string(count) + " cell names for " + std::to_string(cellCount) + " cells");
    s.requireItems(count, 4);
    g.cellNames.reserve(count);
    for (std::uint32_t c = 0; c < count; ++c)
        g.cellNames.push_back(s.string());
}

void readKdNodes(PvsByteReader& s, PvsFile& file)
{
    CellGraph& g = file.data.graph;
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = s.u32();
    s.requireItems(count, 1 + 8 + 4 + 4);
    g.nodes.resize(count);
    for (std::uint32_t i = 0; i < count; ++i)
    {
        CellGraph::KdNode& node = g.nodes[i];
        node.axis = s.u8();
        node.split = s.finiteF64();
        node.children[0] = s.u32();
        node.children[1] = s.u32();
        if (node.axis > 3)
            s.fail("kd node " + std::to_string(i) + " with axis " + std::to_string(node.axis));
        const bool leafOk = node.children[0] < cellCount && node.children[1] == NoCell;
        // note: children after their parent keeps every descent finite.
        const bool innerOk =
            node.children[0] > i && node.children[0] < count && node.children[1] > i && node.children[1] < count;
        if (node.axis == 3 ? !leafOk : !innerOk)
            s.fail("kd node " + std::to_string(i) + " with children " + std::to_string(node.children[0]) + ", " +
                   std::to_string(node.children[1]) + " out of range");
    }
}

void readPortals(PvsByteReader& s, PvsFile& file)
{
    CellGraph& g = file.data.graph;
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = s.u32();
    s.requireItems(count, 1 + 5 * 8 + 2 * 4);
    g.portals.resize(count);
    for (std::uint32_t p = 0; p < count; ++p)
    {
        CellPortal& portal = g.portals[p];
        portal.rect.axis = s.u8();
        if (portal.rect.axis > 2)
            s.fail("portal " + std::to_string(p) + " with axis " + std::to_string(portal.rect.axis));
        portal.rect.coordinate = s.finiteF64();
        portal.rect.uMin = s.finiteF64();
        portal.rect.uMax = s.finiteF64();
        portal.rect.vMin = s.finiteF64();
        portal.rect.vMax = s.finiteF64();
        portal.lowCell = s.u32();
        portal.highCell = s.u32();
        if (portal.lowCell >= cellCount || portal.highCell >= cellCount || portal.lowCell == portal.highCell)
            s.fail("portal " + std::to_string(p) + " joining cells " + std::to_string(portal.lowCell) + " and " +
                   std::to_string(portal.highCell) + " of " + std::to_string(cellCount));
    }
}

void readCellPortals(PvsByteReader& s, PvsFile& file)
{
    CellGraph& g = file.data.graph;
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = s.u32();
    if (count != cellCount)
        s.fail(std::to_string(count) + " portal lists for " + std::to_string(cellCount) + " cells");
    s.requireItems(count, 4);
    g.cellPortals.resize(count);
    for (std::uint32_t c = 0; c < count; ++c)
    {
        const std::uint32_t n = s.u32();
        s.requireItems(n, 4);
        g.cellPortals[c].resize(n);
        for (std::uint32_t& p : g.cellPortals[c])
        {
            p = s.u32();
            if (p >= g.portals.size() || (g.portals[p].lowCell != c && g.portals[p].highCell != c))
                s.fail("cell " + std::to_string(c) + " lists portal " + std::to_string(p) + " that does not border it");
        }
    }
}

void readSources(PvsByteReader& s, PvsFile& file)
{
    CellPortalData& d = file.data;
    CellGraph& g = file.data.graph;
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = s.u32();
    if (count != cellCount)
        s.fail(std::to_string(count) + " source cells for " + std::to_string(cellCount) + " cells");
    // note: the smallest source is a flag, a node count and two bitsets of one byte each.
    s.requireItems(count, 1 + 4 + 1 + 1);
    d.sources.resize(count);
    for (std::uint32_t c = 0; c < count; ++c)
    {
        SourceCellVisibility& source = d.sources[c];
        const std::uint8_t flag = s.u8();
        if (flag > 1)
            s.fail("budget flag " + std::to_string(flag) + " of source cell " + std::to_string(c));
        source.budgetExceeded = flag == 1;
        const std::uint32_t n = s.u32();
        s.requireItems(n, 4 * 4);
        source.stabTree.resize(n);
        for (StabNode& node : source.stabTree)
        {
            node.portal = s.u32();
            node.cell = s.u32();
            node.parent = s.u32();
            node.subtreeEnd = s.u32();
        }
        checkStabTree(s, source.stabTree, c, g);
        source.cellToCell = decodeBitset(s, cellCount);
        source.cellToObject = decodeBitset(s, d.objectCount);
    }
}

void readStatistics(PvsByteReader& s, PvsFile& file)
{
    CellPortalData& d = file.data;
    BakeStatistics& st = d.statistics;
    st.cells = s.u32();
    st.portals = s.u32();
    st.budgetExceededCells = s.u32();
    st.stabNodes = s.u64();
    st.averageVisibleCells = s.finiteF64();
    st.averagePvsObjects = s.finiteF64();
    st.seconds = s.finiteF64();
}

// Reads one section with `read`, checking its tag before and that it used its body exactly after.
void readSection(PvsByteReader& in, const Section& section, PvsFile& file, void (*read)(PvsByteReader&, PvsFile&))
{
    PvsByteReader body = openSection(in, section);
    read(body, file);
    closeSection(body);
}

PvsFile readBody(PvsByteReader& in)
{
    PvsFile file;
    readSection(in, ModelSection, file, readModelHeader);
    readSection(in, BoundsSection, file, readBounds);
    readSection(in, CellSection, file, readCells);
    readSection(in, NameSection, file, readCellNames);
    readSection(in, KdSection, file, readKdNodes);
    readSection(in, PortalSection, file, readPortals);
    readSection(in, CellPortalSection, file, readCellPortals);
    readSection(in, SourceSection, file, readSources);
    readSection(in, StatisticsSection, file, readStatistics);
    return file;
}

std::string hex(std::uint32_t value)
{
    char text[11];
    std::snprintf(text, sizeof text, "0x%08x", value);
    return text;
}
} // namespace

std::vector<std::uint8_t> encodePvs(const PvsFile& file)
{
    checkEncodable(file);
    const CellPortalData& d = file.data;
    const CellGraph& g = d.graph;
    PvsByteWriter out;
    for (std::uint8_t byte : Magic)
        out.u8(byte);
    out.u32(FormatVersion);
    out.u64(0); // body size, patched below

    {
        const std::size_t body = beginSection(out, ModelSection);
        out.u64(d.fingerprint);
        out.u32(d.objectCount);
        out.string(file.modelPath);
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, BoundsSection);
        writeAabb(out, g.bounds);
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, CellSection);
        out.u32(static_cast<std::uint32_t>(g.cells.size()));
        for (const Aabb& cell : g.cells)
            writeAabb(out, cell);
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, NameSection);
        out.u32(static_cast<std::uint32_t>(g.cellNames.size()));
        for (const std::string& name : g.cellNames)
            out.string(name);
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, KdSection);
        out.u32(static_cast<std::uint32_t>(g.nodes.size()));
        for (const CellGraph::KdNode& node : g.nodes)
        {
            out.u8(node.axis);
            out.f64(node.split);
            out.u32(node.children[0]);
            out.u32(node.children[1]);
        }
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, PortalSection);
        out.u32(static_cast<std::uint32_t>(g.portals.size()));
        for (const CellPortal& p : g.portals)
        {
            out.u8(p.rect.axis);
            out.f64(p.rect.coordinate);
            out.f64(p.rect.uMin);
            out.f64(p.rect.uMax);
            out.f64(p.rect.vMin);
            out.f64(p.rect.vMax);
            out.u32(p.lowCell);
            out.u32(p.highCell);
        }
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, CellPortalSection);
        out.u32(static_cast<std::uint32_t>(g.cellPortals.size()));
        for (const std::vector<std::uint32_t>& list : g.cellPortals)
        {
            out.u32(checkedCount(list.size(), "portals of one cell"));
            for (std::uint32_t p : list)
                out.u32(p);
        }
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, SourceSection);
        out.u32(static_cast<std::uint32_t>(d.sources.size()));
        for (const SourceCellVisibility& source : d.sources)
        {
            out.u8(source.budgetExceeded ? 1 : 0);
            out.u32(static_cast<std::uint32_t>(source.stabTree.size()));
            for (const StabNode& node : source.stabTree)
            {
                out.u32(node.portal);
                out.u32(node.cell);
                out.u32(node.parent);
                out.u32(node.subtreeEnd);
            }
            encodeBitset(source.cellToCell, out);
            encodeBitset(source.cellToObject, out);
        }
        endSection(out, body);
    }
    {
        const std::size_t body = beginSection(out, StatisticsSection);
        const BakeStatistics& st = d.statistics;
        out.u32(st.cells);
        out.u32(st.portals);
        out.u32(st.budgetExceededCells);
        out.u64(st.stabNodes);
        out.f64(st.averageVisibleCells);
        out.f64(st.averagePvsObjects);
        out.f64(st.seconds);
        endSection(out, body);
    }

    out.patchU64(12, out.size() - HeaderBytes);
    out.u32(crc32(out.bytes().data(), out.size()));
    // The writer's own output must read back: this catches invalid data (bad indices, NaN) at save.
    try
    {
        decodePvs(out.bytes().data(), out.size());
    }
    catch (const PvsFormatError& e)
    {
        throw PvsFormatError(std::string("cannot encode .pvs, the data are inconsistent: ") + e.what());
    }
    return std::move(out.bytes());
}

PvsFile decodePvs(const std::uint8_t* bytes, std::size_t size)
{
    PvsByteReader header(bytes, 0, size);
    const std::size_t magicBytes = std::min(size, sizeof Magic);
    if (magicBytes > 0 && std::memcmp(bytes, Magic, magicBytes) != 0)
        throw PvsFormatError("not a .pvs file: bad magic (the file must start with \"OSGVPVS\\0\")");
    for (std::size_t i = 0; i < sizeof Magic; ++i)
        header.u8();
    header.setContext("format version");
    const std::uint32_t version = header.u32();
    if (version > FormatVersion)
        throw PvsFormatError("unsupported .pvs format version " + std::to_string(version) +
                             ": this osgVis reads version " + std::to_string(FormatVersion) +
                             " (the file was written by a newer osgVis)");
    if (version != FormatVersion)
        throw PvsFormatError("invalid .pvs format version " + std::to_string(version));
    header.setContext("header");
    const std::uint64_t bodySize = header.u64();

    const std::size_t available = size - HeaderBytes;
    if (bodySize > available || available - bodySize < ChecksumBytes)
    {
        // Parse what is there, so the message says in which part the file ends.
        PvsByteReader body(bytes, HeaderBytes, size);
        readBody(body);
        throw PvsFormatError("truncated at byte " + std::to_string(size) +
                             " while reading the checksum (the header announces " + std::to_string(bodySize) +
                             " body bytes)");
    }
    const std::size_t checksumAt = HeaderBytes + static_cast<std::size_t>(bodySize);
    if (available - bodySize > ChecksumBytes)
        throw PvsFormatError(std::to_string(size - checksumAt - ChecksumBytes) +
                             " unexpected bytes after the checksum at byte " +
                             std::to_string(checksumAt + ChecksumBytes));
    PvsByteReader trailer(bytes, checksumAt, size);
    trailer.setContext("checksum");
    const std::uint32_t stored = trailer.u32();
    const std::uint32_t computed = crc32(bytes, checksumAt);
    if (stored != computed)
        throw PvsFormatError("checksum mismatch: the file stores " + hex(stored) + " but its bytes give " +
                             hex(computed) + " (the file is corrupt)");

    PvsByteReader body(bytes, HeaderBytes, checksumAt);
    PvsFile file = readBody(body);
    if (body.remaining() != 0)
        body.fail(std::to_string(body.remaining()) + " unexpected bytes after the last section");
    return file;
}

void writePvsFile(const std::string& path, const PvsFile& file)
{
    const std::vector<std::uint8_t> bytes = encodePvs(file);
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw PvsFormatError("cannot write .pvs file '" + temporary + "': " + std::strerror(errno));
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out)
        {
            std::remove(temporary.c_str());
            throw PvsFormatError("cannot write .pvs file '" + temporary + "' (disk full?)");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
    {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw PvsFormatError("cannot rename '" + temporary + "' to '" + path + "': " + reason);
    }
}

PvsFile readPvsFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw PvsFormatError("cannot open .pvs file '" + path + "': " + std::strerror(errno));
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        throw PvsFormatError("cannot read .pvs file '" + path + "'");
    try
    {
        return decodePvs(bytes.data(), bytes.size());
    }
    catch (const PvsFormatError& e)
    {
        throw PvsFormatError(path + ": " + e.what());
    }
}
} // namespace osgVis::core
