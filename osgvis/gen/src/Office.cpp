// SPDX-License-Identifier: MIT
// Office building: storeys of furnished rooms along corridors (the office floor of Teller–Séquin's
// cell-portal paper and the office scene of Coorg–Teller's octree paper).
//
// One storey, seen from above (y up), for 2 wings × C columns:
//
//   +----+----+----+----+----+----+
//   |    | B  | B  | B  | B  |    |   strip B of wing 1 (doors to the corridor below)
//   |    +-d--+--d-+-d--+---d+    |
//   | X  |   corridor of wing 1   | X
//   |    +--d-+-d--+--d-+-d--+    |
//   |    | A  | A  | A  | A  |    |   strip A of wing 1
//   |    +----+----+----+----+    |
//   |    | B  | B  | B  | B  |    |   strip B of wing 0
//   |    +-d--+---d+--d-+-d--+    |
//   | X  |   corridor of wing 0   | X     X: cross corridors joining every wing corridor
//   |    +--d-+-d--+-d--+---d+    |
//   |    | A  | A  | A  | A  |    |   strip A of wing 0
//   +----+----+----+----+----+----+
//
// Every room has a door to its corridor; side walls get doors to the neighbour (or the cross
// corridor) at random. Walls are centred on the grid lines; walls along x own the corners so no two
// boxes overlap. The walk stays on the ground storey; the floor preset (one storey, fixed room count)
// walks its corridors only.
#include "Palette.h"
#include "Scenes.h"
#include "Shapes.h"
#include "WalkPath.h"

#include <algorithm>
#include <cmath>

namespace osgVis::gen
{
namespace
{
constexpr double roomWidth = 4.0; // along x
constexpr double roomDepth = 5.0; // along y
constexpr double corridorWidth = 2.4;
constexpr double wallThickness = 0.15;
constexpr double wallHeight = 3.0;
constexpr double storeyHeight = 3.5;
constexpr double doorWidth = 0.9;
// Door centres keep this far from a wall's ends, so furniture and corners stay clear of them.
constexpr double doorInset = 1.05;
constexpr double eyeHeight = 1.7;
constexpr std::size_t maxRoomsPerStorey = 150;

constexpr double half = 0.5 * wallThickness;
constexpr double wingDepth = 2.0 * roomDepth + corridorWidth;

struct Layout
{
    int wings = 1;
    int columns = 1;
    int storeys = 1;
    double sizeX() const { return 2.0 * corridorWidth + columns * roomWidth; }
    double sizeY() const { return wings * wingDepth; }
};

// Wings and columns for one storey of about `perStorey` rooms. A wing is about three times as long
// as it is deep: roughly square storeys.
Layout storeyLayout(int storeys, double perStorey)
{
    Layout layout;
    layout.storeys = storeys;
    layout.wings = std::max(1, int(std::lround(std::sqrt(perStorey / 6.0))));
    layout.columns = std::max(1, int(std::ceil(perStorey / (2.0 * layout.wings))));
    return layout;
}

// About 300 triangles of walls and furniture per room at the coarsest meshing; rooms grow as
// triangles^0.7 so larger budgets get both more rooms and finer walls.
Layout officeLayout(std::uint64_t triangles)
{
    const auto rooms = std::max<std::size_t>(2, std::size_t(std::llround(std::pow(double(triangles), 0.7) / 80.0)));
    const int storeys = int((rooms + maxRoomsPerStorey - 1) / maxRoomsPerStorey);
    return storeyLayout(storeys, std::ceil(double(rooms) / storeys));
}

// The floor preset: one storey whose room count is fixed so that it has about 2 300 objects, like
// Teller–Séquin's office floor (Soda Hall), whatever the triangle budget.
constexpr double floorRooms = 204.0;

// A door of a ground-storey room onto its corridor, for the walk.
struct CorridorDoor
{
    double x;     // door centre
    double wallY; // centre line of the corridor wall
    double into;  // +1 or -1: direction from the corridor into the room
    double roomCentreX;
};

enum class Route
{
    ThroughRooms,  // office: corridors with detours into some rooms
    CorridorsOnly  // floor: wing and cross corridors only
};

class OfficeBuilder
{
public:
    OfficeBuilder(const Layout& layout, Route routeKind, std::uint32_t seed)
        : _layout(layout), _routeKind(routeKind), _rng(seed)
    {
        _desk = _model.addMesh(deskMesh(palette::desk));
        _chairs[0] = _model.addMesh(chairMesh(palette::chair));
        _chairs[1] = _model.addMesh(chairMesh(palette::chairRed));
        _shelf = _model.addMesh(shelfMesh(palette::shelf));
    }

