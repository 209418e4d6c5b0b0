// SPDX-License-Identifier: MIT
// Cell-portal data baked on a whole paged database serve a scene with any of its tiles loaded, in
// any order: a row of rooms, each room's crates and its east wall a tile behind a placeholder.
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/pvs/PvsFormat.h>

#include "BoxScenes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace
{
using namespace osgVis::core;
using osgVis::test::addBox;

constexpr int Rooms = 5;
// Doors in the inner walls: the first two line up, the others are offset, so far rooms hide.
const double DoorY[Rooms - 1] = {1.5, 1.5, 0.1, 2.9};

std::string roomFile(int room) { return "room_" + std::to_string(room) + ".osgb"; }

// The root's objects (shell and one placeholder per room), then the tiles of `loaded` in that order.
// `crateShift` moves room 2's crate (a tile edited after the bake).
Scene pagedRow(const std::vector<int>& loaded, double crateShift = 0.0)
{
    Scene s;
    osgVis::test::addRoomRowShell(s, Rooms);
    auto tiles = std::make_shared<SceneTiles>();
    tiles->keys.assign(s.objects.size(), TileKey{});
    std::vector<ObjectId> placeholder;
    for (int room = 0; room < Rooms; ++room)
    {
        placeholder.push_back(s.addObject(Aabb({4.0 * room - 0.1, 0.0, 0.0}, {4.0 * room + 4.1, 4.0, 3.0}), 0));
        tiles->keys.push_back(TileKey{});
    }
    for (int room : loaded)
    {
        const auto tile = std::uint32_t(tiles->files.size());
        tiles->files.push_back(roomFile(room));
        tiles->owners.push_back(placeholder[std::size_t(room)]);
        const double x0 = 4.0 * room + (room == 2 ? crateShift : 0.0);
        addBox(s, {x0 + 1.5, 1.5, 0.0}, {x0 + 2.5, 2.5, 1.0}, "crate");
        addBox(s, {x0 + 0.5, 3.0, 0.0}, {x0 + 1.0, 3.5, 0.5}, "small crate");
        if (room + 1 < Rooms)
        {
            const double x = 4.0 * (room + 1), y = DoorY[room];
            addBox(s, {x - 0.1, 0.0, 0.0}, {x + 0.1, y, 3.0}, "wall");
            addBox(s, {x - 0.1, y + 1.0, 0.0}, {x + 0.1, 4.0, 3.0}, "wall");
            addBox(s, {x - 0.1, y, 2.0}, {x + 0.1, y + 1.0, 3.0}, "lintel");
        }
        tiles->keys.resize(s.objects.size(), TileKey{tile, 0});
    }
    tiles->complete = loaded.size() == std::size_t(Rooms);
    finishSceneTiles(s, *tiles);
    s.tiles = std::move(tiles);
    return s;
}

std::vector<View> viewsInEveryRoom()
{
    std::vector<View> views;
    const Mat4 projection = glm::perspective(glm::radians(70.0), 1.25, 0.1, 200.0);
    for (int room = 0; room < Rooms; ++room)
        for (double y : {0.7, 2.0, 3.3})
            for (int turn = 0; turn < 8; ++turn)
            {
                const double angle = turn * 0.7853981633974483 + 0.1;
                const Vec3 eye(4.0 * room + 2.0, y, 1.6);
                const Vec3 gaze(std::cos(angle), std::sin(angle), turn % 3 == 0 ? -0.3 : 0.05);
                views.push_back(makeView(glm::lookAt(eye, eye + gaze, Vec3(0, 0, 1)), projection));
            }
    return views;
}

VisibleSet culled(VisibilityModule& module, const View& view, std::size_t objects)
{
    VisibleSet visible(objects, true);
    module.cull(view, visible);
    return visible;
}

TEST(TiledBake, PlaceholdersAreInAPvsExactlyWhenAnObjectOfTheirTileIs)
{
    const Scene whole = pagedRow({0, 1, 2, 3, 4});
    const CellPortalData data = bakeCellPortal(whole);
    ASSERT_TRUE(data.tiles);
    std::size_t hiddenPlaceholders = 0;
    for (const SourceCellVisibility& source : data.sources)
        for (std::uint32_t tile = 0; tile < data.tiles->files.size(); ++tile)
        {
            bool anyMember = false;
            for (ObjectId id = 0; id < whole.objects.size(); ++id)
                anyMember = anyMember || (data.tiles->keys[id].tile == tile && source.cellToObject.test(id));
            EXPECT_EQ(source.cellToObject.test(data.tiles->owners[tile]), anyMember);
            hiddenPlaceholders += !anyMember;
        }
    EXPECT_GT(hiddenPlaceholders, 0u) << "the offset doors hide far rooms: some tile must be out of some PVS";
    // A bake of only some tiles keeps no keys: it is tied to exactly that scene.
    EXPECT_FALSE(bakeCellPortal(pagedRow({0, 1})).tiles);
}

TEST(TiledBake, AnyLoadStateIsCulledAsTheWholeDatabaseIs)
{
    const Scene whole = pagedRow({0, 1, 2, 3, 4});
    auto data = std::make_shared<const CellPortalData>(bakeCellPortal(whole));
    registerBakedCellPortalData(data);
    const std::vector<View> views = viewsInEveryRoom();
    for (CellPortalStage stage : {CellPortalStage::EyeToObject, CellPortalStage::CellToObject})
    {
        CellPortalModule reference(stage);
        reference.setScene(whole);
        ASSERT_FALSE(reference.bakedOnTheSpot());
        for (const std::vector<int>& loaded : {std::vector<int>{}, {3, 0, 2}, {4, 1}, {2, 4, 0, 3, 1}})
        {
            const Scene part = pagedRow(loaded);
            CellPortalModule module(stage);
            module.setScene(part);
            ASSERT_TRUE(module.usesTiledBake()) << module.tiledBakeRefusal();
            EXPECT_FALSE(module.bakedOnTheSpot());
            std::vector<ObjectId> bakedOf;
            std::string why;
            ASSERT_TRUE(mapToBakedObjects(*data->tiles, *part.tiles, bakedOf, why)) << why;
            for (const View& view : views)
            {
                const VisibleSet expected = culled(reference, view, whole.objects.size());
                const VisibleSet got = culled(module, view, part.objects.size());
                for (ObjectId id = 0; id < part.objects.size(); ++id)
                    ASSERT_EQ(got.test(id), expected.test(bakedOf[id]))
                        << "object " << id << " (" << part.objects[id].name << ") of tiles loaded " << loaded.size();
            }
        }
    }
}

TEST(TiledBake, AnEditedTileOrAnotherRootIsRefusedAndBakedOnTheSpot)
{
    registerBakedCellPortalData(std::make_shared<const CellPortalData>(bakeCellPortal(pagedRow({0, 1, 2, 3, 4}))));
    CellPortalModule module;
    module.setScene(pagedRow({1, 2}, 0.25));
    EXPECT_FALSE(module.usesTiledBake());
    EXPECT_TRUE(module.bakedOnTheSpot());
    EXPECT_EQ(module.tiledBakeRefusal(), "tile 'room_2.osgb' differs from the one baked");

    Scene unknownTile = pagedRow({1});
    std::const_pointer_cast<SceneTiles>(unknownTile.tiles)->files[0] = "elsewhere.osgb";
    module.setScene(unknownTile);
    EXPECT_FALSE(module.usesTiledBake());
    EXPECT_EQ(module.tiledBakeRefusal(), "tile 'elsewhere.osgb' is not in the bake");

    // The root's objects are the key the data are found by: another root finds nothing to refuse.
    Scene otherRoot = pagedRow({1});
    otherRoot.objects[0].bounds.max.z += 1.0;
    finishSceneTiles(otherRoot, *std::const_pointer_cast<SceneTiles>(otherRoot.tiles));
    module.setScene(otherRoot);
    EXPECT_FALSE(module.usesTiledBake());
    EXPECT_TRUE(module.bakedOnTheSpot());
}

// With nothing paged in, a scene is the root's objects alone and fingerprints as the root does:
// its own bake and the whole database's are stored apart.
TEST(TiledBake, ABakeOfTheRootAloneDoesNotHideTheWholeDatabasesBake)
{
    const Scene whole = pagedRow({0, 1, 2, 3, 4});
    const Scene rootAlone = pagedRow({});
    EXPECT_EQ(sceneFingerprint(rootAlone), rootAlone.tiles->rootFingerprint);
    registerBakedCellPortalData(std::make_shared<const CellPortalData>(bakeCellPortal(whole)));
    registerBakedCellPortalData(std::make_shared<const CellPortalData>(bakeCellPortal(rootAlone)));
    ASSERT_TRUE(findBakedCellPortalDataOfDatabase(rootAlone.tiles->rootFingerprint));
    EXPECT_TRUE(findBakedCellPortalDataOfDatabase(rootAlone.tiles->rootFingerprint)->tiles);
    CellPortalModule module;
    module.setScene(pagedRow({1, 2}));
    EXPECT_TRUE(module.usesTiledBake()) << module.tiledBakeRefusal();
    module.setScene(rootAlone); // its own bake, found by its fingerprint
    EXPECT_FALSE(module.usesTiledBake());
    EXPECT_FALSE(module.bakedOnTheSpot());
}

TEST(TiledBake, TileKeysSurviveTheFileAndTheReaderRefusesBrokenOnes)
{
    PvsFile file;
    file.method = "cellportal";
    file.data = bakeCellPortal(pagedRow({0, 1, 2, 3, 4}));
    const std::vector<std::uint8_t> bytes = encodePvs(file);
    const PvsFile read = decodePvs(bytes.data(), bytes.size());
    ASSERT_TRUE(read.data.tiles);
    const SceneTiles& a = *file.data.tiles;
    const SceneTiles& b = *read.data.tiles;
    EXPECT_EQ(b.files, a.files);
    EXPECT_EQ(b.owners, a.owners);
    EXPECT_EQ(b.fingerprints, a.fingerprints);
    EXPECT_EQ(b.rootFingerprint, a.rootFingerprint);
    ASSERT_EQ(b.keys.size(), a.keys.size());
    for (std::size_t i = 0; i < a.keys.size(); ++i)
    {
        EXPECT_EQ(b.keys[i].tile, a.keys[i].tile);
        EXPECT_EQ(b.keys[i].local, a.keys[i].local);
    }
    EXPECT_TRUE(b.complete);
    EXPECT_EQ(encodePvs(read), bytes);

    const auto encodeError = [&](const std::function<void(SceneTiles&)>& spoil)
    {
        PvsFile broken = file;
        auto tiles = std::make_shared<SceneTiles>(*file.data.tiles);
        spoil(*tiles);
        broken.data.tiles = tiles;
        try
        {
            encodePvs(broken);
        }
        catch (const PvsFormatError& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(encodeError([](SceneTiles& t) { t.files[1] = t.files[0]; }),
              "cannot encode .pvs: tile 1 repeats the file 'room_0.osgb'");
    EXPECT_EQ(encodeError([](SceneTiles& t) { t.files[2].clear(); }), "cannot encode .pvs: tile 2 has no file name");
    EXPECT_EQ(encodeError([](SceneTiles& t) { t.complete = false; }),
              "cannot encode .pvs: tile keys of a database not wholly loaded");
    EXPECT_EQ(encodeError([](SceneTiles& t) { t.owners[0] = 99999; }),
              "cannot encode .pvs: tile 0 owned by object 99999 of " + std::to_string(a.keys.size()));
    // Room 0's placeholder moved into room 1's tile, whose placeholder lies in room 0's: a cycle.
    EXPECT_EQ(encodeError(
                  [](SceneTiles& t)
                  {
                      t.keys[t.owners[0]].tile = 1;
                      t.keys[t.owners[1]].tile = 0;
                  }),
              "cannot encode .pvs: tile 0 lies below itself (its owners form a cycle)");
    EXPECT_EQ(encodeError([](SceneTiles& t) { std::swap(t.keys[0].local, t.keys[1].local); }),
              "cannot encode .pvs: tile locals are not the objects' ranks in id order");
    PvsFile noCellPortal = file;
    noCellPortal.hasCellPortal = false;
    noCellPortal.data.graph = {};
    noCellPortal.data.sources.clear();
    EXPECT_THROW(encodePvs(noCellPortal), PvsFormatError);
}
} // namespace
