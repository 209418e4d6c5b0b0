// SPDX-License-Identifier: MIT
// The .pvs format: exact round trips, compact bitsets, and a specific PvsFormatError for each way
// a file can be wrong (docs/pvs-format.md).
#include "PvsSample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

using namespace osgVis::core;
using osgVis::test::fixFraming;
using osgVis::test::makeSamplePvs;
using osgVis::test::putU32;
using osgVis::test::putU64;
using osgVis::test::sectionBody;

namespace
{
void expectSameBox(const Aabb& a, const Aabb& b)
{
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_EQ(a.min[i], b.min[i]);
        EXPECT_EQ(a.max[i], b.max[i]);
    }
}

void expectSameFile(const PvsFile& a, const PvsFile& b)
{
    EXPECT_EQ(a.modelPath, b.modelPath);
    EXPECT_EQ(a.data.fingerprint, b.data.fingerprint);
    EXPECT_EQ(a.data.objectCount, b.data.objectCount);
    const CellGraph& ga = a.data.graph;
    const CellGraph& gb = b.data.graph;
    expectSameBox(ga.bounds, gb.bounds);
    ASSERT_EQ(ga.cells.size(), gb.cells.size());
    for (std::size_t c = 0; c < ga.cells.size(); ++c)
        expectSameBox(ga.cells[c], gb.cells[c]);
    EXPECT_EQ(ga.cellNames, gb.cellNames);
    ASSERT_EQ(ga.portals.size(), gb.portals.size());
    for (std::size_t p = 0; p < ga.portals.size(); ++p)
    {
        const CellPortal &pa = ga.portals[p], &pb = gb.portals[p];
        EXPECT_EQ(pa.rect.axis, pb.rect.axis);
        EXPECT_EQ(pa.rect.coordinate, pb.rect.coordinate);
        EXPECT_EQ(pa.rect.uMin, pb.rect.uMin);
        EXPECT_EQ(pa.rect.uMax, pb.rect.uMax);
        EXPECT_EQ(pa.rect.vMin, pb.rect.vMin);
        EXPECT_EQ(pa.rect.vMax, pb.rect.vMax);
        EXPECT_EQ(pa.lowCell, pb.lowCell);
        EXPECT_EQ(pa.highCell, pb.highCell);
    }
    EXPECT_EQ(ga.cellPortals, gb.cellPortals);
    ASSERT_EQ(ga.nodes.size(), gb.nodes.size());
    for (std::size_t n = 0; n < ga.nodes.size(); ++n)
    {
        EXPECT_EQ(ga.nodes[n].axis, gb.nodes[n].axis);
        EXPECT_EQ(ga.nodes[n].split, gb.nodes[n].split);
        EXPECT_EQ(ga.nodes[n].children[0], gb.nodes[n].children[0]);
        EXPECT_EQ(ga.nodes[n].children[1], gb.nodes[n].children[1]);
    }
    ASSERT_EQ(a.data.sources.size(), b.data.sources.size());
    for (std::size_t c = 0; c < a.data.sources.size(); ++c)
    {
        const SourceCellVisibility &sa = a.data.sources[c], &sb = b.data.sources[c];
        EXPECT_EQ(sa.budgetExceeded, sb.budgetExceeded);
        ASSERT_EQ(sa.stabTree.size(), sb.stabTree.size());
        for (std::size_t n = 0; n < sa.stabTree.size(); ++n)
        {
            EXPECT_EQ(sa.stabTree[n].portal, sb.stabTree[n].portal);
            EXPECT_EQ(sa.stabTree[n].cell, sb.stabTree[n].cell);
            EXPECT_EQ(sa.stabTree[n].parent, sb.stabTree[n].parent);
            EXPECT_EQ(sa.stabTree[n].subtreeEnd, sb.stabTree[n].subtreeEnd);
        }
        EXPECT_EQ(sa.cellToCell.capacity(), sb.cellToCell.capacity());
        EXPECT_EQ(sa.cellToCell.ids(), sb.cellToCell.ids());
        EXPECT_EQ(sa.cellToObject.capacity(), sb.cellToObject.capacity());
        EXPECT_EQ(sa.cellToObject.ids(), sb.cellToObject.ids());
    }
    const BakeStatistics &ta = a.data.statistics, &tb = b.data.statistics;
    EXPECT_EQ(ta.cells, tb.cells);
    EXPECT_EQ(ta.portals, tb.portals);
    EXPECT_EQ(ta.budgetExceededCells, tb.budgetExceededCells);
    EXPECT_EQ(ta.stabNodes, tb.stabNodes);
    EXPECT_EQ(ta.averageVisibleCells, tb.averageVisibleCells);
    EXPECT_EQ(ta.averagePvsObjects, tb.averagePvsObjects);
    EXPECT_EQ(ta.seconds, tb.seconds);
}

