// SPDX-License-Identifier: MIT
#include "RawScene.h"

#include <osgVis/gltf/GltfAccessors.h>
#include <osgVis/gltf/GltfError.h>
#include <osgVis/visapi.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace osgVis::rawgl
{
namespace
{
constexpr double HalfPi = 1.57079632679489661923; // as OSG's osg::PI_2

// a · b, each element a left-to-right sum of four products as OSG's Matrixd multiplies: its
// m.preMult(other) is product(other, m), its m.postMult(other) product(m, other).
Matrix product(const Matrix& a, const Matrix& b)
{
    Matrix out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out.m[r][c] = a.m[r][0] * b.m[0][c] + a.m[r][1] * b.m[1][c] + a.m[r][2] * b.m[2][c] + a.m[r][3] * b.m[3][c];
    return out;
}

// The rotation of quaternion (x, y, z, w), normalised on the fly by 2/|q|² (OSG's Matrixd::setRotate);
// a zero quaternion gives a zero 3×3 block.
Matrix rotation(double x, double y, double z, double w)
{
    Matrix r;
    const double length2 = x * x + y * y + z * z + w * w;
    if (std::fabs(length2) <= std::numeric_limits<double>::min())
    {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                r.m[i][j] = 0.0;
        return r;
    }
    const double s = length2 != 1.0 ? 2.0 / length2 : 2.0;
    const double x2 = s * x, y2 = s * y, z2 = s * z;
    const double xx = x * x2, xy = x * y2, xz = x * z2, yy = y * y2, yz = y * z2, zz = z * z2;
    const double wx = w * x2, wy = w * y2, wz = w * z2;
    r.m[0][0] = 1.0 - (yy + zz);
    r.m[1][0] = xy - wz;
    r.m[2][0] = xz + wy;
    r.m[0][1] = xy + wz;
    r.m[1][1] = 1.0 - (xx + zz);
    r.m[2][1] = yz - wx;
    r.m[0][2] = xz - wy;
    r.m[1][2] = yz + wx;
    r.m[2][2] = 1.0 - (xx + yy);
    return r;
}

// glTF's Y-up to Z-up: +90° about +X through the quaternion (sin 45°, 0, 0, cos 45°), as the plugin's
// osg::Matrixd::rotate(osg::PI_2, osg::X_AXIS).
Matrix zUp()
{
    const double half = 0.5 * HalfPi;
    return rotation(1.0 * std::sin(half) * 1.0, 0.0 * std::sin(half) * 1.0, 0.0 * std::sin(half) * 1.0, std::cos(half));
}

// Throws the shared reader's GltfError for a transform of the wrong size (a SceneError in loadRawScene).
Matrix nodeMatrix(const tinygltf::Node& node, int index)
{
    gltf::checkNodeTransform(node, index);
    Matrix out;
    if (!node.matrix.empty())
    {
        for (int i = 0; i < 16; ++i)
            out.m[i / 4][i % 4] = node.matrix[std::size_t(i)]; // glTF's column-major array, as it is
        return out;
    }
    if (!node.scale.empty()) // M · S: column c scaled by s[c]
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 3; ++c)
                out.m[r][c] *= node.scale[std::size_t(c)];
    if (!node.rotation.empty())
    {
        const std::vector<double>& q = node.rotation;
        if (!(q[0] == 0.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 1.0)) // no rotation: nothing to multiply
            out = product(out, rotation(q[0], q[1], q[2], q[3]));
    }
    if (!node.translation.empty()) // M · T
        for (int c = 0; c < 3; ++c)
        {
            const double t = node.translation[std::size_t(c)];
            if (t == 0)
                continue;
            for (int r = 0; r < 4; ++r)
                out.m[r][c] += t * out.m[r][3];
        }
    return out;
}

// p = v · M, divided by the homogeneous coordinate as OSG's Vec3d * Matrixd does.
void transform(const Matrix& world, const double v[3], double out[3])
{
    const double(&m)[4][4] = world.m;
    const double d = 1.0 / (m[0][3] * v[0] + m[1][3] * v[1] + m[2][3] * v[2] + m[3][3]);
    for (int c = 0; c < 3; ++c)
        out[c] = (m[0][c] * v[0] + m[1][c] * v[1] + m[2][c] * v[2] + m[3][c]) * d;
}

bool finite3(const double v[3])
{
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void check(bool holds, const std::string& what)
{
    if (!holds)
        throw SceneError(what);
}

// A VEC3 float accessor's values, three per element, read by the accessor reader the glTF plugin
// uses (its GltfError becomes a SceneError in loadRawScene).
std::vector<float> readVec3(const tinygltf::Model& model, int index, const char* usage)
{
    return gltf::readFloatAccessor(model, index, {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, usage).values;
}

// The corners of the triangles a triangle-mode primitive draws, three per triangle, in the order and
// winding OSG's TriangleFunctor reports them (strips alternate, fans turn around their first vertex).
std::vector<std::uint32_t> triangleCorners(int mode, const std::vector<std::uint32_t>& drawn)
{
    std::vector<std::uint32_t> corners;
    const std::size_t n = drawn.size();
    if (mode == TINYGLTF_MODE_TRIANGLES)
    {
        // note: a trailing incomplete triangle is left out (OSG would read past the index list).
        for (std::size_t i = 0; i + 2 < n; i += 3)
            corners.insert(corners.end(), {drawn[i], drawn[i + 1], drawn[i + 2]});
    }
    else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
    {
        for (std::size_t i = 2; i < n; ++i)
            if (i % 2)
                corners.insert(corners.end(), {drawn[i - 2], drawn[i], drawn[i - 1]});
            else
                corners.insert(corners.end(), {drawn[i - 2], drawn[i - 1], drawn[i]});
    }
    else if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
    {
        for (std::size_t i = 2; i < n; ++i)
            corners.insert(corners.end(), {drawn[0], drawn[i - 1], drawn[i]});
    }
    return corners;
}

// Flags the OSG adapter derives from the state the plugin gives a glTF material: BLEND → transparent
// (blending, transparent bin), MASK → no automatic occluder (alpha test), one-sided → back faces culled.
std::uint32_t materialFlags(const tinygltf::Material& material)
{
    std::uint32_t flags = 0;
    if (material.alphaMode == "BLEND")
        flags |= OSGVIS_OBJECT_TRANSPARENT;
    else if (material.alphaMode == "MASK")
        flags |= OSGVIS_OBJECT_NO_AUTO_OCCLUDER;
    if (!material.doubleSided)
        flags |= OSGVIS_OBJECT_CULL_BACK;
    return flags;
}

// A primitive's vertex attributes, in local coordinates, three floats per vertex.
struct Vertices
{
    std::vector<float> positions;
    std::vector<float> normals; // empty where the primitive has none
    std::size_t count() const { return positions.size() / 3; }
};

Vertices readVertices(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& where)
{
    Vertices vertices;
    const auto position = primitive.attributes.find("POSITION");
    check(position != primitive.attributes.end(), where + " has no POSITION attribute");
    vertices.positions = readVec3(model, position->second, "POSITION");
    const auto normal = primitive.attributes.find("NORMAL");
    if (normal != primitive.attributes.end())
    {
        vertices.normals = readVec3(model, normal->second, "NORMAL");
        check(vertices.normals.size() == vertices.positions.size(), where + ": NORMAL and POSITION differ in count");
    }
    return vertices;
}

// The flags and base colour of the primitive's material.
void applyMaterial(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& where,
                   RawObject& out)
{
    tinygltf::Material material; // glTF's default material: opaque, one-sided, white
    if (primitive.material >= 0)
    {
        check(std::size_t(primitive.material) < model.materials.size(),
              where + " names material " + std::to_string(primitive.material) + ", which does not exist");
        material = model.materials[std::size_t(primitive.material)];
    }
    out.flags = materialFlags(material);
    const std::vector<double>& base = material.pbrMetallicRoughness.baseColorFactor;
    for (std::size_t i = 0; i < 4 && i < base.size(); ++i)
        out.color[i] = float(base[i]);
}

// The vertices drawn, in order: the index list, or every vertex for a primitive without one.
std::vector<std::uint32_t> drawnVertices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                         std::size_t vertexCount)
{
    std::vector<std::uint32_t> drawn;
    if (primitive.indices >= 0)
        drawn = gltf::readIndexAccessor(model, primitive.indices, vertexCount);
    else
        for (std::size_t i = 0; i < vertexCount; ++i)
            drawn.push_back(std::uint32_t(i));
    return drawn;
}

// Bounds over the vertices drawn (every vertex when none is), as the adapter's extraction, in world
// coordinates through out.world.
void addBounds(const std::vector<float>& positions, const std::vector<std::uint32_t>& drawn, RawObject& out)
{
    const std::size_t vertexCount = positions.size() / 3;
    std::vector<bool> used(vertexCount, drawn.empty());
    for (std::uint32_t i : drawn)
        used[i] = true;
    bool nonFinite = false;
    for (std::size_t i = 0; i < vertexCount; ++i)
    {
        if (!used[i])
            continue;
        const double local[3] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
        double p[3];
        transform(out.world, local, p);
        if (!finite3(local) || !finite3(p))
        {
            nonFinite = true;
            continue;
        }
        for (int c = 0; c < 3; ++c)
        {
            out.boundsMin[c] = std::min(out.boundsMin[c], p[c]);
            out.boundsMax[c] = std::max(out.boundsMax[c], p[c]);
        }
    }
    if (nonFinite)
        out.flags |= OSGVIS_OBJECT_ALWAYS_VISIBLE;
}

Topology topologyOf(int mode, const std::string& where)
{
    switch (mode)
    {
    case TINYGLTF_MODE_TRIANGLES:
    case TINYGLTF_MODE_TRIANGLE_STRIP:
    case TINYGLTF_MODE_TRIANGLE_FAN:
        return Topology::Triangles;
    case TINYGLTF_MODE_LINE:
        return Topology::Lines;
    case TINYGLTF_MODE_LINE_STRIP:
        return Topology::LineStrip;
    case TINYGLTF_MODE_LINE_LOOP:
        return Topology::LineLoop;
    case TINYGLTF_MODE_POINTS:
        return Topology::Points;
    default:
        throw SceneError(where + " has unknown mode " + std::to_string(mode));
    }
}

// The world corners of the triangle at corners[t], as floats; false where one is not finite.
bool worldTriangle(const Matrix& world, const std::vector<float>& positions, const std::vector<std::uint32_t>& corners,
                   std::size_t t, float w[9])
{
    bool finite = true;
    for (int k = 0; k < 3; ++k)
    {
        const std::uint32_t i = corners[t + std::size_t(k)];
        const double local[3] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
        double p[3];
        transform(world, local, p);
        finite = finite && finite3(p);
        for (int c = 0; c < 3; ++c)
            w[3 * k + c] = float(p[c]);
    }
    return finite;
}

// The normal of the triangle at corners[t], not normalised: what a primitive without normals is lit by.
void faceNormal(const std::vector<float>& positions, const std::vector<std::uint32_t>& corners, std::size_t t,
                float normal[3])
{
    const float* a = &positions[3 * corners[t]];
    const float* b = &positions[3 * corners[t + 1]];
    const float* c = &positions[3 * corners[t + 2]];
    const float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const float v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    normal[0] = u[1] * v[2] - u[2] * v[1];
    normal[1] = u[2] * v[0] - u[0] * v[2];
    normal[2] = u[0] * v[1] - u[1] * v[0];
}

// A triangle-mode primitive's world triangles (for culling) and the corners it draws with their normals.
void addTriangles(int mode, const Vertices& vertices, const std::vector<std::uint32_t>& drawn, RawObject& out)
{
    const std::vector<float>& positions = vertices.positions;
    const std::vector<float>& normals = vertices.normals;
    const std::vector<std::uint32_t> corners = triangleCorners(mode, drawn);
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3)
    {
        float w[9];
        // note: a triangle with a non-finite corner is neither kept for culling nor drawn; its
        // object is always visible (the bounds pass flagged it).
        if (!worldTriangle(out.world, positions, corners, t, w))
            continue;
        out.worldTriangles.insert(out.worldTriangles.end(), w, w + 9);
        float normal[3] = {0, 0, 0};
        if (normals.empty())
            faceNormal(positions, corners, t, normal);
        for (int k = 0; k < 3; ++k)
        {
            const std::uint32_t i = corners[t + std::size_t(k)];
            out.positions.insert(out.positions.end(), &positions[3 * i], &positions[3 * i] + 3);
            if (normals.empty())
                out.normals.insert(out.normals.end(), normal, normal + 3);
            else
                out.normals.insert(out.normals.end(), &normals[3 * i], &normals[3 * i] + 3);
        }
    }
}

class Flattener
{
public:
    Flattener(const tinygltf::Model& model, RawScene& out) : _model(model), _out(out), _onPath(model.nodes.size()) {}

    // Returns the node instance's index in RawScene::nodes.
    std::uint32_t node(int index, const Matrix& parentWorld, const std::string& parentPath)
    {
        check(index >= 0 && std::size_t(index) < _model.nodes.size(),
              (parentPath.empty() ? std::string("the scene") : "a node") + " names node " + std::to_string(index) +
                  ", but there are " + std::to_string(_model.nodes.size()));
        check(!_onPath[std::size_t(index)], "node " + std::to_string(index) + " is its own ancestor");
        _onPath[std::size_t(index)] = true;
        const tinygltf::Node& source = _model.nodes[std::size_t(index)];
        // OSG's computeLocalToWorld: local · parent.
        const Matrix world = product(nodeMatrix(source, index), parentWorld);
        const std::string path = (parentPath.empty() ? "n" : parentPath + "/n") + std::to_string(index);
        const auto instance = std::uint32_t(_out.nodes.size());
        _out.nodes.emplace_back();
        if (source.mesh >= 0)
        {
            const auto first = std::uint32_t(_out.objects.size());
            mesh(source.mesh, world, path);
            for (auto id = first; id < _out.objects.size(); ++id)
                _out.nodes[instance].objects.push_back(id);
        }
        for (int child : source.children)
        {
            const std::uint32_t c = node(child, world, path);
            _out.nodes[instance].children.push_back(c);
        }
        _onPath[std::size_t(index)] = false;
        return instance;
    }

private:
    void mesh(int index, const Matrix& world, const std::string& path)
    {
        check(std::size_t(index) < _model.meshes.size(),
              "a node names mesh " + std::to_string(index) + ", but there are " + std::to_string(_model.meshes.size()));
        const tinygltf::Mesh& mesh = _model.meshes[std::size_t(index)];
        check(!mesh.primitives.empty(), "mesh " + std::to_string(index) + " has no primitives");
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
            _out.objects.push_back(object(mesh.primitives[p], world, path + "#p" + std::to_string(p),
                                          "mesh " + std::to_string(index) + " primitive " + std::to_string(p)));
    }

    RawObject object(const tinygltf::Primitive& primitive, const Matrix& world, const std::string& identity,
                     const std::string& where)
    {
        check(!primitive.extensions.count("KHR_draco_mesh_compression"), where + " is Draco-compressed");
        RawObject out;
        out.identity = identity;
        out.world = world;
        const Vertices vertices = readVertices(_model, primitive, where);
        applyMaterial(_model, primitive, where, out);
        const std::vector<std::uint32_t> drawn = drawnVertices(_model, primitive, vertices.count());
        addBounds(vertices.positions, drawn, out);
        out.topology = topologyOf(primitive.mode, where);
        if (out.topology != Topology::Triangles)
        {
            for (std::uint32_t i : drawn)
                out.positions.insert(out.positions.end(), &vertices.positions[3 * i], &vertices.positions[3 * i] + 3);
            return out;
        }
        addTriangles(primitive.mode, vertices, drawn, out);
        return out;
    }

    const tinygltf::Model& _model;
    RawScene& _out;
    std::vector<bool> _onPath;
};

// Images are not drawn (objects are lit by their normal in their base colour): keep none.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true;
}

