// SPDX-License-Identifier: MIT
// Cell subdivision and portal enumeration on hand-built scenes: which faces count as opaque, the
// exact cells and door portals of two rooms, slits that must stay open, walls that must not block
// (one-sided, transparent, dynamic, slanted), stated cells and portals, point location on and off
// boundaries, and a randomized "no portal missing" check on grids of rooms with random doors.
//
//   two rooms (top view, z up 0..3), wall slab x 4.75..5.25, door y 2..3, z 0..2.25:
//
//     y=5 +-----------+##+-----------+
//         |           |##|           |
//     y=3 |  room 1   +--+  room 2   |
//         |             door         |
//     y=2 |   [desk]  +--+           |
//         |           |##|           |
//     y=0 +-----------+##+-----------+
//         x=0      4.75  5.25       x=10
#include <osgVis/core/cellportal/CellSubdivision.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

using namespace osgVis::core;

namespace
{
void addQuad(std::vector<Triangle>& out, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    out.push_back({Vec3f(a), Vec3f(b), Vec3f(c)});
    out.push_back({Vec3f(a), Vec3f(c), Vec3f(d)});
}

ObjectId addObject(Scene& scene, const std::vector<Triangle>& triangles, std::uint32_t flags)
{
    Aabb bounds;
    for (const Triangle& t : triangles)
        for (const Vec3f& v : {t.a, t.b, t.c})
            bounds.expand(Vec3(v));
    const ObjectId id = scene.addObject(bounds, std::uint32_t(triangles.size()), flags);
    scene.objects[id].firstTriangle = std::uint32_t(scene.triangles.size());
    scene.triangles.insert(scene.triangles.end(), triangles.begin(), triangles.end());
    return id;
}

// The box [lo, hi] as 12 triangles, counter-clockwise seen from outside.
ObjectId addBox(Scene& scene, const Vec3& lo, const Vec3& hi, std::uint32_t flags = OBJECT_NONE)
{
    const Vec3 e = hi - lo;
    const Vec3 x(e.x, 0, 0), y(0, e.y, 0), z(0, 0, e.z);
    std::vector<Triangle> t;
    // Each face: origin, then two edges whose cross product points outwards.
    auto face = [&](const Vec3& o, const Vec3& e1, const Vec3& e2) { addQuad(t, o, o + e1, o + e1 + e2, o + e2); };
    face(lo, z, y);     // -x
    face(lo + x, y, z); // +x
    face(lo, x, z);     // -y
    face(lo + y, z, x); // +y
    face(lo, y, x);     // -z
    face(lo + z, x, y); // +z
    return addObject(scene, t, flags);
}

// A quad object a, b, c, d.
ObjectId addQuadObject(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                       std::uint32_t flags = OBJECT_NONE)
{
    std::vector<Triangle> t;
    addQuad(t, a, b, c, d);
    return addObject(scene, t, flags);
}

// Walls, floor and ceiling of thickness t around the interior [lo, hi], overlapping at the corners.
void addEnclosure(Scene& scene, const Vec3& lo, const Vec3& hi, double t)
{
    addBox(scene, {lo.x - t, lo.y - t, lo.z - t}, {hi.x + t, hi.y + t, lo.z});
    addBox(scene, {lo.x - t, lo.y - t, hi.z}, {hi.x + t, hi.y + t, hi.z + t});
    addBox(scene, {lo.x - t, lo.y - t, lo.z}, {lo.x, hi.y + t, hi.z});
    addBox(scene, {hi.x, lo.y - t, lo.z}, {hi.x + t, hi.y + t, hi.z});
    addBox(scene, {lo.x, lo.y - t, lo.z}, {hi.x, lo.y, hi.z});
    addBox(scene, {lo.x, hi.y, lo.z}, {hi.x, hi.y + t, hi.z});
}

// The picture at the top of the file. Dyadic coordinates: exact in float storage.
Scene twoRooms()
{
    Scene scene;
    addEnclosure(scene, {0, 0, 0}, {10, 5, 3}, 0.25);
    addBox(scene, {4.75, 0, 0}, {5.25, 2, 3});
    addBox(scene, {4.75, 3, 0}, {5.25, 5, 3});
    addBox(scene, {4.75, 2, 2.25}, {5.25, 3, 3}); // lintel
    addBox(scene, {0.5, 0.5, 0}, {2.125, 1.25, 0.75}); // desk: far too small to split a room
    return scene;
}

std::vector<std::uint32_t> locate(const CellGraph& graph, const Vec3& p, double tolerance = 0.0)
{
    std::vector<std::uint32_t> out;
    graph.locate(p, tolerance, out);
    return out;
}

std::uint32_t cellAt(const CellGraph& graph, const Vec3& p)
{
    const std::vector<std::uint32_t> cells = locate(graph, p);
    EXPECT_EQ(cells.size(), 1u) << "at " << p.x << " " << p.y << " " << p.z;
    return cells.empty() ? NoCell : cells.front();
}

void expectBox(const Aabb& box, const Vec3& lo, const Vec3& hi)
{
    EXPECT_EQ(box.min, lo);
    EXPECT_EQ(box.max, hi);
}

void expectRect(const AxialRect& r, int axis, double coordinate, double uMin, double uMax, double vMin, double vMax)
{
    EXPECT_EQ(r.axis, axis);
    EXPECT_EQ(r.coordinate, coordinate);
    EXPECT_EQ(r.uMin, uMin);
    EXPECT_EQ(r.uMax, uMax);
    EXPECT_EQ(r.vMin, vMin);
    EXPECT_EQ(r.vMax, vMax);
}

// Cells reachable from `start` through portals.
std::set<std::uint32_t> reachable(const CellGraph& graph, std::uint32_t start)
{
    std::set<std::uint32_t> seen{start};
    std::vector<std::uint32_t> stack{start};
    while (!stack.empty())
    {
        const std::uint32_t c = stack.back();
        stack.pop_back();
        for (std::uint32_t p : graph.cellPortals[c])
        {
            const std::uint32_t other = graph.portals[p].otherCell(c);
            if (seen.insert(other).second)
                stack.push_back(other);
        }
    }
    return seen;
}

// cellPortals must list exactly the portals naming each cell, in ascending order.
void expectConsistentIndex(const CellGraph& graph)
{
    ASSERT_EQ(graph.cellPortals.size(), graph.cells.size());
    std::vector<std::vector<std::uint32_t>> expected(graph.cells.size());
    for (std::uint32_t p = 0; p < graph.portals.size(); ++p)
    {
        expected[graph.portals[p].lowCell].push_back(p);
        expected[graph.portals[p].highCell].push_back(p);
    }
    EXPECT_EQ(graph.cellPortals, expected);
}

bool inRect(const AxialRect& r, double u, double v, double slack)
{
    return u >= r.uMin - slack && u <= r.uMax + slack && v >= r.vMin - slack && v <= r.vMax + slack;
}
} // namespace