// The message of the PvsFormatError that decoding `bytes` throws ("" when it decodes).
std::string decodeError(const std::vector<std::uint8_t>& bytes)
{
    try
    {
        decodePvs(bytes.data(), bytes.size());
    }
    catch (const PvsFormatError& e)
    {
        return e.what();
    }
    return "";
}

// One object bitset per source cell, all of `capacity` bits, the rest of the sample unchanged.
PvsFile sampleWithObjectSets(std::size_t capacity, const std::vector<VisibleSet>& sets)
{
    PvsFile file = makeSamplePvs();
    file.data.objectCount = static_cast<std::uint32_t>(capacity);
    for (std::size_t c = 0; c < 3; ++c)
        file.data.sources[c].cellToObject = sets[c];
    return file;
}

std::filesystem::path freshDirectory(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / ("osgvis-pvs-format-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}
} // namespace

TEST(PvsFormat, RoundTripKeepsEveryField)
{
    const PvsFile original = makeSamplePvs();
    const std::vector<std::uint8_t> bytes = encodePvs(original);
    const PvsFile decoded = decodePvs(bytes.data(), bytes.size());
    expectSameFile(original, decoded);
    EXPECT_EQ(encodePvs(decoded), bytes); // one spelling per content
}

TEST(PvsFormat, EmptyDataRoundTrips)
{
    const PvsFile empty;
    const std::vector<std::uint8_t> bytes = encodePvs(empty);
    expectSameFile(decodePvs(bytes.data(), bytes.size()), empty);
}

TEST(PvsFormat, ChecksumIsZlibCrc32)
{
    const std::string check = "123456789";
    EXPECT_EQ(crc32(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0xCBF43926u);
    EXPECT_EQ(crc32(nullptr, 0), 0u);
}

TEST(PvsFormat, StartsWithMagicAndVersionLittleEndian)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::vector<std::uint8_t> start(bytes.begin(), bytes.begin() + 12);
    EXPECT_EQ(start, (std::vector<std::uint8_t>{'O', 'S', 'G', 'V', 'P', 'V', 'S', 0, 1, 0, 0, 0}));
    const std::size_t head = sectionBody(bytes, "HEAD");
    ASSERT_EQ(head, 32u);
    EXPECT_EQ(bytes[head], 0xef); // fingerprint 0x0123456789abcdef, low byte first
    EXPECT_EQ(bytes[head + 7], 0x01);
}

TEST(PvsFormat, BitsetsOfOddSizesRoundTrip)
{
    std::mt19937 random(7);
    for (std::size_t capacity : {0u, 1u, 2u, 63u, 64u, 65u, 127u, 129u, 1000u, 4097u})
    {
        for (double density : {0.0, 1.0, 0.01, 0.5, 0.97})
        {
            std::vector<VisibleSet> sets;
            for (int c = 0; c < 3; ++c)
            {
                VisibleSet set(capacity);
                std::bernoulli_distribution pick(density);
                for (std::size_t id = 0; id < capacity; ++id)
                    if (pick(random))
                        set.set(static_cast<ObjectId>(id));
                sets.push_back(set);
            }
            const PvsFile original = sampleWithObjectSets(capacity, sets);
            const std::vector<std::uint8_t> bytes = encodePvs(original);
            const PvsFile decoded = decodePvs(bytes.data(), bytes.size());
            for (int c = 0; c < 3; ++c)
            {
                EXPECT_EQ(decoded.data.sources[c].cellToObject, sets[c]) << capacity << " bits, density " << density;
                EXPECT_EQ(decoded.data.sources[c].cellToObject.capacity(), capacity);
            }
        }
    }
}

TEST(PvsFormat, EmptyFullAndClusteredSetsStaySmall)
{
    const std::size_t capacity = 1000000;
    VisibleSet clustered(capacity);
    for (ObjectId id = 5000; id < 7000; ++id)
        clustered.set(id);
    clustered.set(999999);
    const PvsFile file = sampleWithObjectSets(capacity, {VisibleSet(capacity), VisibleSet(capacity, true), clustered});
    const std::vector<std::uint8_t> bytes = encodePvs(file);
    const std::size_t sampleSize = encodePvs(makeSamplePvs()).size();
    // Three million bits take 375 000 bytes as a plain bitset; runs of up to 3-byte varints take:
    // empty 1+3, full 1+1+3, clustered 1+2+2+3+3+1 (runs 5000, 2000, 992999, 1).
    EXPECT_LE(bytes.size(), sampleSize + 30);
    const PvsFile decoded = decodePvs(bytes.data(), bytes.size());
    EXPECT_EQ(decoded.data.sources[0].cellToObject.count(), 0u);
    EXPECT_EQ(decoded.data.sources[1].cellToObject.count(), capacity);
    EXPECT_EQ(decoded.data.sources[2].cellToObject, clustered);
}

TEST(PvsFormat, BadMagicIsNotAPvsFile)
{
    std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    bytes[3] = 'X';
    EXPECT_NE(decodeError(bytes).find("not a .pvs file: bad magic"), std::string::npos) << decodeError(bytes);
    const std::vector<std::uint8_t> text{'s', 'o', 'l', 'i', 'd'};
    EXPECT_NE(decodeError(text).find("bad magic"), std::string::npos);
}

TEST(PvsFormat, NewerVersionSaysWhich)
{
    std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    putU32(bytes, 8, 2);
    fixFraming(bytes);
    EXPECT_EQ(decodeError(bytes), "unsupported .pvs format version 2: this osgVis reads version 1 (the file was "
                                  "written by a newer osgVis)");
    putU32(bytes, 8, 0);
    EXPECT_EQ(decodeError(bytes), "invalid .pvs format version 0");
}

TEST(PvsFormat, EveryTruncationIsAnError)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    for (std::size_t size = 0; size < bytes.size(); ++size)
    {
        const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
        const std::string error = decodeError(cut);
        EXPECT_NE(error.find("truncated at byte " + std::to_string(size) + " while reading"), std::string::npos)
            << size << ": " << error;
    }
}