    SceneModel build()
    {
        _doors.assign(std::size_t(_layout.wings), {});
        for (int s = 0; s < _layout.storeys; ++s)
        {
            ModelNode& storey = _model.root.add(ModelNode::group("storey " + std::to_string(s)));
            for (int k = 0; k < _layout.wings; ++k)
                addWing(storey, s, k);
            addCrossCorridor(storey, s, false);
            addCrossCorridor(storey, s, true);
        }
        SceneModel scene;
        const osg::BoundingBoxd bounds(-half, -half, 0.0, _layout.sizeX() + half, _layout.sizeY() + half,
                                       (_layout.storeys - 1) * storeyHeight + wallHeight);
        scene.walk = perspectiveWalk(walkAlong(route(), WalkPace{1.4, 0.1, 1.5, 200, 1000}), 0.1, farPlaneFor(bounds));
        scene.model = std::move(_model);
        return scene;
    }

private:
    double storeyZ(int s) const { return s * storeyHeight; }
    double corridorY(int wing) const { return wing * wingDepth + roomDepth + 0.5 * corridorWidth; }

    void addMeshes(ModelNode& geode, std::vector<Mesh> meshes)
    {
        for (Mesh& m : meshes)
            geode.meshes.push_back(_model.addMesh(std::move(m)));
    }

    void addFloorAndCeiling(ModelNode& geode, double x0, double y0, double x1, double y1, double z,
                            const osg::Vec4& floorColour, const char* floorName)
    {
        geode.meshes.push_back(
            _model.addMesh(quadMesh(floorName, floorColour, horizontalQuad(x0, y0, x1, y1, z, true))));
        geode.meshes.push_back(_model.addMesh(
            quadMesh("ceiling", palette::ceiling, horizontalQuad(x0, y0, x1, y1, z + wallHeight, false))));
    }

    WallSpec wall(bool alongX, double from, double to, double at, double z) const
    {
        WallSpec w;
        w.alongX = alongX;
        w.from = from;
        w.to = to;
        w.at = at;
        w.z0 = z;
        w.height = wallHeight;
        w.thickness = wallThickness;
        w.doorWidth = doorWidth;
        return w;
    }

    void withDoor(WallSpec& w)
    {
        w.hasDoor = true;
        w.doorCentre = _rng.uniform(w.from + doorInset, w.to - doorInset);
    }

    void addWing(ModelNode& storey, int s, int k)
    {
        const double z = storeyZ(s);
        const double y0 = k * wingDepth;
        const double x0 = corridorWidth, x1 = corridorWidth + _layout.columns * roomWidth;

        ModelNode corridor = ModelNode::geode("corridor " + std::to_string(s) + "/" + std::to_string(k));
        addFloorAndCeiling(corridor, x0, y0 + roomDepth, x1, y0 + roomDepth + corridorWidth, z, palette::corridorFloor,
                           "corridor floor");
        storey.add(std::move(corridor));

        addStrip(storey, s, k, false, y0);
        addStrip(storey, s, k, true, y0 + roomDepth + corridorWidth);
    }

