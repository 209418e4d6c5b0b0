// SPDX-License-Identifier: MIT
#pragma once
// osgvisrawgl's own scene: a glTF 2.0 file read with tinygltf and flattened into drawable objects,
// without OSG and without osgVis's glTF plugin. One object per (node instance path, primitive) of
// the default scene (else scene 0, else every parentless node), depth first: a node's own mesh
// primitives in index order, then its children in index order, which is the order in which OSG's
// scene extraction numbers the plugin's graph (osgVis/SceneExtractor). The world matrix is the
// glTF Y-up to Z-up rotation (+90° about X) times the node matrices, composed in double; world
// bounds and world triangles (float, counter-clockwise) come from the positions and indices.
//
// note: so that the two renderers agree to the last bit, the matrices are composed with the same
// arithmetic as OSG's Matrixd (row-vector layout, which is OpenGL's column-major memory layout):
// a glTF node's T·R·S as postMultScale, postMultRotate (quaternion to matrix, normalised through
// 2/|q|²), postMultTranslate; a path as preMult from the root; a point as v·M. See RawScene.cpp.
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::rawgl
{
struct SceneError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// 4×4 double matrix in OSG's row-vector layout: m[3][0..2] is the translation, a point maps as v·M.
// Its memory is OpenGL's column-major layout.
struct Matrix
{
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    const double* data() const { return &m[0][0]; }
};

enum class Topology
{
    Triangles,
    Lines,
    LineStrip,
    LineLoop,
    Points
};

struct RawObject
{
    static constexpr double Huge = std::numeric_limits<double>::max();

    std::string identity; // "n0/n3/n12#p1": glTF node indices from the scene root, then the primitive
    Matrix world;         // local → world (Z-up)
    Topology topology = Topology::Triangles;
    // What is drawn, in local coordinates, in drawing order: for triangle topologies three corners
    // per triangle (strips and fans unrolled, counter-clockwise); otherwise the primitive's vertices.
    std::vector<float> positions;
    std::vector<float> normals; // per corner; empty for points and lines (drawn unlit)
    float color[4] = {1, 1, 1, 1};
    std::vector<float> worldTriangles; // 9 floats per triangle, CCW front; non-finite ones left out
    // World bounds; an object without vertices keeps the empty box of the core (min > max, finite).
    double boundsMin[3] = {Huge, Huge, Huge}, boundsMax[3] = {-Huge, -Huge, -Huge};
    std::uint32_t flags = 0; // OSGVIS_OBJECT_*

    std::uint32_t triangleCount() const { return std::uint32_t(worldTriangles.size() / 9); }
};

// A node instance of the flattened scene: the objects of its own mesh and its child instances.
struct RawNode
{
    std::vector<std::uint32_t> objects, children;
};

struct RawScene
{
    std::vector<RawObject> objects;
    std::vector<RawNode> nodes;           // every node instance, depth first
    std::vector<std::uint32_t> rootNodes; // the scene's root instances
};

// Reads `path` (.gltf or .glb). Throws SceneError naming what is wrong (unreadable file, parse
// error, a dangling reference, an accessor out of range, a required extension).
RawScene loadRawScene(const std::string& path);
} // namespace osgVis::rawgl
