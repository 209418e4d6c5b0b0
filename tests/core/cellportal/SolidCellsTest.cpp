// SPDX-License-Identifier: MIT
// Cells and portals from solid space (SubdivisionOptions::fromSolids, docs/cellportal.md "Solid
// space"): rooms of solid wall boxes become cells joined by their doors; what a solid does not
// prove (a face never drawn, a face an unproven solid meets, no eye point, a slit thinner than a
// cell) leaves space open; and on random room grids, nothing a ray from a jittered eye reaches is
// missing from the module's answer.
#include <osgVis/core/cellportal/CellPortalBake.h>
#include <osgVis/core/cellportal/CellPortalModule.h>

#include "BoxScenes.h"
#include "RayCastVisibility.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <deque>
#include <random>

namespace
{
using namespace osgVis::core;
using osgVis::test::addBox;

constexpr std::uint8_t AllFacesOpaque = 0x3f;

// A drawn box that is also a solid box of the scene's solid space.
ObjectId addSolid(Scene& scene, const Vec3& lo, const Vec3& hi, std::uint8_t opaqueFaces = AllFacesOpaque)
{
    scene.solids.boxes.push_back({{lo, hi}, opaqueFaces});
    return addBox(scene, lo, hi, "solid");
}

// nx × ny rooms 4 × 4 × 3 m, walls 0.2 m thick, every inner wall with a 1 m × 2 m door at a
// random place along it, a crate in each room, and an eye point in each room's middle.
struct RoomGrid
{
    Scene scene;
    std::vector<ObjectId> crates;
    std::vector<std::size_t> innerWallSolids; // indices into scene.solids.boxes, one per wall piece
};

RoomGrid roomGrid(int nx, int ny, std::uint32_t seed)
{
    RoomGrid grid;
    Scene& s = grid.scene;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> doorAt(0.4, 2.6);
    const double X = 4.0 * nx, Y = 4.0 * ny;
    addSolid(s, {-0.1, -0.1, -0.2}, {X + 0.1, Y + 0.1, 0.0});
    addSolid(s, {-0.1, -0.1, 3.0}, {X + 0.1, Y + 0.1, 3.2});
    addSolid(s, {-0.1, -0.1, 0.0}, {0.1, Y + 0.1, 3.0});
    addSolid(s, {X - 0.1, -0.1, 0.0}, {X + 0.1, Y + 0.1, 3.0});
    addSolid(s, {-0.1, -0.1, 0.0}, {X + 0.1, 0.1, 3.0});
    addSolid(s, {-0.1, Y - 0.1, 0.0}, {X + 0.1, Y + 0.1, 3.0});
    // A wall along `axis` (0: the wall spans y at x = c; 1: it spans x at y = c), from a to a + 4.
    const auto wall = [&](int axis, double c, double a)
    {
        const double door = a + doorAt(random);
        const auto piece = [&](double from, double to, double z0, double z1)
        {
            grid.innerWallSolids.push_back(s.solids.boxes.size());
            if (axis == 0)
                addSolid(s, {c - 0.1, from, z0}, {c + 0.1, to, z1});
            else
                addSolid(s, {from, c - 0.1, z0}, {to, c + 0.1, z1});
        };
        piece(a, door, 0.0, 3.0);
        piece(door + 1.0, a + 4.0, 0.0, 3.0);
        piece(door, door + 1.0, 2.0, 3.0);
    };
    for (int i = 1; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            wall(0, 4.0 * i, 4.0 * j);
    for (int j = 1; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            wall(1, 4.0 * j, 4.0 * i);
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
        {
            const Vec3 centre(4.0 * i + 2.0, 4.0 * j + 2.0, 1.5);
            grid.crates.push_back(addBox(s, centre - Vec3(0.8, 0.3, 1.5), centre + Vec3(-0.2, 0.3, -0.7), "crate"));
            s.solids.eyePoints.push_back(centre);
        }
    return grid;
}

SubdivisionOptions fromSolids()
{
    SubdivisionOptions options;
    options.fromSolids = true;
    return options;
}

std::vector<std::uint32_t> cellsAt(const CellGraph& graph, const Vec3& p)
{
    std::vector<std::uint32_t> cells;
    graph.locate(p, 1e-6, cells);
    return cells;
}

// Cells reachable from `from` through portals.
std::vector<bool> connected(const CellGraph& graph, std::uint32_t from)
{
    std::vector<bool> seen(graph.cells.size(), false);
    std::deque<std::uint32_t> queue{from};
    seen[from] = true;
    while (!queue.empty())
    {
        const std::uint32_t c = queue.front();
        queue.pop_front();
        for (std::uint32_t p : graph.cellPortals[c])
        {
            const std::uint32_t next = graph.portals[p].otherCell(c);
            if (!seen[next])
                queue.push_back(next), seen[next] = true;
        }
    }
    return seen;
}

TEST(SolidCells, RoomsOfSolidWallsBecomeCellsJoinedByTheirDoors)
{
    RoomGrid grid = roomGrid(3, 1, 7);
    SolidSubdivisionReport report;
    const CellGraph graph = subdivideSolidCells(grid.scene, fromSolids(), &report);
    EXPECT_GT(report.solidLeaves, 0u);
    EXPECT_EQ(report.mixedLeaves, 0u);
    EXPECT_GT(report.closedFaces, 0u);
    // Sightlines from the rooms reach no solid; the thin space outside the shell, where a level
    // compiler drops faces, is no cell (an eye there keeps everything).
    EXPECT_EQ(report.reachedSolidLeaves, 0u);
    EXPECT_GT(report.unreachedOpenLeaves, 0u);
    for (int room = 0; room < 3; ++room)
        EXPECT_EQ(cellsAt(graph, {4.0 * room + 2.0, 2.0, 1.5}).size(), 1u) << "room " << room;
    const std::vector<bool> fromRoom0 = connected(graph, cellsAt(graph, {2.0, 2.0, 1.5})[0]);
    EXPECT_TRUE(fromRoom0[cellsAt(graph, {10.0, 2.0, 1.5})[0]]) << "through both doors";
    // Three rooms and two doorways are all the rooms reach: no wall, floor or ceiling.
    EXPECT_EQ(std::count(fromRoom0.begin(), fromRoom0.end(), true), 5);
    EXPECT_EQ(graph.cells.size(), 5u);
    for (const Vec3& inWall : {Vec3(4.0, 0.2, 1.0), Vec3(4.0, 3.8, 1.0), Vec3(6.0, 2.0, 3.1), Vec3(6.0, 2.0, -0.1)})
        for (std::uint32_t cell : cellsAt(graph, inWall))
            EXPECT_FALSE(fromRoom0[cell]) << inWall.x << "," << inWall.y << "," << inWall.z;
    EXPECT_EQ(graph.cells.size(), subdivideCells(grid.scene, fromSolids()).cells.size());
}

TEST(SolidCells, AFaceNeverDrawnLetsSightlinesIntoItsSolid)
{
    RoomGrid grid = roomGrid(2, 1, 3);
    // The first piece of the inner wall: its face towards room 0 (x low face) is not drawn.
    SolidBox& piece = grid.scene.solids.boxes[grid.innerWallSolids[0]];
    piece.opaqueFaces &= std::uint8_t(~1u);
    const Vec3 inside = (piece.box.min + piece.box.max) * 0.5;
    SolidSubdivisionReport report;
    const CellGraph graph = subdivideSolidCells(grid.scene, fromSolids(), &report);
    EXPECT_GT(report.reachedSolidLeaves, 0u);
    EXPECT_FALSE(cellsAt(graph, inside).empty());
    // Its face towards room 1 is drawn: the way from the wall into room 1 stays closed there.
    EXPECT_GT(report.closedFaces, 0u);
}

TEST(SolidCells, WithoutEyePointsOrWhereAnUnprovenSolidMeetsItNoFaceIsTrusted)
{
    RoomGrid grid = roomGrid(2, 1, 3);
    Scene noEyes = grid.scene;
    noEyes.solids.eyePoints.clear();
    SolidSubdivisionReport report;
    subdivideSolidCells(noEyes, fromSolids(), &report);
    EXPECT_EQ(report.eyeSpaceLeaves, 0u);
    EXPECT_EQ(report.closedFaces, 0u);
    EXPECT_EQ(report.reachedSolidLeaves, report.solidLeaves);
    EXPECT_EQ(report.unreachedOpenLeaves, 0u);

    Scene unproven = grid.scene;
    const Aabb wall = unproven.solids.boxes[grid.innerWallSolids[0]].box;
    unproven.solids.unproven.push_back({wall.min - Vec3(0.05, 0, 0), Vec3(wall.min.x, wall.max.y, wall.max.z)});
    const CellGraph graph = subdivideSolidCells(unproven, fromSolids(), &report);
    EXPECT_FALSE(cellsAt(graph, (wall.min + wall.max) * 0.5).empty());
}

TEST(SolidCells, APocketAnUnprovenSolidSealsIsNoEyeSpace)
{
    // Room 1's door is blocked by a slanted solid the model states only as an unproven bound: the
    // boxes alone would join room 1 to room 0's eye point through the door, but a level compiler
    // may have filled room 1 as unreached and dropped its faces. Room 1 must trust no face.
    RoomGrid grid = roomGrid(2, 1, 3);
    grid.scene.solids.eyePoints = {{2.0, 2.0, 1.5}};
    const Aabb door = grid.scene.solids.boxes[grid.innerWallSolids[2]].box; // the lintel: x, y of the door
    grid.scene.solids.unproven.push_back({{door.min.x, door.min.y, 0.0}, {door.max.x, door.max.y, 2.0}});
    SolidSubdivisionReport report;
    const CellGraph graph = subdivideSolidCells(grid.scene, fromSolids(), &report);
    const std::vector<std::uint32_t> room1 = cellsAt(graph, {6.0, 2.0, 1.5});
    ASSERT_EQ(room1.size(), 1u);
    // Room 1's walls are cells then: sightlines from room 1 (or through the door) may enter them.
    const std::vector<bool> fromRoom1 = connected(graph, room1[0]);
    const std::vector<std::uint32_t> farWall = cellsAt(graph, {8.0, 2.0, 1.5});
    ASSERT_FALSE(farWall.empty());
    EXPECT_TRUE(fromRoom1[farWall[0]]);
    // Room 0 still trusts its own walls: no portal from it into its west wall (which sightlines
    // from room 1 may reach through the floor and ceiling slabs the rooms share).
    const std::uint32_t room0 = cellsAt(graph, {2.0, 2.0, 1.5})[0];
    for (std::uint32_t wall : cellsAt(graph, {0.0, 2.0, 1.5}))
        for (std::uint32_t p : graph.cellPortals[room0])
            EXPECT_NE(graph.portals[p].otherCell(room0), wall);
}

TEST(SolidCells, ASlitThinnerThanACellStaysOpen)
{
    // Two rooms and a wall between them with no door, only a 0.5 mm slit from floor to ceiling.
    Scene s;
    addSolid(s, {-0.1, -0.1, -0.2}, {8.1, 4.1, 0.0});
    addSolid(s, {-0.1, -0.1, 3.0}, {8.1, 4.1, 3.2});
    addSolid(s, {-0.1, -0.1, 0.0}, {0.1, 4.1, 3.0});
    addSolid(s, {7.9, -0.1, 0.0}, {8.1, 4.1, 3.0});
    addSolid(s, {-0.1, -0.1, 0.0}, {8.1, 0.1, 3.0});
    addSolid(s, {-0.1, 3.9, 0.0}, {8.1, 4.1, 3.0});
    addSolid(s, {3.9, 0.0, 0.0}, {4.1, 2.0, 3.0});
    addSolid(s, {3.9, 2.0005, 0.0}, {4.1, 4.0, 3.0});
    const ObjectId far = addBox(s, {6.0, 1.9, 1.0}, {6.2, 2.1, 1.2}, "far");
    s.solids.eyePoints = {{2, 2, 1.5}, {6, 2, 1.5}};
    BakeOptions bake;
    bake.subdivision = fromSolids();
    bake.subdivision.minCellSize = 1e-3; // cells no thinner than ~9 mm here
    const CellPortalData data = bakeCellPortal(s, bake);
    const std::vector<std::uint32_t> near = cellsAt(data.graph, {2, 2, 1.5});
    ASSERT_EQ(near.size(), 1u);
    EXPECT_TRUE(connected(data.graph, near[0])[cellsAt(data.graph, {6, 2, 1.5})[0]]);
    EXPECT_TRUE(data.sources[near[0]].cellToObject.test(far)) << "seen through the slit";
}

TEST(SolidCells, ModelsThatStateNoSolidsGiveOneCell)
{
    Scene s;
    addBox(s, {0, 0, 0}, {1, 1, 1}, "box");
    SolidSubdivisionReport report;
    const CellGraph graph = subdivideSolidCells(s, fromSolids(), &report);
    EXPECT_EQ(graph.cells.size(), 1u);
    EXPECT_EQ(report.solidBoxes, 0u);
}

View randomView(std::mt19937& random, const Vec3& eye)
{
    std::uniform_real_distribution<double> angle(-3.14159, 3.14159), pitch(-0.6, 0.6), fov(40.0, 100.0);
    const double yaw = angle(random), up = pitch(random);
    const Vec3 direction(std::cos(yaw) * std::cos(up), std::sin(yaw) * std::cos(up), std::sin(up));
    const Mat4 view = glm::lookAt(eye, eye + direction, Vec3(0, 0, 1));
    return makeView(view, glm::perspective(glm::radians(fov(random)), 1.33, 0.05, 100.0), 0.0, 96, 72);
}

TEST(SolidCells, NothingARayReachesIsCulledOnRandomRoomGrids)
{
    for (std::uint32_t seed = 1; seed <= 3; ++seed)
    {
        RoomGrid grid = roomGrid(3, 3, seed);
        BakeOptions bake;
        bake.subdivision = fromSolids();
        auto data = std::make_shared<const CellPortalData>(bakeCellPortal(grid.scene, bake));
        ASSERT_GE(data->graph.cells.size(), 9u);
        CellPortalModule module;
        module.setBakedData(data);
        module.setScene(grid.scene);
        ASSERT_FALSE(module.bakedOnTheSpot());
        const osgVis::test::RayCastVisibility rays(grid.scene);
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> along(0.15, 11.85), height(0.1, 2.9), unit(0.0, 1.0);
        std::size_t culledSomething = 0;
        for (int v = 0; v < 40; ++v)
        {
            Vec3 eye(along(random), along(random), height(random));
            if (v % 4 == 0) // on a wall's plane: in a doorway, or in the wall (no cell: all kept)
                eye.x = 4.0 + 0.1 * (unit(random) < 0.5 ? -1 : 1);
            const View view = randomView(random, eye);
            VisibleSet visible(grid.scene.objects.size(), true);
            module.cull(view, visible);
            culledSomething += visible.count() < grid.scene.objects.size();
            osgVis::test::RayCastOptions options;
            options.samplesPerAxis = 2;
            const osgVis::test::RayCastResult seen = rays.cast(view, options);
            for (ObjectId id : seen.ids())
                EXPECT_TRUE(visible.test(id)) << "seed " << seed << " view " << v << ": object " << id << " ("
                                              << grid.scene.objects[id].name << ") seen but culled, eye "
                                              << eye.x << "," << eye.y << "," << eye.z;
        }
        EXPECT_GT(culledSomething, 10u) << "seed " << seed;
    }
}
} // namespace
