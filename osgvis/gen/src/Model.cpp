// SPDX-License-Identifier: MIT
#include "Model.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <algorithm>
#include <cmath>

namespace osgVis::gen
{
namespace
{
// Caps one edge so a runaway density cannot ask for billions of cells.
constexpr double maxSubdivisions = 4096.0;

std::uint32_t triangleSubdivisions(const Tri& t, double density)
{
    const double longest = std::max({(t.b - t.a).length(), (t.c - t.b).length(), (t.a - t.c).length()});
    return subdivisions(longest, density);
}

void countInstances(const ModelNode& node, std::vector<std::uint64_t>& instances)
{
    for (MeshId id : node.meshes)
        ++instances[id];
    for (const ModelNode& child : node.children)
        countInstances(child, instances);
}

// How many geodes draw each mesh.
std::vector<std::uint64_t> instanceCounts(const Model& model)
{
    std::vector<std::uint64_t> instances(model.meshes.size(), 0);
    countInstances(model.root, instances);
    return instances;
}

std::uint64_t instancedTriangles(const Model& model, const std::vector<std::uint64_t>& instances, double density)
{
    std::uint64_t count = 0;
    for (std::size_t i = 0; i < model.meshes.size(); ++i)
        if (instances[i])
            count += instances[i] * meshTriangles(model.meshes[i], density);
    return count;
}

osg::Vec3 unitNormal(const osg::Vec3d& n)
{
    osg::Vec3d unit = n;
    if (!(unit.normalize() > 0.0))
        return {0.0f, 0.0f, 1.0f};
    return osg::Vec3(unit);
}

class GeometryWriter
{
public:
    GeometryWriter()
        : _vertices(new osg::Vec3Array), _normals(new osg::Vec3Array), _indices(new osg::DrawElementsUInt(GL_TRIANGLES))
    {
    }

    void addQuad(const Quad& q, std::uint32_t nu, std::uint32_t nv)
    {
        const osg::Vec3 normal = unitNormal(q.u ^ q.v);
        const auto base = std::uint32_t(_vertices->size());
        for (std::uint32_t j = 0; j <= nv; ++j)
            for (std::uint32_t i = 0; i <= nu; ++i)
            {
                _vertices->push_back(osg::Vec3(q.origin + q.u * (double(i) / nu) + q.v * (double(j) / nv)));
                _normals->push_back(normal);
            }
        const std::uint32_t row = nu + 1;
        for (std::uint32_t j = 0; j < nv; ++j)
            for (std::uint32_t i = 0; i < nu; ++i)
            {
                const std::uint32_t a = base + j * row + i;
                addTriangle(a, a + 1, a + row + 1);
                addTriangle(a, a + row + 1, a + row);
            }
    }

    // Splits the triangle into k² similar ones on a barycentric grid.
    void addTriangle(const Tri& t, std::uint32_t k)
    {
        const osg::Vec3 normal = unitNormal((t.b - t.a) ^ (t.c - t.a));
        const auto base = std::uint32_t(_vertices->size());
        const osg::Vec3d du = (t.b - t.a) / double(k);
        const osg::Vec3d dv = (t.c - t.a) / double(k);
        // Row j holds k + 1 - j vertices.
        std::vector<std::uint32_t> rowStart(k + 2);
        for (std::uint32_t j = 0, next = base; j <= k; ++j)
        {
            rowStart[j] = next;
            for (std::uint32_t i = 0; i + j <= k; ++i)
            {
                _vertices->push_back(osg::Vec3(t.a + du * double(i) + dv * double(j)));
                _normals->push_back(normal);
            }
            next += k + 1 - j;
        }
        for (std::uint32_t j = 0; j < k; ++j)
            for (std::uint32_t i = 0; i + j < k; ++i)
            {
                const std::uint32_t a = rowStart[j] + i;
                const std::uint32_t above = rowStart[j + 1] + i;
                addTriangle(a, a + 1, above);
                if (i + j + 1 < k)
                    addTriangle(a + 1, above + 1, above);
            }
    }

    osg::ref_ptr<osg::Geometry> finish(const Mesh& mesh)
    {
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setName(mesh.name);
        geometry->setUseDisplayList(false);
        geometry->setUseVertexBufferObjects(true);
        if (!_indices->empty())
            geometry->addPrimitiveSet(_indices.get());
        for (const std::vector<osg::Vec3d>& polygon : mesh.polygons)
        {
            osg::Vec3d newell;
            for (std::size_t i = 0; i < polygon.size(); ++i)
                newell += polygon[i] ^ polygon[(i + 1) % polygon.size()];
            const osg::Vec3 normal = unitNormal(newell);
            const auto first = GLint(_vertices->size());
            for (const osg::Vec3d& p : polygon)
            {
                _vertices->push_back(osg::Vec3(p));
                _normals->push_back(normal);
            }
            geometry->addPrimitiveSet(new osg::DrawArrays(GL_POLYGON, first, GLsizei(polygon.size())));
        }
        geometry->setVertexArray(_vertices.get());
        geometry->setNormalArray(_normals.get(), osg::Array::BIND_PER_VERTEX);
        osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
        colours->push_back(mesh.colour);
        geometry->setColorArray(colours.get(), osg::Array::BIND_OVERALL);
        return geometry;
    }

private:
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
    {
        _indices->push_back(a);
        _indices->push_back(b);
        _indices->push_back(c);
    }

