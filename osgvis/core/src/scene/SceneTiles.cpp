// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/SceneTiles.h>

#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/SceneFingerprint.h>
#include <osgVis/core/scene/VisibleSet.h>

#include "TileFingerprints.h"

#include <stdexcept>
#include <unordered_map>

namespace osgVis::core
{
namespace
{
bool inTile(std::uint32_t tile, const SceneTiles& tiles) { return tile < tiles.files.size(); }

// Ids of each tile's objects by local rank; the root's at index files.size().
std::vector<std::vector<ObjectId>> objectsByTile(const SceneTiles& tiles)
{
    std::vector<std::vector<ObjectId>> byTile(tiles.files.size() + 1);
    for (ObjectId id = 0; id < tiles.keys.size(); ++id)
    {
        const TileKey& key = tiles.keys[id];
        if (key.tile == RootTile)
            byTile.back().push_back(id);
        else if (inTile(key.tile, tiles))
            byTile[key.tile].push_back(id);
    }
    return byTile;
}
} // namespace

void finishSceneTiles(const Scene& scene, SceneTiles& tiles)
{
    if (tiles.keys.size() != scene.objects.size())
        throw std::invalid_argument("scene tiles: " + std::to_string(tiles.keys.size()) + " keys for " +
                                    std::to_string(scene.objects.size()) + " objects");
    if (tiles.owners.size() != tiles.files.size())
        throw std::invalid_argument("scene tiles: " + std::to_string(tiles.owners.size()) + " owners for " +
                                    std::to_string(tiles.files.size()) + " tiles");
    for (ObjectId owner : tiles.owners)
        if (owner >= scene.objects.size())
            throw std::invalid_argument("scene tiles: an owner names object " + std::to_string(owner) + " of " +
                                        std::to_string(scene.objects.size()));
    std::vector<std::uint32_t> next(tiles.files.size() + 1, 0);
    for (TileKey& key : tiles.keys)
    {
        if (key.tile == NoTile)
            continue;
        if (key.tile != RootTile && !inTile(key.tile, tiles))
            throw std::invalid_argument("scene tiles: a key names tile " + std::to_string(key.tile) + " of " +
                                        std::to_string(tiles.files.size()));
        key.local = next[key.tile == RootTile ? tiles.files.size() : key.tile]++;
    }
    tiles.fingerprints = tileFingerprintsOf(scene, tiles);
    tiles.rootFingerprint = tiles.fingerprints.back();
    tiles.fingerprints.pop_back();
}

ObjectId ownerOf(const SceneTiles& tiles, ObjectId object)
{
    if (object >= tiles.keys.size() || !inTile(tiles.keys[object].tile, tiles))
        return InvalidObject;
    return tiles.owners[tiles.keys[object].tile];
}

void propagateToPlaceholders(const SceneTiles& tiles, VisibleSet& pvs)
{
    std::vector<bool> isOwner(tiles.keys.size(), false);
    for (ObjectId owner : tiles.owners)
        if (owner < isOwner.size())
        {
            isOwner[owner] = true;
            pvs.clear(owner);
        }
    std::vector<ObjectId> members = pvs.ids();
    for (ObjectId id : members)
        for (ObjectId owner = ownerOf(tiles, id); owner != InvalidObject && !pvs.test(owner);
             owner = ownerOf(tiles, owner))
            pvs.set(owner); // an owner already set has its own owners set too
}

bool mapToBakedObjects(const SceneTiles& baked, const SceneTiles& current, std::vector<ObjectId>& bakedOf,
                       std::string& why)
{
    if (current.rootFingerprint != baked.rootFingerprint)
    {
        why = "the root file's objects differ from the bake's";
        return false;
    }
    std::unordered_map<std::string, std::uint32_t> bakedTile;
    for (std::uint32_t t = 0; t < baked.files.size(); ++t)
        bakedTile.emplace(baked.files[t], t);
    std::vector<std::uint32_t> tileInBake(current.files.size());
    for (std::uint32_t t = 0; t < current.files.size(); ++t)
    {
        const auto found = bakedTile.find(current.files[t]);
        if (found == bakedTile.end())
        {
            why = "tile '" + current.files[t] + "' is not in the bake";
            return false;
        }
        if (current.fingerprints[t] != baked.fingerprints[found->second])
        {
            why = "tile '" + current.files[t] + "' differs from the one baked";
            return false;
        }
        tileInBake[t] = found->second;
    }
    const std::vector<std::vector<ObjectId>> bakedIds = objectsByTile(baked);
    bakedOf.assign(current.keys.size(), InvalidObject);
    for (ObjectId id = 0; id < current.keys.size(); ++id)
    {
        const TileKey& key = current.keys[id];
        if (key.tile == NoTile)
            continue;
        const std::vector<ObjectId>& ids = bakedIds[key.tile == RootTile ? baked.files.size() : tileInBake[key.tile]];
        if (key.local >= ids.size()) // equal fingerprints hash equal counts: only a forged key gets here
        {
            why = "an object lies past its tile's objects in the bake";
            return false;
        }
        bakedOf[id] = ids[key.local];
    }
    return true;
}
} // namespace osgVis::core