bool hasSuffix(const std::string& text, const std::string& suffix)
{
    if (text.size() < suffix.size())
        return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) != suffix[i])
            return false;
    return true;
}
} // namespace

RawScene loadRawScene(const std::string& path)
{
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    bool loaded = false;
    try
    {
        loaded = hasSuffix(path, ".glb") ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                                         : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    }
    catch (const std::exception& e)
    {
        throw SceneError(path + ": tinygltf failed: " + e.what());
    }
    while (!error.empty() && error.back() == '\n')
        error.pop_back();
    if (!loaded)
        throw SceneError(path + ": " + (error.empty() ? std::string("tinygltf cannot read it") : error));
    for (const std::string& extension : model.extensionsRequired)
        throw SceneError(path + ": required extension " + extension + " is not supported");

    std::vector<int> roots;
    if (!model.scenes.empty())
    {
        if (model.defaultScene >= int(model.scenes.size()))
            throw SceneError(path + ": the default scene is " + std::to_string(model.defaultScene) +
                             ", but there are " + std::to_string(model.scenes.size()) + " scenes");
        roots = model.scenes[std::size_t(std::max(model.defaultScene, 0))].nodes;
    }
    else
    {
        // No scene: every node that is no node's child, in index order.
        std::vector<bool> isChild(model.nodes.size(), false);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children)
                if (child >= 0 && std::size_t(child) < model.nodes.size())
                    isChild[std::size_t(child)] = true;
        for (std::size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i])
                roots.push_back(int(i));
    }

    RawScene scene;
    try
    {
        // The identity, then the Z-up rotation, as OSG's path from the plugin's root starts.
        const Matrix root = product(zUp(), Matrix());
        Flattener flattener(model, scene);
        for (int node : roots)
            scene.rootNodes.push_back(flattener.node(node, root, ""));
    }
    catch (const SceneError& e)
    {
        throw SceneError(path + ": " + e.what());
    }
    catch (const gltf::GltfError& e) // from the shared accessor reader, in its words
    {
        throw SceneError(path + ": " + e.what());
    }
    return scene;
}
} // namespace osgVis::rawgl
