// SPDX-License-Identifier: MIT
#include "Shapes.h"

namespace osgVis::gen
{
namespace
{
struct Piece
{
    osg::BoundingBoxd box;
    unsigned faces;
};

// Box spanning [a0, a1] along the wall, the wall's thickness across it, and [z0, z1] in height.
Piece wallPiece(const WallSpec& w, double a0, double a1, double z0, double z1, unsigned faces)
{
    const double half = 0.5 * w.thickness;
    if (w.alongX)
        return {osg::BoundingBoxd(a0, w.at - half, z0, a1, w.at + half, z1), faces};
    return {osg::BoundingBoxd(w.at - half, a0, z0, w.at + half, a1, z1), faces};
}

std::vector<Piece> pieces(const WallSpec& w)
{
    const double top = w.z0 + w.height;
    if (!w.hasDoor)
        return {wallPiece(w, w.from, w.to, w.z0, top, NO_BOTTOM)};
    const double open0 = w.doorCentre - 0.5 * w.doorWidth;
    const double open1 = w.doorCentre + 0.5 * w.doorWidth;
    std::vector<Piece> result;
    if (open0 > w.from)
        result.push_back(wallPiece(w, w.from, open0, w.z0, top, NO_BOTTOM));
    if (w.to > open1)
        result.push_back(wallPiece(w, open1, w.to, w.z0, top, NO_BOTTOM));
    // The lintel's underside shows from the door.
    result.push_back(wallPiece(w, open0, open1, w.z0 + w.doorHeight, top, ALL_FACES));
    return result;
}

// Four square legs of side `side` standing on z = 0 up to `height`, their low corners at (x, y)
// for x in `xs` and y in `ys`.
void addLegs(Mesh& mesh, const double (&xs)[2], const double (&ys)[2], double side, double height)
{
    for (double x : xs)
        for (double y : ys)
            addBox(mesh, {x, y, 0.0}, {x + side, y + side, height}, NO_BOTTOM);
}
} // namespace

void addBox(Mesh& mesh, const osg::Vec3d& lo, const osg::Vec3d& hi, unsigned faces)
{
    const osg::Vec3d d = hi - lo;
    const osg::Vec3d dx(d.x(), 0, 0), dy(0, d.y(), 0), dz(0, 0, d.z());
    // Each face's u × v points outward.
    if (faces & FACE_MIN_X)
        mesh.quads.push_back({lo, dz, dy});
    if (faces & FACE_MAX_X)
        mesh.quads.push_back({lo + dx, dy, dz});
    if (faces & FACE_MIN_Y)
        mesh.quads.push_back({lo, dx, dz});
    if (faces & FACE_MAX_Y)
        mesh.quads.push_back({lo + dy, dz, dx});
    if (faces & FACE_MIN_Z)
        mesh.quads.push_back({lo, dy, dx});
    if (faces & FACE_MAX_Z)
        mesh.quads.push_back({lo + dz, dx, dy});
}

Mesh boxMesh(std::string name, const osg::Vec4& colour, const osg::Vec3d& min, const osg::Vec3d& max, unsigned faces)
{
    Mesh mesh;
    mesh.name = std::move(name);
    mesh.colour = colour;
    addBox(mesh, min, max, faces);
    return mesh;
}

Quad horizontalQuad(double x0, double y0, double x1, double y1, double z, bool facingUp)
{
    const osg::Vec3d dx(x1 - x0, 0, 0), dy(0, y1 - y0, 0);
    const osg::Vec3d origin(x0, y0, z);
    return facingUp ? Quad{origin, dx, dy} : Quad{origin, dy, dx};
}

Mesh quadMesh(std::string name, const osg::Vec4& colour, const Quad& quad, double densityScale)
{
    Mesh mesh;
    mesh.name = std::move(name);
    mesh.colour = colour;
    mesh.densityScale = densityScale;
    mesh.quads.push_back(quad);
    return mesh;
}

std::vector<Mesh> wallPieces(const WallSpec& wall, const std::string& name, const osg::Vec4& colour)
{
    std::vector<Mesh> meshes;
    for (const Piece& p : pieces(wall))
        meshes.push_back(boxMesh(name, colour, p.box._min, p.box._max, p.faces));
    return meshes;
}

std::vector<osg::BoundingBoxd> wallPieceBounds(const WallSpec& wall)
{
    std::vector<osg::BoundingBoxd> boxes;
    for (const Piece& p : pieces(wall))
        boxes.push_back(p.box);
    return boxes;
}

Mesh deskMesh(const osg::Vec4& colour)
{
    Mesh mesh = boxMesh("desk", colour, {-0.7, -0.35, 0.72}, {0.7, 0.35, 0.75});
    addLegs(mesh, {-0.64, 0.59}, {-0.29, 0.24}, 0.05, 0.72);
    return mesh;
}

Mesh chairMesh(const osg::Vec4& colour)
{
    Mesh mesh = boxMesh("chair", colour, {-0.225, -0.225, 0.42}, {0.225, 0.225, 0.46});
    addBox(mesh, {-0.225, -0.225, 0.46}, {0.225, -0.195, 0.9});
    addLegs(mesh, {-0.215, 0.185}, {-0.215, 0.185}, 0.03, 0.42);
    return mesh;
}

Mesh shelfMesh(const osg::Vec4& colour)
{
    Mesh mesh = boxMesh("shelf", colour, {-0.45, -0.175, 0.0}, {-0.43, 0.175, 1.8}, NO_BOTTOM);
    addBox(mesh, {0.43, -0.175, 0.0}, {0.45, 0.175, 1.8}, NO_BOTTOM);
    addBox(mesh, {-0.43, -0.175, 0.0}, {0.43, -0.16, 1.8}, NO_BOTTOM);
    for (double z : {0.05, 0.5, 0.95, 1.4, 1.78})
        addBox(mesh, {-0.43, -0.16, z}, {0.43, 0.175, z + 0.02});
    return mesh;
}

osg::Matrixd quarterTurn(int quarters, const osg::Vec3d& t)
{
    static const double cosines[4] = {1.0, 0.0, -1.0, 0.0};
    static const double sines[4] = {0.0, 1.0, 0.0, -1.0};
    const int q = ((quarters % 4) + 4) % 4;
    const double c = cosines[q], s = sines[q];
    // osg matrices act on row vectors: p' = p · M.
    return osg::Matrixd(c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, t.x(), t.y(), t.z(), 1);
}
} // namespace osgVis::gen