TEST(OpaqueAxialFaces, KeepsTwoSidedAxialRectanglesOnly)
{
    Scene scene;
    addBox(scene, {0, 0, 0}, {1, 2, 3});                                                  // 6 faces
    addBox(scene, {5, 0, 0}, {6, 1, 1}, OBJECT_CULL_BACK);                                // one-sided: none
    addBox(scene, {8, 0, 0}, {9, 1, 1}, OBJECT_TRANSPARENT);                              // none
    addBox(scene, {10, 0, 0}, {11, 1, 1}, OBJECT_DYNAMIC);                                // none
    addQuadObject(scene, {20, 0, 0}, {21, 1, 0}, {21, 1, 2}, {20, 0, 2});                 // slanted: none
    addQuadObject(scene, {30, 0, 0}, {32, 0, 0}, {31.5, 0, 1}, {30.5, 0, 1});             // trapezoid: none
    const ObjectId tessellated = addObject(scene, {}, OBJECT_NONE);
    {
        // A 2×1 wall at y = 40 from four quads: merges into one rectangle.
        std::vector<Triangle> t;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                addQuad(t, {40 + i, 40, j * 0.5}, {40 + i, 40, j * 0.5 + 0.5}, {41 + i, 40, j * 0.5 + 0.5},
                        {41 + i, 40, j * 0.5});
        scene.objects[tessellated].firstTriangle = std::uint32_t(scene.triangles.size());
        scene.objects[tessellated].triangleCount = std::uint32_t(t.size());
        scene.objects[tessellated].bounds = Aabb({40, 40, 0}, {42, 40, 1});
        scene.triangles.insert(scene.triangles.end(), t.begin(), t.end());
    }
    // Stated occluders: an axial rectangle counts (with a collinear extra vertex), a slanted one not.
    scene.occluders.push_back({ConvexPolygon({{50, 0, 0}, {52, 0, 0}, {52, 1, 0}, {51, 1, 0}, {50, 1, 0}}), InvalidObject});
    scene.occluders.push_back({ConvexPolygon({{60, 0, 0}, {62, 0, 1}, {62, 1, 1}, {60, 1, 0}}), InvalidObject});

    const std::vector<OpaqueFace> faces = findOpaqueAxialFaces(scene);
    ASSERT_EQ(faces.size(), 8u);
    std::set<std::pair<int, double>> planes;
    for (int i = 0; i < 6; ++i)
    {
        EXPECT_EQ(faces[i].owner, 0u);
        planes.insert({faces[i].rect.axis, faces[i].rect.coordinate});
    }
    EXPECT_EQ(planes, (std::set<std::pair<int, double>>{{0, 0}, {0, 1}, {1, 0}, {1, 2}, {2, 0}, {2, 3}}));
    EXPECT_EQ(faces[6].owner, tessellated);
    expectRect(faces[6].rect, 1, 40, 0, 1, 40, 42); // y plane: u = z, v = x
    EXPECT_EQ(faces[7].owner, InvalidObject);
    expectRect(faces[7].rect, 2, 0, 50, 52, 0, 1);
}

