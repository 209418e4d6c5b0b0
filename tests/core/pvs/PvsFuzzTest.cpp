// SPDX-License-Identifier: MIT
// Deterministic mutation fuzzing of valid .pvs files, version 2 with every kind of section and
// the version 1 sample: every mutant either decodes to consistent data or throws PvsFormatError;
// anything else (another exception, a crash, a sanitizer report) fails. Most mutants get their
// body size and CRC-32 repaired so they reach the parser.
#include "PvsSample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <random>

using namespace osgVis::core;

namespace
{
// Version 2's sections, then the parts of its CPDT (version 1's sections but HEAD).
constexpr const char* SectionTags[] = {"HEAD", "BILD", "GEOM", "CPDT", "VCEL", "BNDS", "CELL",
                                       "NAME", "KDTR", "PORT", "CPRT", "SRCS", "STAT"};
constexpr std::size_t SectionTagCount = std::size(SectionTags);

class Mutator
{
public:
    explicit Mutator(const std::vector<std::uint8_t>& valid) : _valid(valid) {}

    std::vector<std::uint8_t> mutate(std::mt19937& random) const
    {
        std::vector<std::uint8_t> bytes = _valid;
        const int steps = 1 + int(random() % 3);
        for (int s = 0; s < steps && !bytes.empty(); ++s)
            mutateOnce(bytes, random);
        return bytes;
    }

private:
    static std::size_t pick(std::mt19937& random, std::size_t size) { return size ? random() % size : 0; }

    // A u32 count placed where a count is (start of a section body, or a node count of a source).
    void overwriteCount(std::vector<std::uint8_t>& bytes, std::mt19937& random) const
    {
        static const std::uint32_t values[] = {0,  1,  2,   3,       4,          5,          36,
                                               37, 38, 255, 0x10000, 0x7FFFFFFF, 0xFFFFFFFE, 0xFFFFFFFF};
        const std::size_t body = osgVis::test::sectionBody(bytes, SectionTags[pick(random, SectionTagCount)]);
        if (body == std::string::npos || body + 4 > bytes.size())
            return;
        // Half the time the count field itself, otherwise any aligned u32 in the first 64 bytes.
        const std::size_t at = (random() & 1) ? body : body + 4 * pick(random, 16);
        if (at + 4 <= bytes.size())
            osgVis::test::putU32(bytes, at, values[pick(random, std::size(values))]);
    }

    void mutateOnce(std::vector<std::uint8_t>& bytes, std::mt19937& random) const
    {
        switch (random() % 7)
        {
        case 0: // bit flip
            bytes[pick(random, bytes.size())] ^= std::uint8_t(1u << (random() % 8));
            break;
        case 1: // byte set to an interesting or random value
        {
            static const std::uint8_t values[] = {0x00, 0x01, 0x7F, 0x80, 0xFF, 0xFE, 0x03};
            bytes[pick(random, bytes.size())] = (random() & 1) ? values[pick(random, 7)] : std::uint8_t(random());
            break;
        }
        case 2: // insertion of 1..8 random bytes
        {
            const std::size_t at = pick(random, bytes.size() + 1);
            const std::size_t n = 1 + random() % 8;
            for (std::size_t i = 0; i < n; ++i)
                bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), std::uint8_t(random()));
            break;
        }
        case 3: // deletion of 1..16 bytes
        {
            const std::size_t at = pick(random, bytes.size());
            const std::size_t n = std::min<std::size_t>(1 + random() % 16, bytes.size() - at);
            bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                        bytes.begin() + static_cast<std::ptrdiff_t>(at + n));
            break;
        }
        case 4: // splice: a range of the valid file copied over another place
        {
            const std::size_t from = pick(random, _valid.size());
            const std::size_t to = pick(random, bytes.size());
            const std::size_t n = std::min({std::size_t(1 + random() % 32), _valid.size() - from, bytes.size() - to});
            std::copy_n(_valid.begin() + static_cast<std::ptrdiff_t>(from), n,
                        bytes.begin() + static_cast<std::ptrdiff_t>(to));
            break;
        }
        case 5:
            overwriteCount(bytes, random);
            break;
        default: // a section length rewritten
        {
            const std::size_t body = osgVis::test::sectionBody(bytes, SectionTags[pick(random, SectionTagCount)]);
            if (body != std::string::npos && body >= 8)
            {
                static const std::uint64_t values[] = {0, 1, 3, 7, 100, 0xFFFFFFFFull, ~std::uint64_t(0)};
                osgVis::test::putU64(bytes, body - 8, values[pick(random, std::size(values))]);
            }
            break;
        }
        }
    }

    const std::vector<std::uint8_t>& _valid;
};