    // Strip A (stripB false) has its corridor on +y; strip B on -y.
    void addStrip(ModelNode& storey, int s, int k, bool stripB, double ya)
    {
        const double z = storeyZ(s);
        const double yb = ya + roomDepth;
        const int columns = _layout.columns;
        // Side wall c stands at x = corridorWidth + c · roomWidth; the outer two face the cross corridors.
        std::vector<bool> sideDoor(std::size_t(columns) + 1);
        for (int c = 0; c <= columns; ++c)
            sideDoor[std::size_t(c)] = _rng.chance(c == 0 || c == columns ? 0.5 : 0.3);

        for (int c = 0; c < columns; ++c)
        {
            const double xa = corridorWidth + c * roomWidth, xb = xa + roomWidth;
            const bool last = c == columns - 1;
            const osg::Vec4 wallColour = varied(palette::wall, _rng, 0.06);
            const std::string id =
                std::to_string(s) + "/" + std::to_string(k) + (stripB ? "B" : "A") + std::to_string(c);
            ModelNode room = ModelNode::group("room " + id);
            ModelNode shell = ModelNode::geode("room shell " + id);
            addFloorAndCeiling(shell, xa, ya, xb, yb, z, varied(palette::floor, _rng, 0.05), "floor");

            const double alongEnd = last ? xb + half : xb - half;
            WallSpec corridorWall = wall(true, xa - half, alongEnd, stripB ? ya : yb, z);
            withDoor(corridorWall);
            addMeshes(shell, wallPieces(corridorWall, "wall", wallColour));
            // Back-to-back strips share one wall, owned by strip A; the last wing's strip B closes the storey.
            if (!stripB || k == _layout.wings - 1)
                addMeshes(shell, wallPieces(wall(true, xa - half, alongEnd, stripB ? yb : ya, z), "wall", wallColour));
            for (int side = c; side <= (last ? c + 1 : c); ++side)
            {
                WallSpec sideWall = wall(false, ya + half, yb - half, corridorWidth + side * roomWidth, z);
                if (sideDoor[std::size_t(side)])
                    withDoor(sideWall);
                addMeshes(shell, wallPieces(sideWall, "wall", wallColour));
            }
            room.add(std::move(shell));

            const double back = stripB ? yb - half : ya + half;
            const double inward = stripB ? -1.0 : 1.0;
            furnish(room, 0.5 * (xa + xb), back, inward, z, sideDoor[std::size_t(c)], sideDoor[std::size_t(c) + 1]);
            storey.add(std::move(room));

            if (s == 0)
                _doors[std::size_t(k)].push_back({corridorWall.doorCentre, corridorWall.at, -inward, 0.5 * (xa + xb)});
        }
    }

    void place(ModelNode& room, const char* name, MeshId mesh, int quarters, const osg::Vec3d& at)
    {
        ModelNode& transform = room.add(ModelNode::transform(name, quarterTurn(quarters, at)));
        ModelNode& geode = transform.add(ModelNode::geode(name));
        geode.meshes.push_back(mesh);
    }

    // Desks against the back wall with a chair each, maybe a shelf against a side wall without a door.
    // Everything stays within 2.5 m of the back wall: the walk turns in the half near the door.
    void furnish(ModelNode& room, double centreX, double back, double inward, double z, bool doorWest, bool doorEast)
    {
        const int deskQuarters = inward > 0 ? 0 : 2; // desk front (+y) towards the room
        const int desks = _rng.between(1, 2);
        for (int i = 0; i < desks; ++i)
        {
            const double x = desks == 1 ? centreX + _rng.uniform(-0.8, 0.8) : centreX + (i == 0 ? -0.85 : 0.85);
            const double deskY = back + inward * 0.4;
            place(room, "desk", _desk, deskQuarters, {x, deskY, z});
            const double chairX = x + _rng.uniform(-0.2, 0.2);
            place(room, "chair", _chairs[_rng.below(2)], deskQuarters + 2, {chairX, deskY + inward * 0.65, z});
        }
        if (_rng.chance(0.6))
        {
            const bool west = doorWest ? false : doorEast ? true : _rng.chance(0.5);
            if (west ? doorWest : doorEast)
                return;
            const double x = west ? centreX - 0.5 * roomWidth + half + 0.175 : centreX + 0.5 * roomWidth - half - 0.175;
            const double y = back + inward * _rng.uniform(1.2, 1.9);
            place(room, "shelf", _shelf, west ? 3 : 1, {x, y, z}); // open side towards the room
        }
    }