TEST(CellSubdivision, TwoRoomsDoorInThickWall)
{
    const Scene scene = twoRooms();
    const CellGraph graph = subdivideCells(scene);
    expectConsistentIndex(graph);
    ASSERT_FALSE(graph.nodes.empty());
    EXPECT_TRUE(graph.cellNames.empty());

    const std::uint32_t room1 = cellAt(graph, {2.5, 2.5, 1.5});
    const std::uint32_t door = cellAt(graph, {5, 2.5, 1});
    const std::uint32_t room2 = cellAt(graph, {7.5, 2.5, 1.5});
    ASSERT_NE(room1, NoCell);
    ASSERT_NE(door, NoCell);
    ASSERT_NE(room2, NoCell);
    expectBox(graph.cells[room1], {0, 0, 0}, {4.75, 5, 3});
    expectBox(graph.cells[door], {4.75, 2, 0}, {5.25, 3, 2.25});
    expectBox(graph.cells[room2], {5.25, 0, 0}, {10, 5, 3});
    EXPECT_EQ(cellAt(graph, {1, 1, 1}), room1); // over the desk: the desk did not split the room

    ASSERT_EQ(graph.cellPortals[room1].size(), 1u);
    ASSERT_EQ(graph.cellPortals[room2].size(), 1u);
    ASSERT_EQ(graph.cellPortals[door].size(), 2u);
    const CellPortal& west = graph.portals[graph.cellPortals[room1][0]];
    const CellPortal& east = graph.portals[graph.cellPortals[room2][0]];
    expectRect(west.rect, 0, 4.75, 2, 3, 0, 2.25); // x plane: u = y, v = z
    EXPECT_EQ(west.lowCell, room1);
    EXPECT_EQ(west.highCell, door);
    expectRect(east.rect, 0, 5.25, 2, 3, 0, 2.25);
    EXPECT_EQ(east.lowCell, door);
    EXPECT_EQ(east.highCell, room2);
    // Sealed: no portal leads through the wall, the floor, the ceiling or out of the building.
    EXPECT_EQ(reachable(graph, room1), (std::set<std::uint32_t>{room1, door, room2}));
    for (const CellPortal& p : graph.portals)
    {
        const double y = 0.5 * (p.rect.uMin + p.rect.uMax), z = 0.5 * (p.rect.vMin + p.rect.vMax);
        const bool inWallSlab = p.rect.axis == 0 && p.rect.coordinate >= 4.75 && p.rect.coordinate <= 5.25 &&
                                y > 0 && y < 5 && z > 0 && z < 3;
        if (inWallSlab)
        {
            EXPECT_TRUE(y > 2 && y < 3 && z < 2.25) << "portal in the wall at x " << p.rect.coordinate;
        }
    }
}