    osg::ref_ptr<osg::Vec3Array> _vertices;
    osg::ref_ptr<osg::Vec3Array> _normals;
    osg::ref_ptr<osg::DrawElementsUInt> _indices;
};

osg::ref_ptr<osg::Geometry> buildGeometry(const Mesh& mesh, double density)
{
    const double d = density * mesh.densityScale;
    GeometryWriter writer;
    for (const Quad& q : mesh.quads)
        writer.addQuad(q, subdivisions(q.u.length(), d), subdivisions(q.v.length(), d));
    for (const Tri& t : mesh.triangles)
        writer.addTriangle(t, triangleSubdivisions(t, d));
    return writer.finish(mesh);
}

osg::ref_ptr<osg::Node> buildNode(const ModelNode& node, const std::vector<osg::ref_ptr<osg::Geometry>>& drawables)
{
    osg::ref_ptr<osg::Group> group;
    switch (node.kind)
    {
    case ModelNode::Kind::Geode:
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        for (MeshId id : node.meshes)
            geode->addDrawable(drawables[id].get());
        geode->setName(node.name);
        return geode;
    }
    case ModelNode::Kind::Transform:
    {
        osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform(node.matrix);
        transform->setDataVariance(node.dynamic ? osg::Object::DYNAMIC : osg::Object::STATIC);
        group = transform;
        break;
    }
    case ModelNode::Kind::Group:
        group = new osg::Group;
        break;
    }
    group->setName(node.name);
    for (const ModelNode& child : node.children)
        group->addChild(buildNode(child, drawables).get());
    return group;
}
} // namespace

ModelNode ModelNode::group(std::string name)
{
    ModelNode node;
    node.name = std::move(name);
    return node;
}

ModelNode ModelNode::geode(std::string name)
{
    ModelNode node;
    node.kind = Kind::Geode;
    node.name = std::move(name);
    return node;
}

ModelNode ModelNode::transform(std::string name, const osg::Matrixd& matrix)
{
    ModelNode node;
    node.kind = Kind::Transform;
    node.name = std::move(name);
    node.matrix = matrix;
    return node;
}

ModelNode& ModelNode::add(ModelNode child)
{
    children.push_back(std::move(child));
    return children.back();
}

MeshId Model::addMesh(Mesh mesh)
{
    meshes.push_back(std::move(mesh));
    return MeshId(meshes.size() - 1);
}

std::uint32_t subdivisions(double length, double density)
{
    const double cells = std::round(length * density);
    if (!(cells >= 1.0))
        return 1;
    return std::uint32_t(std::min(cells, maxSubdivisions));
}

std::uint64_t meshTriangles(const Mesh& mesh, double density)
{
    const double d = density * mesh.densityScale;
    std::uint64_t count = 0;
    for (const Quad& q : mesh.quads)
        count += 2ull * subdivisions(q.u.length(), d) * subdivisions(q.v.length(), d);
    for (const Tri& t : mesh.triangles)
    {
        const std::uint64_t k = triangleSubdivisions(t, d);
        count += k * k;
    }
    for (const std::vector<osg::Vec3d>& polygon : mesh.polygons)
        count += polygon.size() >= 3 ? polygon.size() - 2 : 0;
    return count;
}

std::uint64_t modelTriangles(const Model& model, double density)
{
    return instancedTriangles(model, instanceCounts(model), density);
}

double calibrateDensity(const Model& model, std::uint64_t target)
{
    const std::vector<std::uint64_t> instances = instanceCounts(model);
    const auto count = [&](double density) { return instancedTriangles(model, instances, density); };
    if (count(0.0) >= target)
        return 0.0;
    double lo = 0.0, hi = 1.0;
    while (count(hi) < target && hi < maxSubdivisions)
        hi *= 2.0;
    // The count is a non-decreasing step function of the density: bisect to the step at the target.
    for (int i = 0; i < 60; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (count(mid) < target ? lo : hi) = mid;
    }
    const auto distance = [&](double density)
    {
        const std::uint64_t c = count(density);
        return c > target ? c - target : target - c;
    };
    return distance(lo) <= distance(hi) ? lo : hi;
}

osg::ref_ptr<osg::Group> buildSceneGraph(const Model& model, double density)
{
    const std::vector<std::uint64_t> instances = instanceCounts(model);
    std::vector<osg::ref_ptr<osg::Geometry>> drawables(model.meshes.size());
    for (std::size_t i = 0; i < model.meshes.size(); ++i)
        if (instances[i])
            drawables[i] = buildGeometry(model.meshes[i], density);
    osg::ref_ptr<osg::Node> root = buildNode(model.root, drawables);
    return root->asGroup();
}
} // namespace osgVis::gen