TEST(PvsFormat, TruncationNamesTheSection)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::size_t portals = sectionBody(bytes, "PORT");
    const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(portals + 10));
    EXPECT_EQ(decodeError(cut), "truncated at byte " + std::to_string(portals + 10) +
                                    " while reading portals (102 bytes announced, 10 present)");
}

TEST(PvsFormat, EveryFlippedByteIsAnError)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    for (std::size_t at = 0; at < bytes.size(); ++at)
        for (std::uint8_t mask : {0x01, 0x80, 0xFF})
        {
            std::vector<std::uint8_t> flipped = bytes;
            flipped[at] ^= mask;
            EXPECT_NE(decodeError(flipped), "") << "byte " << at << " mask " << int(mask);
        }
    std::vector<std::uint8_t> flipped = bytes;
    flipped[sectionBody(bytes, "CELL") + 5] ^= 0x10;
    EXPECT_EQ(decodeError(flipped).rfind("checksum mismatch: the file stores 0x", 0), 0u) << decodeError(flipped);
}

TEST(PvsFormat, HugeCountFailsBeforeAllocating)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    for (const char* tag : {"CELL", "NAME", "KDTR", "PORT", "SRCS"})
    {
        std::vector<std::uint8_t> huge = bytes;
        putU32(huge, sectionBody(huge, tag), 0xFFFFFFFFu);
        fixFraming(huge);
        const std::string error = decodeError(huge);
        // NAME and SRCS must match the cell count; the others are checked against the bytes left.
        const bool mustMatchCells = std::string(tag) == "NAME" || std::string(tag) == "SRCS";
        EXPECT_NE(error.find(mustMatchCells ? "4294967295" : "count 4294967295 of items"), std::string::npos)
            << tag << ": " << error;
    }
    std::vector<std::uint8_t> hugeSection = bytes;
    putU64(hugeSection, sectionBody(bytes, "PORT") - 8, std::uint64_t(1) << 62);
    fixFraming(hugeSection);
    EXPECT_NE(decodeError(hugeSection).find("while reading portals (4611686018427387904 bytes announced"),
              std::string::npos)
        << decodeError(hugeSection);
    // An object count far beyond what the bitsets cover is refused before a set of that size exists.
    std::vector<std::uint8_t> hugeObjects = bytes;
    putU32(hugeObjects, sectionBody(bytes, "HEAD") + 8, 0xFFFFFFF0u);
    fixFraming(hugeObjects);
    EXPECT_NE(decodeError(hugeObjects).find("bitset runs covering 37 of its 4294967280 bits"), std::string::npos)
        << decodeError(hugeObjects);
}

