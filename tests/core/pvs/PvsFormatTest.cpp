// SPDX-License-Identifier: MIT
// The .pvs format: exact round trips, one spelling per content, compact bitsets, version 1 files
// still read, the rule for unknown sections, and a specific PvsFormatError for each way a file can
// be wrong (docs/pvs-format.md).
#include "PvsSample.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

using namespace osgVis::core;
using osgVis::test::fixFraming;
using osgVis::test::makeCellPortalSample;
using osgVis::test::makeSamplePvs;
using osgVis::test::makeSampleViewCells;
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

// The file version 1 wrote for makeCellPortalSample() (with no bake seconds), before version 2.
std::vector<std::uint8_t> version1Sample()
{
    std::ifstream in(std::string(OSGVIS_PVS_TEST_DATA_DIR) + "/sample-v1.pvs", std::ios::binary);
    return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void expectSameViewCells(const ViewCellPvs& a, const ViewCellPvs& b)
{
    EXPECT_EQ(a.totalCells, b.totalCells);
    EXPECT_EQ(a.cellIndices, b.cellIndices);
    ASSERT_EQ(a.cells.size(), b.cells.size());
    for (std::size_t c = 0; c < a.cells.size(); ++c)
        expectSameBox(a.cells[c], b.cells[c]);
    ASSERT_EQ(a.pvs.size(), b.pvs.size());
    for (std::size_t c = 0; c < a.pvs.size(); ++c)
    {
        EXPECT_EQ(a.pvs[c].capacity(), b.pvs[c].capacity());
        EXPECT_EQ(a.pvs[c].ids(), b.pvs[c].ids());
    }
}

// The model and the cell-portal data (what version 1 holds too).
void expectSameCellPortalFile(const PvsFile& a, const PvsFile& b)
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
}

