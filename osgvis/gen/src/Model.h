// SPDX-License-Identifier: MIT
#pragma once
// A generated scene before it is meshed: shapes (quads, triangles, raw polygons) grouped into meshes
// (one drawable each) and placed by a tree of groups, geodes and transforms. The same model meshes at
// any tessellation density, so the triangle count is calibrated to a budget before any OSG geometry
// exists, and random layout decisions never depend on the budget's fine tuning.
#include <osg/Group>
#include <osg/Matrixd>
#include <osg/Vec3d>
#include <osg/Vec4>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::gen
{
// Parallelogram origin, origin+u, origin+u+v, origin+v; its front face (normal u × v) is
// counter-clockwise. Tessellated into a grid of cells.
struct Quad
{
    osg::Vec3d origin, u, v;
};

// Front face counter-clockwise. Tessellated into k² similar triangles.
struct Tri
{
    osg::Vec3d a, b, c;
};

// A closed tapered cylinder (a cone frustum with flat end caps), counter-clockwise seen from outside.
// Meshed with max(3, round(2π·r·d)) sides for its larger radius r and round(length·d / 4) rings
// (at least 1): a straight taper needs no rings for its shape, only for finer triangles.
struct Tube
{
    osg::Vec3d base, top;
    double baseRadius = 0.0, topRadius = 0.0;
};

// A closed ellipsoid, counter-clockwise seen from outside: the centre and three orthogonal semi-axes
// forming a right-handed frame. Meshed as an octahedron whose faces are split into k² triangles and
// pushed onto the surface, k = round(π/2 · longest semi-axis · d) (at least 1): 8k² triangles.
struct Ellipsoid
{
    osg::Vec3d centre, a, b, c;
};

struct Mesh
{
    std::string name;
    osg::Vec4 colour{0.8f, 0.8f, 0.8f, 1.0f};
    // Multiplies the scene's tessellation density (ground planes are meshed coarser than facades).
    double densityScale = 1.0;
    std::vector<Quad> quads;
    std::vector<Tri> triangles;
    std::vector<Tube> tubes;
    std::vector<Ellipsoid> ellipsoids;
    // Drawn exactly as given (one GL_POLYGON each), never tessellated: degenerate occluder input.
    std::vector<std::vector<osg::Vec3d>> polygons;
};

using MeshId = std::uint32_t;

struct ModelNode
{
    enum class Kind
    {
        Group,
        Geode,    // draws `meshes`
        Transform // osg::MatrixTransform with `matrix`
    };
    Kind kind = Kind::Group;
    std::string name;
    osg::Matrixd matrix;        // Transform only
    bool dynamic = false;       // Transform only: DataVariance DYNAMIC
    std::vector<MeshId> meshes; // Geode only; a mesh used by several geodes is one shared drawable
    std::vector<ModelNode> children;

    static ModelNode group(std::string name);
    static ModelNode geode(std::string name);
    static ModelNode transform(std::string name, const osg::Matrixd& matrix);
    ModelNode& add(ModelNode child);
};

struct Model
{
    std::vector<Mesh> meshes;
    ModelNode root = ModelNode::group("scene");

    MeshId addMesh(Mesh mesh);
};

// Cells along an edge of `length` metres: round(length × density), at least 1.
std::uint32_t subdivisions(double length, double density);
// Triangles of one drawable of the mesh at the given density (subdivisions per metre).
std::uint64_t meshTriangles(const Mesh& mesh, double density);
// Triangles drawn by the whole model: a mesh under several geodes counts once per instance.
std::uint64_t modelTriangles(const Model& model, double density);
// Density whose triangle count is nearest to `target` (0 when even the coarsest meshing exceeds it).
double calibrateDensity(const Model& model, std::uint64_t target);

osg::ref_ptr<osg::Group> buildSceneGraph(const Model& model, double density);
} // namespace osgVis::gen