    void addCrossCorridor(ModelNode& storey, int s, bool east)
    {
        const double z = storeyZ(s);
        const double sizeX = _layout.sizeX(), sizeY = _layout.sizeY();
        const double x0 = east ? sizeX - corridorWidth : 0.0, x1 = x0 + corridorWidth;
        ModelNode geode = ModelNode::geode(std::string(east ? "east" : "west") + " corridor " + std::to_string(s));
        addFloorAndCeiling(geode, x0, 0.0, x1, sizeY, z, palette::corridorFloor, "corridor floor");
        const double outerX = east ? x1 : x0;
        addMeshes(geode, wallPieces(wall(false, half, sizeY - half, outerX, z), "wall", palette::wall));
        // End walls along x continue the strips' back walls (which own x up to corridorWidth ± half).
        const double from = east ? x0 + half : x0 - half, to = east ? x1 + half : x1 - half;
        for (double y : {0.0, sizeY})
            addMeshes(geode, wallPieces(wall(true, from, to, y, z), "wall", palette::wall));
        storey.add(std::move(geode));
    }

    // Along each ground-storey wing corridor in turn (east, then west, …), into some of its rooms
    // (Route::ThroughRooms): straight through every door, a loop in the room's free half, and out again.
    std::vector<osg::Vec3d> route()
    {
        const double crossWest = 0.5 * corridorWidth, crossEast = _layout.sizeX() - 0.5 * corridorWidth;
        std::vector<osg::Vec3d> points;
        auto at = [&](double x, double y) { points.emplace_back(x, y, eyeHeight); };
        at(crossWest, corridorY(0));
        for (int k = 0; k < _layout.wings; ++k)
        {
            const double yc = corridorY(k);
            const bool eastward = k % 2 == 0;
            std::vector<CorridorDoor> doors = _doors[std::size_t(k)];
            std::sort(doors.begin(), doors.end(),
                      [&](const CorridorDoor& a, const CorridorDoor& b) { return eastward ? a.x < b.x : a.x > b.x; });
            bool visited = false;
            // Corridor-only routes draw no random numbers here, so their rooms match the office's rules.
            for (std::size_t i = 0; _routeKind == Route::ThroughRooms && i < doors.size(); ++i)
            {
                // Always enter at least one room of the first corridor.
                if (!_rng.chance(0.5) && (visited || k > 0 || i + 1 < doors.size()))
                    continue;
                visited = true;
                const CorridorDoor& d = doors[i];
                for (double depth : {-0.9, -0.3, 0.3, 0.9})
                    at(d.x, d.wallY + d.into * depth);
                const double nearX = d.x < d.roomCentreX ? d.roomCentreX - 0.9 : d.roomCentreX + 0.9;
                const double farX = 2.0 * d.roomCentreX - nearX;
                at(nearX, d.wallY + d.into * 2.4);
                at(farX, d.wallY + d.into * 2.4);
                for (double depth : {0.9, 0.3, -0.3, -0.9})
                    at(d.x, d.wallY + d.into * depth);
            }
            const double crossX = eastward ? crossEast : crossWest;
            const double toward = eastward ? 1.0 : -1.0;
            at(crossX - toward * 0.6, yc);
            if (k + 1 < _layout.wings)
            {
                at(crossX, yc + 0.6);
                at(crossX, corridorY(k + 1) - 0.6);
                at(crossX - toward * 0.6, corridorY(k + 1));
            }
            else
                at(crossX, yc);
        }
        return points;
    }

    Layout _layout;
    Route _routeKind;
    Random _rng;
    Model _model;
    MeshId _desk = 0, _chairs[2] = {0, 0}, _shelf = 0;
    std::vector<std::vector<CorridorDoor>> _doors; // per wing of the ground storey
};
} // namespace

SceneModel officeModel(std::uint64_t triangles, std::uint32_t seed)
{
    return OfficeBuilder(officeLayout(triangles), Route::ThroughRooms, seed).build();
}

SceneModel floorModel(std::uint32_t seed)
{
    return OfficeBuilder(storeyLayout(1, floorRooms), Route::CorridorsOnly, seed).build();
}
} // namespace osgVis::gen