void expectSameFile(const PvsFile& a, const PvsFile& b)
{
    expectSameCellPortalFile(a, b);
    EXPECT_EQ(a.method, b.method);
    EXPECT_EQ(a.options, b.options);
    EXPECT_EQ(a.nearDistance, b.nearDistance);
    EXPECT_EQ(a.geometryFingerprint, b.geometryFingerprint);
    EXPECT_EQ(a.hasCellPortal, b.hasCellPortal);
    EXPECT_EQ(a.hasViewCells, b.hasViewCells);
    expectSameViewCells(a.viewCells, b.viewCells);
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

// The message of the PvsFormatError that encoding `file` throws ("" when it encodes).
std::string encodeError(const PvsFile& file)
{
    try
    {
        encodePvs(file);
    }
    catch (const PvsFormatError& e)
    {
        return e.what();
    }
    return "";
}

// One object bitset per source cell, all of `capacity` bits, the rest of the cell-portal sample unchanged.
PvsFile sampleWithObjectSets(std::size_t capacity, const std::vector<VisibleSet>& sets)
{
    PvsFile file = makeCellPortalSample();
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
    EXPECT_EQ(decoded.version, 2u);
    EXPECT_TRUE(decoded.hasCellPortal);
    EXPECT_TRUE(decoded.hasViewCells);
    EXPECT_EQ(encodePvs(decoded), bytes); // one spelling per content
}

TEST(PvsFormat, ViewCellsAloneRoundTrip)
{
    PvsFile original;
    original.modelPath = "city.osgb";
    original.method = "multifocal";
    original.options = "resolution=256";
    original.nearDistance = 0.1;
    original.geometryFingerprint = 42;
    original.data.fingerprint = 7;
    original.data.objectCount = 37;
    original.hasCellPortal = false;
    original.hasViewCells = true;
    original.viewCells = makeSampleViewCells();
    const std::vector<std::uint8_t> bytes = encodePvs(original);
    const PvsFile decoded = decodePvs(bytes.data(), bytes.size());
    expectSameFile(original, decoded);
    EXPECT_FALSE(decoded.hasCellPortal);
    std::vector<std::string> tags;
    for (const osgVis::test::FramedPiece& piece : osgVis::test::topLevelPieces(bytes))
        tags.push_back(piece.tag);
    EXPECT_EQ(tags, (std::vector<std::string>{"HEAD", "BILD", "GEOM", "VCEL"}));
}

TEST(PvsFormat, EmptyDataRoundTrips)
{
    const PvsFile empty;
    const std::vector<std::uint8_t> bytes = encodePvs(empty);
    expectSameFile(decodePvs(bytes.data(), bytes.size()), empty);
}

TEST(PvsFormat, SameContentGivesTheSameBytes)
{
    // The same sets filled in another order, and a set that held more ids before, change nothing.
    PvsFile other = makeSamplePvs();
    VisibleSet reversed(37);
    for (ObjectId id : {9u, 8u, 7u, 6u, 5u, 30u})
        reversed.set(id);
    reversed.clear(30);
    other.viewCells.pvs[2] = reversed;
    EXPECT_EQ(encodePvs(other), encodePvs(makeSamplePvs()));
    other.viewCells.pvs[2].set(30);
    EXPECT_NE(encodePvs(other), encodePvs(makeSamplePvs()));
}

TEST(PvsFormat, ChecksumIsZlibCrc32)
{
    const std::string check = "123456789";
    EXPECT_EQ(crc32(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0xCBF43926u);
    EXPECT_EQ(crc32(nullptr, 0), 0u);
}

TEST(PvsFormat, StartsWithMagicVersionAndSectionsInOrder)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::vector<std::uint8_t> start(bytes.begin(), bytes.begin() + 12);
    EXPECT_EQ(start, (std::vector<std::uint8_t>{'O', 'S', 'G', 'V', 'P', 'V', 'S', 0, 2, 0, 0, 0}));
    std::vector<std::string> tags;
    for (const osgVis::test::FramedPiece& piece : osgVis::test::topLevelPieces(bytes))
    {
        tags.push_back(piece.tag);
        EXPECT_EQ(osgVis::test::readLittleEndian(bytes, piece.start + 4, 4), 1u) << piece.tag << " is required";
    }
    EXPECT_EQ(tags, (std::vector<std::string>{"HEAD", "BILD", "GEOM", "CPDT", "VCEL"}));
    const std::size_t head = sectionBody(bytes, "HEAD");
    ASSERT_EQ(head, 36u);
    EXPECT_EQ(bytes[head], 0xef); // fingerprint 0x0123456789abcdef, low byte first
    EXPECT_EQ(bytes[head + 7], 0x01);
    EXPECT_EQ(osgVis::test::readLittleEndian(bytes, sectionBody(bytes, "GEOM"), 8), 0xfedcba9876543210ull);
    EXPECT_LT(sectionBody(bytes, "CPDT"), sectionBody(bytes, "BNDS"));
    EXPECT_LT(sectionBody(bytes, "STAT"), sectionBody(bytes, "VCEL"));
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
    const std::size_t sampleSize = encodePvs(makeCellPortalSample()).size();
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

TEST(PvsFormat, Version1FilesStillDecode)
{
    const std::vector<std::uint8_t> v1 = version1Sample();
    ASSERT_EQ(v1.size(), 798u) << "tests/core/pvs/data/sample-v1.pvs";
    const PvsFile file = decodePvs(v1.data(), v1.size());
    EXPECT_EQ(file.version, 1u);
    expectSameCellPortalFile(file, makeCellPortalSample());
    EXPECT_EQ(file.method, "cellportal");
    EXPECT_EQ(file.options, "");
    EXPECT_EQ(file.nearDistance, 0.0);
    EXPECT_EQ(file.geometryFingerprint, 0u);
    EXPECT_TRUE(file.hasCellPortal);
    EXPECT_FALSE(file.hasViewCells);
    // Saved again it becomes version 2 with the same content.
    const std::vector<std::uint8_t> v2 = encodePvs(file);
    EXPECT_EQ(v2[8], 2);
    PvsFile again = decodePvs(v2.data(), v2.size());
    EXPECT_EQ(again.version, 2u);
    again.version = 1;
    expectSameFile(again, file);
    // The tests' version 1 writer gives exactly these bytes (the plugin tests use it).
    EXPECT_EQ(osgVis::test::rewriteAsVersion1(encodePvs(makeCellPortalSample())), v1);
}

TEST(PvsFormat, Version1TruncatedOrFlippedIsAnError)
{
    const std::vector<std::uint8_t> v1 = version1Sample();
    ASSERT_FALSE(v1.empty());
    for (std::size_t size = 0; size < v1.size(); ++size)
    {
        const std::vector<std::uint8_t> cut(v1.begin(), v1.begin() + static_cast<std::ptrdiff_t>(size));
        EXPECT_NE(decodeError(cut).find("truncated at byte " + std::to_string(size) + " while reading"),
                  std::string::npos)
            << size << ": " << decodeError(cut);
    }
    for (std::size_t at = 0; at < v1.size(); ++at)
    {
        std::vector<std::uint8_t> flipped = v1;
        flipped[at] ^= 0x01;
        EXPECT_NE(decodeError(flipped), "") << "byte " << at;
    }
}

TEST(PvsFormat, UnknownOptionalSectionIsSkipped)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::vector<std::uint8_t> payload{1, 2, 3, 4, 5};
    for (const char* before : {"HEAD", "BILD", "CPDT", "VCEL", ""})
    {
        const std::vector<std::uint8_t> extra = osgVis::test::withSection(bytes, "XTRA", 0, payload, before);
        ASSERT_EQ(extra.size(), bytes.size() + 16 + payload.size());
        ASSERT_EQ(decodeError(extra), "") << "before '" << before << "'";
        const PvsFile decoded = decodePvs(extra.data(), extra.size());
        expectSameFile(decoded, makeSamplePvs());
        EXPECT_EQ(encodePvs(decoded), bytes); // what this osgVis does not know it does not write back
    }
    // Flag bits other than bit 0 do not make a section required.
    const std::vector<std::uint8_t> reserved = osgVis::test::withSection(bytes, "XTRA", 0xFFFFFFFEu, payload, "");
    EXPECT_EQ(decodeError(reserved), "");
}

TEST(PvsFormat, UnknownRequiredSectionIsRefused)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::vector<std::uint8_t> extra = osgVis::test::withSection(bytes, "XTRA", 1, {1, 2, 3}, "CPDT");
    const std::size_t at = sectionBody(extra, "XTRA") - 16;
    EXPECT_EQ(decodeError(extra), "required section 'XTRA' at byte " + std::to_string(at) +
                                      " is unknown to this osgVis (the file was written by a newer osgVis)");
    const std::vector<std::uint8_t> unprintable = osgVis::test::withSection(bytes, "\x01Q\xffZ", 3, {}, "");
    EXPECT_EQ(decodeError(unprintable).rfind("required section '?Q?Z' at byte ", 0), 0u) << decodeError(unprintable);
}

