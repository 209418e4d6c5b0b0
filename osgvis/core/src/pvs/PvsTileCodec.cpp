// SPDX-License-Identifier: MIT
#include "PvsTileCodec.h"

#include <stdexcept>
#include <string>
#include <unordered_set>

namespace osgVis::core
{
namespace
{
// The first problem of keys and owners as the reader checks them, or "".
std::string tileProblem(const SceneTiles& t, std::uint32_t objectCount)
{
    std::unordered_set<std::string> names;
    for (std::size_t i = 0; i < t.files.size(); ++i)
    {
        if (t.files[i].empty())
            return "tile " + std::to_string(i) + " has no file name";
        if (!names.insert(t.files[i]).second)
            return "tile " + std::to_string(i) + " repeats the file '" + t.files[i] + "'";
        if (t.owners[i] >= objectCount)
            return "tile " + std::to_string(i) + " owned by object " + std::to_string(t.owners[i]) + " of " +
                   std::to_string(objectCount);
    }
    for (const TileKey& key : t.keys)
        if (key.tile != RootTile && key.tile >= t.files.size())
            return "an object in tile " + std::to_string(key.tile) + " of " + std::to_string(t.files.size());
    // Every owner chain reaches the root within as many steps as there are tiles.
    for (std::size_t i = 0; i < t.files.size(); ++i)
    {
        std::uint32_t tile = std::uint32_t(i);
        for (std::size_t step = 0; tile != RootTile; ++step)
        {
            if (step > t.files.size())
                return "tile " + std::to_string(i) + " lies below itself (its owners form a cycle)";
            tile = t.keys[t.owners[tile]].tile;
        }
    }
    return "";
}
} // namespace

void checkTilesEncodable(const SceneTiles& t, std::uint32_t objectCount)
{
    encodableCount(t.files.size(), "tiles");
    if (!t.complete)
        throw PvsFormatError("cannot encode .pvs: tile keys of a database not wholly loaded");
    if (t.keys.size() != objectCount || t.owners.size() != t.files.size() || t.fingerprints.size() != t.files.size())
        throw PvsFormatError("cannot encode .pvs: " + std::to_string(t.keys.size()) + " tile keys for " +
                             std::to_string(objectCount) + " objects, " + std::to_string(t.owners.size()) +
                             " owners and " + std::to_string(t.fingerprints.size()) + " fingerprints for " +
                             std::to_string(t.files.size()) + " tiles");
    if (const std::string problem = tileProblem(t, objectCount); !problem.empty())
        throw PvsFormatError("cannot encode .pvs: " + problem);
    // The reader numbers each tile's objects in id order: locals that say otherwise would not survive.
    std::vector<std::uint32_t> next(t.files.size() + 1, 0);
    for (const TileKey& key : t.keys)
        if (key.local != next[key.tile == RootTile ? t.files.size() : key.tile]++)
            throw PvsFormatError("cannot encode .pvs: tile locals are not the objects' ranks in id order");
}

void writeTiles(PvsByteWriter& out, const SceneTiles& t)
{
    out.u64(t.rootFingerprint);
    out.u32(static_cast<std::uint32_t>(t.files.size()));
    for (std::size_t i = 0; i < t.files.size(); ++i)
    {
        out.string(t.files[i]);
        out.u64(t.fingerprints[i]);
        out.u32(t.owners[i]);
    }
    for (const TileKey& key : t.keys)
        out.varint(key.tile == RootTile ? 0 : std::uint64_t(key.tile) + 1);
}

SceneTiles readTiles(PvsByteReader& s, std::uint32_t objectCount)
{
    SceneTiles t;
    t.complete = true;
    t.rootFingerprint = s.u64();
    const std::uint32_t count = s.u32();
    // note: the smallest tile is an empty string's length, a fingerprint and an owner.
    s.requireItems(count, 4 + 8 + 4);
    t.files.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i)
    {
        t.files.push_back(s.string());
        t.fingerprints.push_back(s.u64());
        t.owners.push_back(s.u32());
    }
    s.requireItems(objectCount, 1);
    t.keys.resize(objectCount);
    std::vector<std::uint32_t> next(std::size_t(count) + 1, 0);
    for (TileKey& key : t.keys)
    {
        const std::uint64_t tile = s.varint();
        if (tile > count)
            s.fail("an object in tile " + std::to_string(tile - 1) + " of " + std::to_string(count));
        key.tile = tile == 0 ? RootTile : std::uint32_t(tile - 1);
        key.local = next[tile == 0 ? count : tile - 1]++;
    }
    if (const std::string problem = tileProblem(t, objectCount); !problem.empty())
        s.fail(problem);
    return t;
}
} // namespace osgVis::core