TEST(PvsFormat, InconsistentContentIsNamed)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::size_t cells = sectionBody(bytes, "CELL");
    const std::size_t portals = sectionBody(bytes, "PORT");
    const std::size_t sources = sectionBody(bytes, "SRCS");
    struct Case
    {
        std::size_t at;
        std::uint64_t value;
        int width;
        std::string message;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t nanBits;
    std::memcpy(&nanBits, &nan, 8);
    const std::vector<Case> cases = {
        {cells + 4, nanBits, 8, "non-finite number at byte " + std::to_string(cells + 4) + " while reading cells"},
        {cells + 4, 0x4010000000000000ull, 8, "cell 0 with min above max"}, // min.x = 4 > max.x = 1
        {portals + 4, 3, 1, "portal 0 with axis 3"},
        {portals + 4 + 41, 7, 4, "portal 0 joining cells 7 and 1 of 3"},
        {portals + 4 + 45, 0, 4, "portal 0 joining cells 0 and 0 of 3"},
        // source 0, node 1 (flag, count, then 16 bytes a node): parent 0 made "none".
        {sources + 4 + 1 + 4 + 16 + 8, 0xFFFFFFFFu, 4,
         "stab node 1 of source cell 0 names parent none where "
         "preorder gives 0"},
        // node 0's subtree made to end before node 1, which still names it as parent.
        {sources + 4 + 1 + 4 + 12, 1, 4, "stab node 1 of source cell 0 names parent 0 where preorder gives none"},
        {sources + 4 + 1 + 4 + 12, 3, 4, "stab node 0 of source cell 0 has subtree end 3 outside (0, 2]"},
        {sources + 4 + 1 + 4 + 0, 1, 4,
         "stab node 0 of source cell 0 crosses portal 1 which does not join cells "
         "0 and 1"},
        {sources + 4, 2, 1, "budget flag 2 of source cell 0"},
    };
    for (const Case& c : cases)
    {
        std::vector<std::uint8_t> bad = bytes;
        osgVis::test::putLittleEndian(bad, c.at, c.value, c.width);
        fixFraming(bad);
        EXPECT_NE(decodeError(bad).find(c.message), std::string::npos) << decodeError(bad);
    }
    std::vector<std::uint8_t> trailing = bytes;
    trailing.push_back(0);
    EXPECT_EQ(decodeError(trailing), "1 unexpected bytes after the checksum at byte " + std::to_string(bytes.size()));
}

TEST(PvsFormat, EncoderRefusesInconsistentData)
{
    PvsFile file = makeSamplePvs();
    file.data.sources[1].stabTree[1].portal = 5;
    try
    {
        encodePvs(file);
        FAIL() << "encoded a stab node naming portal 5 of 2";
    }
    catch (const PvsFormatError& e)
    {
        EXPECT_NE(std::string(e.what()).find("cannot encode .pvs, the data are inconsistent: stab node 1 of source "
                                             "cell 1 names portal 5 of 2"),
                  std::string::npos)
            << e.what();
    }
    PvsFile wrongCapacity = makeSamplePvs();
    wrongCapacity.data.sources[2].cellToObject = VisibleSet(36);
    EXPECT_THROW(encodePvs(wrongCapacity), PvsFormatError);
}

TEST(PvsFormat, FileRoundTripLeavesNoTemporary)
{
    const auto dir = freshDirectory("roundtrip");
    const std::string path = (dir / "scene.pvs").string();
    writePvsFile(path, makeSamplePvs());
    expectSameFile(readPvsFile(path), makeSamplePvs());
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    EXPECT_EQ(std::filesystem::file_size(path), encodePvs(makeSamplePvs()).size());
    std::filesystem::remove_all(dir);
}

TEST(PvsFormat, FileErrorsNameThePath)
{
    const auto dir = freshDirectory("errors");
    const std::string missing = (dir / "missing.pvs").string();
    try
    {
        readPvsFile(missing);
        FAIL() << "read a missing file";
    }
    catch (const PvsFormatError& e)
    {
        EXPECT_EQ(std::string(e.what()), "cannot open .pvs file '" + missing + "': No such file or directory");
    }
    const std::string truncated = (dir / "short.pvs").string();
    std::ofstream(truncated, std::ios::binary) << "OSGVPVS";
    try
    {
        readPvsFile(truncated);
        FAIL() << "read a truncated file";
    }
    catch (const PvsFormatError& e)
    {
        EXPECT_EQ(std::string(e.what()), truncated + ": truncated at byte 7 while reading header");
    }
    const std::string unwritable = (dir / "no-such-folder" / "x.pvs").string();
    EXPECT_THROW(writePvsFile(unwritable, makeSamplePvs()), PvsFormatError);
    EXPECT_FALSE(std::filesystem::exists(unwritable + ".tmp"));
    std::filesystem::remove_all(dir);
}