TEST(CellSubdivision, LocatesPointsOnBoundariesInBothCellsAndOutsideInNone)
{
    const CellGraph graph = subdivideCells(twoRooms());
    const std::uint32_t room1 = cellAt(graph, {2.5, 2.5, 1.5});
    const std::uint32_t door = cellAt(graph, {5, 2.5, 1});
    EXPECT_EQ(locate(graph, {4.75, 2.5, 1}), (std::vector<std::uint32_t>{std::min(room1, door), std::max(room1, door)}));
    // On the wall's face: room 1 and the cell inside the wall.
    const std::vector<std::uint32_t> atWall = locate(graph, {4.75, 1, 1});
    ASSERT_EQ(atWall.size(), 2u);
    EXPECT_TRUE(atWall[0] == room1 || atWall[1] == room1);
    EXPECT_TRUE(std::is_sorted(atWall.begin(), atWall.end()));
    // Within tolerance of the boundary counts too; far outside the model nothing.
    EXPECT_EQ(locate(graph, {4.75 - 1e-4, 2.5, 1}, 1e-3).size(), 2u);
    EXPECT_TRUE(locate(graph, {100, 2, 1}).empty());
    EXPECT_TRUE(locate(graph, {std::nan(""), 2, 1}).empty());
    // The model's edge is inside the (slightly enlarged) root box.
    EXPECT_EQ(locate(graph, {-0.25, 2.5, 1}).size(), 2u); // the outer wall's outer face: wall and margin
    EXPECT_FALSE(locate(graph, {-0.25, -0.25, -0.25}).empty());
    EXPECT_TRUE(graph.bounds.contains({-0.25, -0.25, -0.25}));
    EXPECT_TRUE(graph.bounds.contains({10.25, 5.25, 3.25}));

    std::vector<std::uint32_t> overlapping;
    graph.cellsOverlapping({{1, 1, 1}, {5, 2.5, 1}}, 0.0, overlapping);
    EXPECT_TRUE(std::find(overlapping.begin(), overlapping.end(), room1) != overlapping.end());
    EXPECT_TRUE(std::find(overlapping.begin(), overlapping.end(), door) != overlapping.end());
    EXPECT_TRUE(std::is_sorted(overlapping.begin(), overlapping.end()));
}

TEST(CellSubdivision, OneCentimetreSlitKeepsItsPortal)
{
    Scene scene;
    addEnclosure(scene, {0, 0, 0}, {10, 5, 3}, 0.25);
    addQuadObject(scene, {5, 0, 0}, {5, 2.5, 0}, {5, 2.5, 3}, {5, 0, 3});
    addQuadObject(scene, {5, 2.51, 0}, {5, 5, 0}, {5, 5, 3}, {5, 2.51, 3});
    const CellGraph graph = subdivideCells(scene);
    const std::uint32_t west = cellAt(graph, {2.5, 2.5, 1.5});
    const std::uint32_t east = cellAt(graph, {7.5, 2.5, 1.5});
    ASSERT_NE(west, east);
    expectBox(graph.cells[west], {0, 0, 0}, {5, 5, 3});
    ASSERT_EQ(graph.cellPortals[west].size(), 1u);
    const CellPortal& slit = graph.portals[graph.cellPortals[west][0]];
    EXPECT_EQ(slit.lowCell, west);
    EXPECT_EQ(slit.highCell, east);
    expectRect(slit.rect, 0, 5, 2.5, double(2.51f), 0, 3);
}

