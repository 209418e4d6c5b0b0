// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Where each object of a paged database comes from: the tile file that loaded it and its place in
/// that tile, a key that does not depend on the order in which tiles were loaded (object ids do).
/// Baked visibility for a paged database is stored by these keys and mapped onto whatever is loaded
/// when it is used (docs/paging.md, "Baked visibility for a paged database").
#include <osgVis/core/scene/TraversalHierarchy.h> // ObjectId

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::core
{
struct Scene;
class VisibleSet;

/// The "tile" of the objects no paged node loads (the root file's own).
constexpr std::uint32_t RootTile = ~std::uint32_t(0);
/// The "tile" of an empty slot (an object gone with its tile): it belongs to no file.
constexpr std::uint32_t NoTile = RootTile - 1;

struct TileKey
{
    std::uint32_t tile = RootTile; ///< index into SceneTiles::files, RootTile or NoTile
    std::uint32_t local = 0;       ///< rank among the tile's objects in id order (finishSceneTiles)
};

struct SceneTiles
{
    std::vector<std::string> files;      ///< per loaded tile: the file its paged node names
    std::vector<ObjectId> owners;        ///< per tile: the placeholder object of the node that loaded it
    std::vector<std::uint64_t> fingerprints; ///< per tile: tileFingerprint (finishSceneTiles)
    std::uint64_t rootFingerprint = 0;   ///< tileFingerprint of RootTile
    std::vector<TileKey> keys;           ///< per object (keys[id])
    /// Every paged node had every child loaded: the scene is the whole database, so a placeholder
    /// stands for exactly the objects below it (propagateToPlaceholders).
    bool complete = false;
};

/// Given each key's tile, numbers the objects of each tile in id order (TileKey::local) and fills
/// the fingerprints (tileFingerprint, SceneFingerprint.h). Throws std::invalid_argument when keys and objects disagree in number, or a key
/// or an owner names no tile or object.
void finishSceneTiles(const Scene& scene, SceneTiles& tiles);

/// The placeholder whose node loaded the tile `object` belongs to; InvalidObject for the root's
/// objects and empty slots.
ObjectId ownerOf(const SceneTiles& tiles, ObjectId object);

/// For a PVS of a complete scene: each placeholder's membership becomes "some object below it is a
/// member" (its own box-based answer is dropped). A hidden placeholder's node is not traversed, so
/// it must be a member exactly when something it would draw is.
void propagateToPlaceholders(const SceneTiles& tiles, VisibleSet& pvs);

/// For each object of `current` (a scene of the same database, with any tiles loaded), its id in
/// `baked` (the complete scene a PVS was baked on): InvalidObject for empty slots. False, with
/// `why` saying what differs, when the root's objects or a loaded tile's differ from the bake's
/// or a loaded tile is not in it: then no object may be judged by that PVS.
bool mapToBakedObjects(const SceneTiles& baked, const SceneTiles& current, std::vector<ObjectId>& bakedOf,
                       std::string& why);
} // namespace osgVis::core