// Everything a consumer indexes with must be in range (the decoder promises it).
void expectConsistent(const PvsFile& file)
{
    const CellPortalData& d = file.data;
    if (d.tiles)
    {
        const SceneTiles& t = *d.tiles;
        ASSERT_EQ(t.keys.size(), d.objectCount);
        ASSERT_EQ(t.owners.size(), t.files.size());
        ASSERT_EQ(t.fingerprints.size(), t.files.size());
        for (ObjectId owner : t.owners)
            ASSERT_LT(owner, d.objectCount);
        for (const TileKey& key : t.keys)
            ASSERT_TRUE(key.tile == RootTile || key.tile < t.files.size());
    }
    const CellGraph& g = d.graph;
    const std::size_t cells = g.cells.size();
    ASSERT_EQ(d.sources.size(), cells);
    ASSERT_EQ(g.cellPortals.size(), cells);
    ASSERT_TRUE(g.cellNames.empty() || g.cellNames.size() == cells);
    for (const CellPortal& p : g.portals)
        ASSERT_TRUE(p.lowCell < cells && p.highCell < cells && p.rect.axis < 3);
    for (std::size_t c = 0; c < cells; ++c)
        for (std::uint32_t p : g.cellPortals[c])
            ASSERT_LT(p, g.portals.size());
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
    {
        const CellGraph::KdNode& node = g.nodes[n];
        if (node.axis == 3)
            ASSERT_LT(node.children[0], cells);
        else
            ASSERT_TRUE(node.children[0] > n && node.children[1] > n && node.children[0] < g.nodes.size() &&
                        node.children[1] < g.nodes.size());
    }
    const ViewCellPvs& v = file.viewCells;
    ASSERT_EQ(v.cells.size(), v.cellIndices.size());
    ASSERT_EQ(v.pvs.size(), v.cellIndices.size());
    for (std::size_t c = 0; c < v.cellIndices.size(); ++c)
    {
        ASSERT_LT(v.cellIndices[c], v.totalCells);
        ASSERT_TRUE(c == 0 || v.cellIndices[c] > v.cellIndices[c - 1]);
        ASSERT_TRUE(v.cells[c].finite() && !v.cells[c].empty());
        ASSERT_EQ(v.pvs[c].capacity(), d.objectCount);
    }
    ASSERT_TRUE(std::isfinite(file.nearDistance) && file.nearDistance >= 0.0);
    for (const SourceCellVisibility& s : d.sources)
    {
        ASSERT_EQ(s.cellToCell.capacity(), cells);
        ASSERT_EQ(s.cellToObject.capacity(), d.objectCount);
        for (std::size_t i = 0; i < s.stabTree.size(); ++i)
        {
            const StabNode& node = s.stabTree[i];
            ASSERT_TRUE(node.portal < g.portals.size() && node.cell < cells);
            ASSERT_TRUE(node.subtreeEnd > i && node.subtreeEnd <= s.stabTree.size());
            ASSERT_TRUE(node.parent == NoStabParent || node.parent < i);
        }
    }
}

// Mutates `valid` 40000 times; each mutant must decode to consistent data that re-encode as
// `reencoded` says, or throw PvsFormatError. Every part in `parts` must see errors of its own.
void fuzz(const std::vector<std::uint8_t>& valid, std::uint32_t seed, const std::vector<std::string>& parts,
          const std::function<void(const PvsFile&, const std::vector<std::uint8_t>&, int)>& reencoded)
{
    const Mutator mutator(valid);
    std::mt19937 random(seed);
    const int cases = 40000;
    int decoded = 0, checksumErrors = 0;
    std::map<std::string, int> errorsBySection; // "while reading <part>" of each message
    for (int n = 0; n < cases; ++n)
    {
        std::vector<std::uint8_t> bytes = mutator.mutate(random);
        if (random() % 10 != 0)
            osgVis::test::fixFraming(bytes);
        try
        {
            const PvsFile file = decodePvs(bytes.data(), bytes.size());
            ++decoded;
            expectConsistent(file);
            reencoded(file, bytes, n);
        }
        catch (const PvsFormatError& e)
        {
            const std::string message = e.what();
            if (message.rfind("checksum mismatch", 0) == 0)
                ++checksumErrors;
            const std::size_t at = message.find("while reading ");
            if (at != std::string::npos)
                ++errorsBySection[message.substr(at + 14, message.find(" (", at) - at - 14)];
        }
        catch (const std::exception& e)
        {
            FAIL() << "case " << n << " threw a " << typeid(e).name() << ": " << e.what();
        }
        if (::testing::Test::HasFatalFailure())
            return;
    }
    // The repaired framing lets most mutants past the checksum into every part of the parser.
    EXPECT_LT(checksumErrors, cases / 5);
    for (const std::string& part : parts)
        EXPECT_GT(errorsBySection[part], 20) << part;
    EXPECT_GT(decoded, 0); // mutants that keep a consistent file (e.g. another double) do decode
    std::cout << cases << " mutants: " << decoded << " decoded, " << checksumErrors << " checksum errors\n";
    for (const auto& [part, count] : errorsBySection)
        std::cout << "  " << count << " errors while reading " << part << "\n";
}
} // namespace