TEST(CellSubdivision, WallsThatDoNotHideFromBothSidesDoNotBlock)
{
    const Vec3 a{5, 0, 0}, b{5, 5, 0}, c{5, 5, 3}, d{5, 0, 3};
    auto roomsSeeEachOther = [&](std::uint32_t flags)
    {
        Scene scene;
        addEnclosure(scene, {0, 0, 0}, {10, 5, 3}, 0.25);
        addQuadObject(scene, a, b, c, d, flags);
        const CellGraph graph = subdivideCells(scene);
        const std::uint32_t west = cellAt(graph, {2.5, 2.5, 1.5});
        const std::uint32_t east = cellAt(graph, {7.5, 2.5, 1.5});
        return reachable(graph, west).count(east) == 1;
    };
    EXPECT_FALSE(roomsSeeEachOther(OBJECT_NONE)); // the control: a two-sided wall seals
    EXPECT_TRUE(roomsSeeEachOther(OBJECT_CULL_BACK));
    EXPECT_TRUE(roomsSeeEachOther(OBJECT_CULL_FRONT));
    EXPECT_TRUE(roomsSeeEachOther(OBJECT_TRANSPARENT));
    EXPECT_TRUE(roomsSeeEachOther(OBJECT_DYNAMIC));
    EXPECT_TRUE(roomsSeeEachOther(OBJECT_NO_AUTO_OCCLUDER));
}

TEST(CellSubdivision, SlantedWallsOnlyGiveOneCell)
{
    Scene scene;
    for (int i = 0; i < 4; ++i)
    {
        const double x = 3.0 * i;
        addQuadObject(scene, {x, 0, 0}, {x + 2, 2, 0}, {x + 2, 2, 3}, {x, 0, 3});
    }
    const CellGraph graph = subdivideCells(scene);
    ASSERT_EQ(graph.cells.size(), 1u);
    EXPECT_TRUE(graph.portals.empty());
    EXPECT_EQ(graph.nodes.size(), 1u);
    EXPECT_EQ(graph.cells[0].min, graph.bounds.min);
    EXPECT_EQ(graph.cells[0].max, graph.bounds.max);
    EXPECT_EQ(locate(graph, {5, 1, 1}), (std::vector<std::uint32_t>{0}));
    expectConsistentIndex(graph);
}

TEST(CellSubdivision, EmptySceneAndCellBudget)
{
    const CellGraph empty = subdivideCells(Scene{});
    EXPECT_TRUE(empty.cells.empty());
    EXPECT_TRUE(locate(empty, {0, 0, 0}).empty());

    SubdivisionOptions oneCell;
    oneCell.maxCells = 1;
    EXPECT_EQ(subdivideCells(twoRooms(), oneCell).cells.size(), 1u);
    SubdivisionOptions shallow;
    shallow.maxDepth = 2;
    const CellGraph twoLevels = subdivideCells(twoRooms(), shallow);
    EXPECT_GE(twoLevels.cells.size(), 3u); // a margin slab may have no plane to split at
    EXPECT_LE(twoLevels.cells.size(), 4u);
    EXPECT_EQ(twoLevels.nodes.size(), 2 * twoLevels.cells.size() - 1);
    SubdivisionOptions budget;
    budget.maxCells = 7;
    EXPECT_EQ(subdivideCells(twoRooms(), budget).cells.size(), 7u);
}

