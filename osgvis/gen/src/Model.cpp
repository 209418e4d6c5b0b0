// SPDX-License-Identifier: MIT
#include "Model.h"

#include "Circle.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace osgVis::gen
{
namespace
{
// Caps one edge so a runaway density cannot ask for billions of cells.
constexpr double maxSubdivisions = 4096.0;

constexpr double pi = 3.141592653589793;

std::uint32_t triangleSubdivisions(const Tri& t, double density)
{
    const double longest = std::max({(t.b - t.a).length(), (t.c - t.b).length(), (t.a - t.c).length()});
    return subdivisions(longest, density);
}

std::uint32_t tubeSides(const Tube& t, double density)
{
    return std::max(3u, subdivisions(2.0 * pi * std::max(t.baseRadius, t.topRadius), density));
}

std::uint32_t tubeRings(const Tube& t, double density)
{
    return subdivisions(0.25 * (t.top - t.base).length(), density);
}

std::uint32_t ellipsoidSubdivisions(const Ellipsoid& e, double density)
{
    return subdivisions(0.5 * pi * std::max({e.a.length(), e.b.length(), e.c.length()}), density);
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

    // Side vertices are shared around and along the tube; each cap has its own copies of its rim (same
    // coordinates, bit for bit, so the surface stays watertight) for a flat normal.
    void addTube(const Tube& t, std::uint32_t sides, std::uint32_t rings)
    {
        osg::Vec3d axis = t.top - t.base;
        const double length = axis.normalize();
        std::vector<osg::Vec3d> around(sides);
        for (std::uint32_t s = 0; s < sides; ++s)
            around[s] = aroundAxis(axis, double(s) / sides);
        const auto ringCentre = [&](std::uint32_t r) { return t.base + axis * (length * r / rings); };
        const auto ringRadius = [&](std::uint32_t r)
        { return t.baseRadius + (t.topRadius - t.baseRadius) * (double(r) / rings); };

        const auto side = std::uint32_t(_vertices->size());
        for (std::uint32_t r = 0; r <= rings; ++r)
            for (std::uint32_t s = 0; s < sides; ++s)
            {
                _vertices->push_back(osg::Vec3(ringCentre(r) + around[s] * ringRadius(r)));
                // The cone's slope tilts the normal towards the narrow end.
                _normals->push_back(unitNormal(around[s] * length + axis * (t.baseRadius - t.topRadius)));
            }
        for (std::uint32_t r = 0; r < rings; ++r)
            for (std::uint32_t s = 0; s < sides; ++s)
            {
                const std::uint32_t a = side + r * sides + s, b = side + r * sides + (s + 1) % sides;
                addTriangle(a, b, b + sides);
                addTriangle(a, b + sides, a + sides);
            }
        addCap(side, sides, ringCentre(0), -axis, false);
        addCap(side + rings * sides, sides, ringCentre(rings), axis, true);
    }

    // Lattice points (x, y, z) with |x| + |y| + |z| = k cover the octahedron; each is one vertex,
    // shared by the faces that meet there, pushed onto the unit sphere and then onto the ellipsoid.
    void addEllipsoid(const Ellipsoid& e, std::uint32_t k)
    {
        std::map<std::array<int, 3>, std::uint32_t> indexOf;
        const osg::Vec3d gradient[3] = {e.a / e.a.length2(), e.b / e.b.length2(), e.c / e.c.length2()};
        const auto vertex = [&](int x, int y, int z)
        {
            const auto [found, added] = indexOf.try_emplace({x, y, z}, std::uint32_t(_vertices->size()));
            if (added)
            {
                osg::Vec3d n(x, y, z);
                n.normalize();
                _vertices->push_back(osg::Vec3(e.centre + e.a * n.x() + e.b * n.y() + e.c * n.z()));
                _normals->push_back(unitNormal(gradient[0] * n.x() + gradient[1] * n.y() + gradient[2] * n.z()));
            }
            return found->second;
        };
        const int n = int(k);
        for (int sz : {1, -1})
            for (int sy : {1, -1})
                for (int sx : {1, -1})
                {
                    // A mirrored octant runs its lattice clockwise: swap two corners to face outward.
                    const bool mirrored = sx * sy * sz < 0;
                    const auto face = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c)
                    {
                        if (mirrored)
                            std::swap(b, c);
                        addTriangle(a, b, c);
                    };
                    for (int j = 0; j < n; ++j)
                        for (int i = 0; i + j < n; ++i)
                        {
                            const auto at = [&](int ii, int jj)
                            { return vertex(sx * ii, sy * jj, sz * (n - ii - jj)); };
                            face(at(i, j), at(i + 1, j), at(i, j + 1));
                            if (i + j + 1 < n)
                                face(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                        }
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
    // A fan around the centre over `sides` rim vertices starting at `rim` (copied), facing `normal`;
    // counter-clockwise seen from outside when the rim runs counter-clockwise about `normal`.
    void addCap(std::uint32_t rim, std::uint32_t sides, const osg::Vec3d& centre, const osg::Vec3d& normal,
                bool rimCounterClockwise)
    {
        const osg::Vec3 n = unitNormal(normal);
        const auto first = std::uint32_t(_vertices->size());
        for (std::uint32_t s = 0; s < sides; ++s)
        {
            const osg::Vec3 p = (*_vertices)[rim + s];
            _vertices->push_back(p);
            _normals->push_back(n);
        }
        const auto middle = std::uint32_t(_vertices->size());
        _vertices->push_back(osg::Vec3(centre));
        _normals->push_back(n);
        for (std::uint32_t s = 0; s < sides; ++s)
        {
            std::uint32_t a = first + s, b = first + (s + 1) % sides;
            if (!rimCounterClockwise)
                std::swap(a, b);
            addTriangle(middle, a, b);
        }
    }

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
    for (const Tube& t : mesh.tubes)
        writer.addTube(t, tubeSides(t, d), tubeRings(t, d));
    for (const Ellipsoid& e : mesh.ellipsoids)
        writer.addEllipsoid(e, ellipsoidSubdivisions(e, d));
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
    for (const Tube& t : mesh.tubes)
    {
        const std::uint64_t sides = tubeSides(t, d);
        count += 2 * sides * tubeRings(t, d) + 2 * sides;
    }
    for (const Ellipsoid& e : mesh.ellipsoids)
    {
        const std::uint64_t k = ellipsoidSubdivisions(e, d);
        count += 8 * k * k;
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