TEST(PvsFormat, KnownSectionsComeOnceInOrderWithTheirFlags)
{
    const std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    const std::vector<std::uint8_t> noBuild = osgVis::test::withSectionsOnly(bytes, {"HEAD", "GEOM", "CPDT", "VCEL"});
    EXPECT_EQ(decodeError(noBuild), "missing section 'BILD' (build identity) before byte " +
                                        std::to_string(sectionBody(noBuild, "GEOM") - 16));
    const std::vector<std::uint8_t> modelOnly = osgVis::test::withSectionsOnly(bytes, {"HEAD", "BILD"});
    EXPECT_EQ(decodeError(modelOnly), "missing section 'GEOM' (geometry fingerprint) at the end of the file");
    const std::vector<std::uint8_t> noCellPortal =
        osgVis::test::withSectionsOnly(bytes, {"HEAD", "BILD", "GEOM", "VCEL"});
    const PvsFile viewCellsOnly = decodePvs(noCellPortal.data(), noCellPortal.size());
    EXPECT_FALSE(viewCellsOnly.hasCellPortal);
    EXPECT_TRUE(viewCellsOnly.data.graph.cells.empty());
    expectSameViewCells(viewCellsOnly.viewCells, makeSampleViewCells());

    const std::vector<std::uint8_t> twice = osgVis::test::withSection(bytes, "GEOM", 1, {0, 0, 0, 0, 0, 0, 0, 0}, "");
    EXPECT_EQ(decodeError(twice), "section 'GEOM' (geometry fingerprint) at byte " + std::to_string(bytes.size() - 4) +
                                      " out of order or repeated (version 2 stores HEAD, BILD, GEOM, CPDT, CPRG, TILE, VCEL in "
                                      "this order, each at most once)");
    std::vector<std::uint8_t> optional = bytes;
    const std::size_t build = sectionBody(bytes, "BILD") - 16;
    putU32(optional, build + 4, 0);
    fixFraming(optional);
    EXPECT_EQ(decodeError(optional), "section 'BILD' (build identity) at byte " + std::to_string(build) +
                                         " has flags 0x00000000 where 0x00000001 is expected");
}