TEST(CellSubdivision, StatedCellsAndPortals)
{
    Scene scene;
    addBox(scene, {0, 0, 0}, {1, 1, 1}); // ignored: stated cells win
    scene.cells.push_back({0, Aabb({0, 0, 0}, {5, 4, 3}), "west"});
    scene.cells.push_back({1, Aabb({5, 0, 0}, {10, 4, 3}), "east"});
    scene.cells.push_back({2, Aabb({20, 0, 0}, {25, 4, 3}), "far"});
    // Axial door between east and west, stated with east first.
    scene.portals.push_back({ConvexPolygon({{5, 1, 0}, {5, 2, 0}, {5, 2, 2}, {5, 1, 2}}), 1, 0});
    // Slanted one near the same face: its bounding rectangle on the shared face.
    scene.portals.push_back({ConvexPolygon({{4.9, 2.5, 0}, {5.1, 3.5, 0}, {5.1, 3.5, 2.5}, {4.9, 2.5, 2.5}}), 0, 1});
    // Cells sharing no face: the polygon's box flattened onto its dominant axis' plane.
    scene.portals.push_back({ConvexPolygon({{15, 1, 0}, {15, 1, 2}, {15.5, 2, 2}, {15.5, 2, 0}}), 2, 0});
    scene.portals.push_back({ConvexPolygon({{5, 1, 0}, {5, 2, 0}, {5, 2, 2}}), 1, 1}); // same cell twice
    scene.portals.push_back({ConvexPolygon({{5, 1, 0}, {5, 2, 0}, {5, 2, 2}}), 0, 7}); // no such cell

    const CellGraph graph = subdivideCells(scene);
    ASSERT_EQ(graph.cells.size(), 3u);
    EXPECT_EQ(graph.cellNames, (std::vector<std::string>{"west", "east", "far"}));
    EXPECT_TRUE(graph.nodes.empty());
    ASSERT_EQ(graph.portals.size(), 3u);
    expectRect(graph.portals[0].rect, 0, 5, 1, 2, 0, 2);
    EXPECT_EQ(graph.portals[0].lowCell, 0u);
    EXPECT_EQ(graph.portals[0].highCell, 1u);
    expectRect(graph.portals[1].rect, 0, 5, 2.5, 3.5, 0, 2.5);
    EXPECT_EQ(graph.portals[1].lowCell, 0u);
    const Vec3 n = glm::abs(ConvexPolygon({{15, 1, 0}, {15, 1, 2}, {15.5, 2, 2}, {15.5, 2, 0}}).newellNormal());
    ASSERT_GT(n.x, n.y); // the third polygon faces mostly along x
    expectRect(graph.portals[2].rect, 0, 15.25, 1, 2, 0, 2);
    EXPECT_EQ(graph.portals[2].lowCell, 0u);
    EXPECT_EQ(graph.portals[2].highCell, 2u);
    expectConsistentIndex(graph);

    EXPECT_EQ(locate(graph, {5, 2, 1}), (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(locate(graph, {22, 2, 1}), (std::vector<std::uint32_t>{2}));
    EXPECT_TRUE(locate(graph, {15, 2, 1}).empty());
}

namespace
{
// nx × ny rooms of 4 m × 4 m × 3 m with 0.25 m walls; each inner wall segment gets a door of random
// position, width and height with probability 0.7, else none. Random coordinates exercise float
// rounding of the stored triangles.
Scene roomGrid(int nx, int ny, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene;
    const double room = 4.0, half = 0.125, height = 3.0;
    addEnclosure(scene, {0, 0, 0}, {nx * room, ny * room, height}, 0.25);
    // A wall segment across `axis` at `at`, spanning [from, to] along the other horizontal axis.
    auto wall = [&](int axis, double at, double from, double to)
    {
        auto box = [&](double a, double b, double z0, double z1)
        {
            Vec3 lo, hi;
            lo[axis] = at - half;
            hi[axis] = at + half;
            lo[1 - axis] = a;
            hi[1 - axis] = b;
            lo.z = z0;
            hi.z = z1;
            addBox(scene, lo, hi);
        };
        if (unit(random) > 0.7)
        {
            box(from, to, 0, height);
            return;
        }
        const double width = 0.7 + 0.6 * unit(random);
        const double start = from + 0.3 + (to - from - 0.6 - width) * unit(random);
        const double top = 2.0 + 0.5 * unit(random);
        box(from, start, 0, height);
        box(start + width, to, 0, height);
        box(start, start + width, top, height);
    };
    for (int i = 1; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            wall(0, i * room, j * room + half, (j + 1) * room - half);
    for (int j = 1; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            wall(1, j * room, i * room - half, (i + 1) * room + half);
    return scene;
}
} // namespace

TEST(CellSubdivision, NoPortalMissingOnRandomRoomGrids)
{
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
        const Scene scene = roomGrid(4, 3, seed);
        const CellGraph graph = subdivideCells(scene);
        const std::vector<OpaqueFace> faces = findOpaqueAxialFaces(scene);
        expectConsistentIndex(graph);
        std::mt19937 random(seed * 7919u);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const double planeSlack = 1e-5;
        auto opaqueAt = [&](int axis, double coordinate, double u, double v, double inset)
        {
            for (const OpaqueFace& f : faces)
            {
                const AxialRect& r = f.rect;
                if (r.axis == axis && std::abs(r.coordinate - coordinate) <= planeSlack && u > r.uMin + inset &&
                    u < r.uMax - inset && v > r.vMin + inset && v < r.vMax - inset)
                    return true;
            }
            return false;
        };

        std::size_t checked = 0, pairs = 0;
        for (std::uint32_t a = 0; a < graph.cells.size(); ++a)
            for (std::uint32_t b = 0; b < graph.cells.size(); ++b)
                for (int axis = 0; axis < 3; ++axis)
                {
                    // Brute-force neighbours: b starts where a ends along axis, overlapping in the plane.
                    const Aabb& low = graph.cells[a];
                    const Aabb& high = graph.cells[b];
                    if (low.max[axis] != high.min[axis])
                        continue;
                    const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
                    const double u0 = std::max(low.min[u], high.min[u]), u1 = std::min(low.max[u], high.max[u]);
                    const double v0 = std::max(low.min[v], high.min[v]), v1 = std::min(low.max[v], high.max[v]);
                    if (!(u1 > u0) || !(v1 > v0))
                        continue;
                    ++pairs;
                    for (int sample = 0; sample < 24; ++sample)
                    {
                        const double pu = u0 + (u1 - u0) * unit(random), pv = v0 + (v1 - v0) * unit(random);
                        if (opaqueAt(axis, low.max[axis], pu, pv, -1e-9))
                            continue;
                        ++checked;
                        bool inPortal = false;
                        for (std::uint32_t p : graph.cellPortals[a])
                        {
                            const CellPortal& portal = graph.portals[p];
                            inPortal |= portal.lowCell == a && portal.highCell == b && portal.rect.axis == axis &&
                                        portal.rect.coordinate == low.max[axis] && inRect(portal.rect, pu, pv, 1e-9);
                        }
                        ASSERT_TRUE(inPortal) << "seed " << seed << ": no portal between cells " << a << " and " << b
                                              << " at axis " << axis << " (" << low.max[axis] << ", " << pu << ", "
                                              << pv << ")";
                    }
                }
        EXPECT_GT(pairs, 100u);
        EXPECT_GT(checked, 200u);

        // Portals are exact: nothing opaque inside them, and they lie on their cells' shared face.
        for (const CellPortal& portal : graph.portals)
        {
            const AxialRect& r = portal.rect;
            EXPECT_EQ(graph.cells[portal.lowCell].max[r.axis], r.coordinate);
            EXPECT_EQ(graph.cells[portal.highCell].min[r.axis], r.coordinate);
            for (int sample = 0; sample < 8; ++sample)
            {
                const double pu = r.uMin + (r.uMax - r.uMin) * unit(random);
                const double pv = r.vMin + (r.vMax - r.vMin) * unit(random);
                EXPECT_FALSE(opaqueAt(r.axis, r.coordinate, pu, pv, 1e-6)) << "portal over an opaque face";
            }
        }

        // Every room is its own cell and the building is sealed: what the rooms reach stays inside.
        const Aabb inside({0, 0, 0}, {16, 12, 3});
        const std::uint32_t first = cellAt(graph, {2, 2, 1.5});
        for (std::uint32_t c : reachable(graph, first))
            EXPECT_TRUE(inside.contains(graph.cells[c].center())) << "leak into cell " << c;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j)
            {
                const std::uint32_t c = cellAt(graph, {4.0 * i + 2, 4.0 * j + 2, 1.5});
                ASSERT_NE(c, NoCell);
                EXPECT_EQ(graph.cells[c].min.z, 0.0);
                EXPECT_EQ(graph.cells[c].max.z, 3.0);
                EXPECT_NEAR(graph.cells[c].extent().x, i == 0 || i == 3 ? 3.875 : 3.75, 1e-6);
            }
    }
}

TEST(CellSubdivision, FiguresForATenByTenGrid)
{
    const Scene scene = roomGrid(10, 10, 42);
    const auto start = std::chrono::steady_clock::now();
    const CellGraph graph = subdivideCells(scene);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("10x10 rooms: %zu triangles, %zu cells, %zu portals, %zu kd nodes, %.3f s\n", scene.triangles.size(),
                graph.cells.size(), graph.portals.size(), graph.nodes.size(), seconds);
    EXPECT_GE(graph.cells.size(), 100u);
    expectConsistentIndex(graph);
}