TEST(PvsFuzz, MutantsDecodeConsistentlyOrThrowPvsFormatError)
{
    fuzz(encodePvs(osgVis::test::makeSamplePvs()), 20261123,
         {"section header", "model header", "build identity", "geometry fingerprint", "cell-portal data", "view cells",
          "graph bounds", "cells", "cell names", "kd nodes", "portals", "cell portal lists", "source cells",
          "bake statistics"},
         [](const PvsFile& file, const std::vector<std::uint8_t>& bytes, int n)
         {
             // note: each content has one spelling, so an accepted mutant is exactly what its content
             // encodes to, once the unknown optional sections a mutation may have made are left out.
             const std::vector<std::uint8_t> known =
                 osgVis::test::withSectionsOnly(bytes, {"HEAD", "BILD", "GEOM", "CPDT", "VCEL"});
             ASSERT_EQ(encodePvs(file), known) << "case " << n;
         });
}

// The sample with tile keys: two tiles owned by objects 0 and 1, the other objects in turn in each.
TEST(PvsFuzz, MutantsOfTileKeysDecodeConsistentlyOrThrowPvsFormatError)
{
    PvsFile sample = osgVis::test::makeSamplePvs();
    auto tiles = std::make_shared<SceneTiles>();
    tiles->complete = true;
    tiles->files = {"tile_0000.osgb", "deeper/tile_0001.osgb"};
    tiles->owners = {0, 1};
    tiles->fingerprints = {0x1234, 0x5678};
    tiles->rootFingerprint = 0x9abc;
    std::uint32_t ranks[3] = {0, 0, 0};
    for (ObjectId id = 0; id < sample.data.objectCount; ++id)
    {
        const std::uint32_t tile = id < 2 ? RootTile : id % 2;
        tiles->keys.push_back({tile, ranks[tile == RootTile ? 2 : tile]++});
    }
    sample.data.tiles = tiles;
    fuzz(encodePvs(sample), 20261204, {"tile keys"},
         [](const PvsFile& file, const std::vector<std::uint8_t>& bytes, int n)
         {
             const std::vector<std::uint8_t> known =
                 osgVis::test::withSectionsOnly(bytes, {"HEAD", "BILD", "GEOM", "CPDT", "TILE", "VCEL"});
             ASSERT_EQ(encodePvs(file), known) << "case " << n;
         });
}

TEST(PvsFuzz, Version1MutantsDecodeConsistentlyOrThrowPvsFormatError)
{
    std::ifstream in(std::string(OSGVIS_PVS_TEST_DATA_DIR) + "/sample-v1.pvs", std::ios::binary);
    const std::vector<std::uint8_t> valid((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(valid.empty());
    fuzz(valid, 20261124,
         {"model header", "graph bounds", "cells", "cell names", "kd nodes", "portals", "cell portal lists",
          "source cells", "bake statistics"},
         [](const PvsFile& file, const std::vector<std::uint8_t>& bytes, int n)
         {
             // Saved again, an accepted version 1 mutant becomes version 2 of the same content, which
             // written as version 1 gives the mutant back but for the bake seconds it dropped.
             std::vector<std::uint8_t> withoutSeconds = bytes;
             const std::size_t stat = osgVis::test::sectionBody(bytes, "STAT");
             ASSERT_NE(stat, std::string::npos);
             osgVis::test::putU64(withoutSeconds, stat + 4 + 4 + 4 + 8 + 8 + 8, 0);
             osgVis::test::fixFraming(withoutSeconds);
             ASSERT_EQ(osgVis::test::rewriteAsVersion1(encodePvs(file)), withoutSeconds) << "case " << n;
         });
}