TEST(PvsFormat, NewerVersionSaysWhich)
{
    std::vector<std::uint8_t> bytes = encodePvs(makeSamplePvs());
    putU32(bytes, 8, 3);
    fixFraming(bytes);
    EXPECT_EQ(decodeError(bytes), "unsupported .pvs format version 3: this osgVis reads versions 1 to 2 (the file "
                                  "was written by a newer osgVis)");
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
    const auto cutAt = [&](std::size_t size) {
        return decodeError(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size)));
    };
    const std::size_t portals = sectionBody(bytes, "PORT");
    EXPECT_EQ(cutAt(portals + 10), "truncated at byte " + std::to_string(portals + 10) +
                                       " while reading portals (102 bytes announced, 10 present)");
    const std::size_t viewCells = sectionBody(bytes, "VCEL");
    const std::size_t viewCellBytes = bytes.size() - 4 - viewCells;
    EXPECT_EQ(cutAt(viewCells + 10), "truncated at byte " + std::to_string(viewCells + 10) +
                                         " while reading view cells (" + std::to_string(viewCellBytes) +
                                         " bytes announced, 10 present)");
    const std::string announced = " (the header announces " + std::to_string(bytes.size() - 24) + " body bytes)";
    const std::size_t betweenSections = sectionBody(bytes, "CPDT") - 16;
    EXPECT_EQ(cutAt(betweenSections),
              "truncated at byte " + std::to_string(betweenSections) + " while reading the next section" + announced);
    EXPECT_EQ(cutAt(bytes.size() - 2),
              "truncated at byte " + std::to_string(bytes.size() - 2) + " while reading the checksum" + announced);
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
    std::vector<std::uint8_t> hugeViewCells = bytes;
    putU32(hugeViewCells, sectionBody(bytes, "VCEL"), 0xFFFFFFFFu);
    putU32(hugeViewCells, sectionBody(bytes, "VCEL") + 4, 0xFFFFFFFFu);
    fixFraming(hugeViewCells);
    EXPECT_NE(decodeError(hugeViewCells).find("count 4294967295 of items of at least 53 bytes exceeds"),
              std::string::npos)
        << decodeError(hugeViewCells);
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
    const std::size_t viewCells = sectionBody(bytes, "VCEL");
    // BILD: method "cellportal" (4 + 10 bytes), options (4 + 34 bytes), then the near distance.
    const std::size_t nearDistance = sectionBody(bytes, "BILD") + 4 + 10 + 4 + 34;
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
        {nearDistance, 0xBFF0000000000000ull, 8, "negative near distance -1 at byte"}, // -1.0
        {nearDistance, nanBits, 8,
         "non-finite number at byte " + std::to_string(nearDistance) + " while reading build identity"},
        // VCEL: total, count, then per cell its index, box and set.
        {viewCells, 2, 4, "3 view cells of a bake of 2"},
        {viewCells + 8, 6, 4, "view cell 0 with index 6 of 6"},
        {viewCells + 8, 2, 4, "view cell 1 with index 2 after 2 (indices ascend strictly)"},
        {viewCells + 12, 0x4010000000000000ull, 8, "view cell 0 (index 1) with min above max"},
        {viewCells + 12, nanBits, 8,
         "non-finite number at byte " + std::to_string(viewCells + 12) + " while reading view cells"},
    };
    for (const Case& c : cases)
    {
        std::vector<std::uint8_t> bad = bytes;
        osgVis::test::putLittleEndian(bad, c.at, c.value, c.width);
        fixFraming(bad);
        EXPECT_NE(decodeError(bad).find(c.message), std::string::npos) << c.message << ": " << decodeError(bad);
    }
    // A view-cell set of another capacity than the object count (here the only sets in the file).
    PvsFile viewCellsOnly = makeSamplePvs();
    viewCellsOnly.hasCellPortal = false;
    viewCellsOnly.data = CellPortalData();
    viewCellsOnly.data.objectCount = 37;
    std::vector<std::uint8_t> moreObjects = encodePvs(viewCellsOnly);
    putU32(moreObjects, sectionBody(moreObjects, "HEAD") + 8, 38);
    fixFraming(moreObjects);
    EXPECT_NE(decodeError(moreObjects).find("bitset runs covering 37 of its 38 bits at byte"), std::string::npos)
        << decodeError(moreObjects);
    EXPECT_NE(decodeError(moreObjects).find("while reading view cells"), std::string::npos) << decodeError(moreObjects);

    std::vector<std::uint8_t> trailing = bytes;
    trailing.push_back(0);
    EXPECT_EQ(decodeError(trailing), "1 unexpected bytes after the checksum at byte " + std::to_string(bytes.size()));
}

