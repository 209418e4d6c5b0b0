// SPDX-License-Identifier: MIT
#pragma once
// The shape builders every scene shares: boxes, horizontal slabs, walls with door openings and the
// office furniture prototypes (built in local coordinates, placed by transforms).
#include "Model.h"

#include <osg/BoundingBox>

namespace osgVis::gen
{
enum BoxFaces : unsigned
{
    FACE_MIN_X = 1u << 0,
    FACE_MAX_X = 1u << 1,
    FACE_MIN_Y = 1u << 2,
    FACE_MAX_Y = 1u << 3,
    FACE_MIN_Z = 1u << 4,
    FACE_MAX_Z = 1u << 5,
    ALL_FACES = 63u,
    // Boxes standing on a floor or the ground never show their bottom.
    NO_BOTTOM = ALL_FACES & ~FACE_MIN_Z,
};

// Axis-aligned box with outward faces.
void addBox(Mesh& mesh, const osg::Vec3d& min, const osg::Vec3d& max, unsigned faces = ALL_FACES);
Mesh boxMesh(std::string name, const osg::Vec4& colour, const osg::Vec3d& min, const osg::Vec3d& max,
             unsigned faces = ALL_FACES);
// Horizontal rectangle [x0, x1] × [y0, y1] at height z, facing up (+z) or down.
Quad horizontalQuad(double x0, double y0, double x1, double y1, double z, bool facingUp);
Mesh quadMesh(std::string name, const osg::Vec4& colour, const Quad& quad, double densityScale = 1.0);

// A straight wall whose centre line runs along x (or y) from `from` to `to` at the other coordinate
// `at`, standing on z0. An optional door is a full-depth gap with a lintel above it.
struct WallSpec
{
    bool alongX = true;
    double from = 0.0, to = 0.0, at = 0.0;
    double z0 = 0.0;
    double height = 3.0;
    double thickness = 0.15;
    bool hasDoor = false;
    double doorCentre = 0.0; // along the wall
    double doorWidth = 0.9;
    double doorHeight = 2.1;
};
// One box mesh per piece (each piece its own drawable, named `name`): two jambs and a lintel for a
// wall with a door, one box otherwise. Pieces standing on the floor have no bottom face.
std::vector<Mesh> wallPieces(const WallSpec& wall, const std::string& name, const osg::Vec4& colour);
// The world-space box of every piece, for keep-out tests.
std::vector<osg::BoundingBoxd> wallPieceBounds(const WallSpec& wall);

// Furniture in local coordinates: footprint centred on the origin, standing on z = 0, its front
// (the side a person uses) towards +y.
Mesh deskMesh(const osg::Vec4& colour);  // 1.4 × 0.7 × 0.75 m
Mesh chairMesh(const osg::Vec4& colour); // 0.45 × 0.45 seat, back at -y, 0.9 m tall
Mesh shelfMesh(const osg::Vec4& colour); // 0.9 × 0.35 × 1.8 m, open to +y

// Rotation about z by quarter turns followed by a translation, without trigonometry so the matrix
// is exact and identical everywhere.
osg::Matrixd quarterTurn(int quarters, const osg::Vec3d& translation);
} // namespace osgVis::gen
