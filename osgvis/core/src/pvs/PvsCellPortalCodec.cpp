// SPDX-License-Identifier: MIT
// The cell-portal data of a `.pvs` file as parts (docs/pvs-format.md): the sections of version 1
// after its model header, which version 2 keeps, unchanged but for the bake seconds, inside its
// cell-portal section.
#include "PvsCellPortalCodec.h"

#include "PvsBitsetCodec.h"

#include <string>
#include <vector>

namespace osgVis::core
{
namespace
{
constexpr PvsTag BoundsPart{"BNDS", "graph bounds"};
constexpr PvsTag CellPart{"CELL", "cells"};
constexpr PvsTag NamePart{"NAME", "cell names"};
constexpr PvsTag KdPart{"KDTR", "kd nodes"};
constexpr PvsTag PortalPart{"PORT", "portals"};
constexpr PvsTag CellPortalPart{"CPRT", "cell portal lists"};
constexpr PvsTag SourcePart{"SRCS", "source cells"};
constexpr PvsTag StatisticsPart{"STAT", "bake statistics"};

std::string parentText(std::uint32_t parent)
{
    return parent == NoStabParent ? std::string("none") : std::to_string(parent);
}

// "<count> <what> for <cells> cells": a list that must hold one entry per cell, in the reader's
// and the writer's messages alike.
std::string perCellText(std::size_t count, const char* what, std::size_t cells)
{
    return std::to_string(count) + " " + what + " for " + std::to_string(cells) + " cells";
}

// Reads a count that must equal the graph's cell count (or be 0 where `noneAllowed`).
std::uint32_t readPerCellCount(PvsByteReader& s, const CellGraph& g, const char* what, bool noneAllowed = false)
{
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = s.u32();
    if (count != cellCount && !(noneAllowed && count == 0))
        s.fail(perCellText(count, what, cellCount));
    return count;
}

void requirePerCell(std::size_t count, const CellGraph& g, const char* what)
{
    if (count != g.cells.size())
        throw PvsFormatError("cannot encode .pvs: " + perCellText(count, what, g.cells.size()));
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

void readBounds(PvsByteReader& s, CellPortalData& d)
{
    d.graph.bounds = s.finiteBox();
}

void readCells(PvsByteReader& s, CellPortalData& d)
{
    CellGraph& g = d.graph;
    const std::uint32_t count = s.u32();
    s.requireItems(count, 6 * 8);
    g.cells.reserve(count);
    for (std::uint32_t c = 0; c < count; ++c)
    {
        g.cells.push_back(s.finiteBox());
        if (g.cells.back().empty())
            s.fail("cell " + std::to_string(c) + " with min above max");
    }
}

void readCellNames(PvsByteReader& s, CellPortalData& d)
{
    CellGraph& g = d.graph;
    const std::uint32_t count = readPerCellCount(s, g, "cell names", true);
    s.requireItems(count, 4);
    g.cellNames.reserve(count);
    for (std::uint32_t c = 0; c < count; ++c)
        g.cellNames.push_back(s.string());
}

void readKdNodes(PvsByteReader& s, CellPortalData& d)
{
    CellGraph& g = d.graph;
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

void readPortals(PvsByteReader& s, CellPortalData& d)
{
    CellGraph& g = d.graph;
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

void readCellPortals(PvsByteReader& s, CellPortalData& d)
{
    CellGraph& g = d.graph;
    const std::uint32_t count = readPerCellCount(s, g, "portal lists");
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

void readSources(PvsByteReader& s, CellPortalData& d)
{
    CellGraph& g = d.graph;
    const auto cellCount = static_cast<std::uint32_t>(g.cells.size());
    const std::uint32_t count = readPerCellCount(s, g, "source cells");
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

void readStatistics(PvsByteReader& s, CellPortalData& d, std::uint32_t version)
{
    BakeStatistics& st = d.statistics;
    st.cells = s.u32();
    st.portals = s.u32();
    st.budgetExceededCells = s.u32();
    st.stabNodes = s.u64();
    st.averageVisibleCells = s.finiteF64();
    st.averagePvsObjects = s.finiteF64();
    if (version == 1)
        s.finiteF64(); // the bake's seconds: wall-clock time, which version 2 leaves out of the file
}
} // namespace

void checkCellPortalEncodable(const CellPortalData& d)
{
    const CellGraph& g = d.graph;
    encodableCount(g.cells.size(), "cells");
    encodableCount(g.portals.size(), "portals");
    encodableCount(g.nodes.size(), "kd nodes");
    if (!g.cellNames.empty())
        requirePerCell(g.cellNames.size(), g, "cell names");
    requirePerCell(g.cellPortals.size(), g, "portal lists");
    requirePerCell(d.sources.size(), g, "source cells");
    for (std::size_t c = 0; c < d.sources.size(); ++c)
    {
        const SourceCellVisibility& s = d.sources[c];
        encodableCount(s.stabTree.size(), "stab nodes");
        if (s.cellToCell.capacity() != g.cells.size() || s.cellToObject.capacity() != d.objectCount)
            throw PvsFormatError("cannot encode .pvs: source cell " + std::to_string(c) +
                                 " has bitsets of the wrong capacity");
    }
}

void writeCellPortalParts(PvsByteWriter& out, const CellPortalData& d)
{
    const CellGraph& g = d.graph;
    writePart(out, BoundsPart, [&] { out.box(g.bounds); });
    writePart(out, CellPart,
              [&]
              {
                  out.u32(static_cast<std::uint32_t>(g.cells.size()));
                  for (const Aabb& cell : g.cells)
                      out.box(cell);
              });
    writePart(out, NamePart,
              [&]
              {
                  out.u32(static_cast<std::uint32_t>(g.cellNames.size()));
                  for (const std::string& name : g.cellNames)
                      out.string(name);
              });
    writePart(out, KdPart,
              [&]
              {
                  out.u32(static_cast<std::uint32_t>(g.nodes.size()));
                  for (const CellGraph::KdNode& node : g.nodes)
                  {
                      out.u8(node.axis);
                      out.f64(node.split);
                      out.u32(node.children[0]);
                      out.u32(node.children[1]);
                  }
              });
    writePart(out, PortalPart,
              [&]
              {
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
              });
    writePart(out, CellPortalPart,
              [&]
              {
                  out.u32(static_cast<std::uint32_t>(g.cellPortals.size()));
                  for (const std::vector<std::uint32_t>& list : g.cellPortals)
                  {
                      out.u32(encodableCount(list.size(), "portals of one cell"));
                      for (std::uint32_t p : list)
                          out.u32(p);
                  }
              });
    writePart(out, SourcePart,
              [&]
              {
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
              });
    writePart(out, StatisticsPart,
              [&]
              {
                  const BakeStatistics& st = d.statistics;
                  out.u32(st.cells);
                  out.u32(st.portals);
                  out.u32(st.budgetExceededCells);
                  out.u64(st.stabNodes);
                  out.f64(st.averageVisibleCells);
                  out.f64(st.averagePvsObjects);
              });
}

void readCellPortalParts(PvsByteReader& in, CellPortalData& d, std::uint32_t version)
{
    readPart(in, BoundsPart, [&](PvsByteReader& s) { readBounds(s, d); });
    readPart(in, CellPart, [&](PvsByteReader& s) { readCells(s, d); });
    readPart(in, NamePart, [&](PvsByteReader& s) { readCellNames(s, d); });
    readPart(in, KdPart, [&](PvsByteReader& s) { readKdNodes(s, d); });
    readPart(in, PortalPart, [&](PvsByteReader& s) { readPortals(s, d); });
    readPart(in, CellPortalPart, [&](PvsByteReader& s) { readCellPortals(s, d); });
    readPart(in, SourcePart, [&](PvsByteReader& s) { readSources(s, d); });
    readPart(in, StatisticsPart, [&](PvsByteReader& s) { readStatistics(s, d, version); });
}
} // namespace osgVis::core