TEST(PvsFormat, EncoderRefusesInconsistentData)
{
    PvsFile file = makeSamplePvs();
    file.data.sources[1].stabTree[1].portal = 5;
    EXPECT_EQ(encodeError(file).rfind("cannot encode .pvs, the data are inconsistent: stab node 1 of source cell 1 "
                                      "names portal 5 of 2",
                                      0),
              0u)
        << encodeError(file);
    PvsFile wrongCapacity = makeSamplePvs();
    wrongCapacity.data.sources[2].cellToObject = VisibleSet(36);
    EXPECT_EQ(encodeError(wrongCapacity), "cannot encode .pvs: source cell 2 has bitsets of the wrong capacity");

    PvsFile viewCellCapacity = makeSamplePvs();
    viewCellCapacity.viewCells.pvs[1] = VisibleSet(36);
    EXPECT_EQ(encodeError(viewCellCapacity), "cannot encode .pvs: view cell 1 has a set of 36 bits for 37 objects");
    PvsFile missingBox = makeSamplePvs();
    missingBox.viewCells.cells.pop_back();
    EXPECT_EQ(encodeError(missingBox),
              "cannot encode .pvs: 3 view cell indices, 2 boxes and 3 sets (one of each per cell)");
    PvsFile repeated = makeSamplePvs();
    repeated.viewCells.cellIndices = {1, 1, 4};
    EXPECT_EQ(encodeError(repeated).rfind("cannot encode .pvs, the data are inconsistent: view cell 1 with index 1 "
                                          "after 1 (indices ascend strictly)",
                                          0),
              0u)
        << encodeError(repeated);
    PvsFile nearNaN = makeSamplePvs();
    nearNaN.nearDistance = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(encodeError(nearNaN).find("non-finite number at byte"), std::string::npos) << encodeError(nearNaN);

    // Data a flag says are not there would be left out silently.
    PvsFile unflaggedCells = makeSamplePvs();
    unflaggedCells.hasCellPortal = false;
    EXPECT_EQ(encodeError(unflaggedCells), "cannot encode .pvs: cell-portal data given but hasCellPortal is false");
    PvsFile unflaggedViewCells = makeSamplePvs();
    unflaggedViewCells.hasViewCells = false;
    EXPECT_EQ(encodeError(unflaggedViewCells), "cannot encode .pvs: view cells given but hasViewCells is false");
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
