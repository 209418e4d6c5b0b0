// SPDX-License-Identifier: MIT
// Field of tetrahedra: regular tetrahedra of random size and orientation resting on a ground plane
// (the third scene of Coorg–Teller's octree paper): many small objects that hide each other only
// partly. Tetrahedra are grouped in square tiles, each tile a MatrixTransform to its corner, so
// every object's world bounds go through a transform.
//
//   +---------------------------+
//   |  .  ^ . ' . tile . ' .  . |     ^ . ' tetrahedra (none within reach of the walk)
//   | .+=================+  .  '|
//   |  |  . ' . ^ .  .   |' .   |     = the walk: a loop around the field's inner part
//   | '|' . ' .  .  ' ^  | .  . |
//   |  +=================+ ' .  |
//   | . ' .  .  ' . ^ .  ' .  ^ |
//   +---------------------------+
#include "Palette.h"
#include "Scenes.h"
#include "Shapes.h"
#include "WalkPath.h"

#include <osg/Quat>

#include <algorithm>
#include <cmath>

namespace osgVis::gen
{
namespace
{
constexpr double spacing = 4.0; // mean distance between neighbouring tetrahedra
constexpr double minEdge = 0.5, maxEdge = 3.0;
constexpr double tileSize = 64.0;
constexpr double groundDensityScale = 0.1;
constexpr double eyeHeight = 2.0;
constexpr double walkInset = 0.15; // the walk loop keeps this fraction of the field outside it
constexpr double walkClearance = 2.5;
constexpr double turnOffset = 4.0;

// Four triangles per tetrahedron at the coarsest meshing; their number grows as triangles^0.75.
std::size_t tetraCount(std::uint64_t triangles)
{
    return std::max<std::size_t>(8, std::size_t(std::llround(std::pow(double(triangles), 0.75) / 2.0)));
}

// Uniformly distributed rotation: a uniform point of the unit 4-ball, normalised (rejection sampling
// needs only arithmetic and a square root, so it is the same everywhere).
osg::Quat randomRotation(Random& rng)
{
    for (;;)
    {
        const double x = rng.uniform(-1, 1), y = rng.uniform(-1, 1), z = rng.uniform(-1, 1), w = rng.uniform(-1, 1);
        const double n2 = x * x + y * y + z * z + w * w;
        if (n2 > 1e-6 && n2 <= 1.0)
        {
            const double n = std::sqrt(n2);
            return osg::Quat(x / n, y / n, z / n, w / n);
        }
    }
}

double distanceToSegment(const osg::Vec2d& p, const osg::Vec2d& a, const osg::Vec2d& b)
{
    const osg::Vec2d ab = b - a;
    const double t = std::clamp(((p - a) * ab) / std::max(ab.length2(), 1e-12), 0.0, 1.0);
    return (a + ab * t - p).length();
}

class TetraBuilder
{
public:
    TetraBuilder(std::size_t count, std::uint32_t seed)
        : _count(count), _size(spacing * std::sqrt(double(count))), _rng(seed)
    {
    }

    SceneModel build()
    {
        const std::vector<osg::Vec3d> route = loop();
        const int tiles = std::max(1, int(std::lround(_size / tileSize)));
        const double tile = _size / tiles;
        std::vector<ModelNode> tileNodes;
        for (int j = 0; j < tiles; ++j)
            for (int i = 0; i < tiles; ++i)
            {
                const osg::Vec3d corner(i * tile, j * tile, 0.0);
                ModelNode node = ModelNode::transform("tile " + std::to_string(i) + "," + std::to_string(j),
                                                      osg::Matrixd::translate(corner));
                ModelNode& geode = node.add(ModelNode::geode("tetrahedra"));
                geode.meshes.push_back(
                    _model.addMesh(quadMesh("ground", varied(palette::ground, _rng, 0.03),
                                            horizontalQuad(0, 0, tile, tile, 0, true), groundDensityScale)));
                tileNodes.push_back(std::move(node));
            }

        for (std::size_t n = 0; n < _count; ++n)
        {
            const double edge = _rng.uniform(minEdge, maxEdge);
            const double radius = edge * std::sqrt(6.0) / 4.0; // circumradius
            osg::Vec2d at;
            do
                at.set(_rng.uniform(radius, _size - radius), _rng.uniform(radius, _size - radius));
            while (nearRoute(at, route, radius + walkClearance));
            const osg::Quat rotation = randomRotation(_rng);
            const int i = std::min(tiles - 1, int(at.x() / tile)), j = std::min(tiles - 1, int(at.y() / tile));
            const osg::Vec3d corner(i * tile, j * tile, 0.0);
            Mesh mesh = tetrahedron(edge, rotation, osg::Vec3d(at.x(), at.y(), 0.0) - corner);
            tileNodes[std::size_t(j * tiles + i)].children.front().meshes.push_back(_model.addMesh(std::move(mesh)));
        }
        for (ModelNode& node : tileNodes)
            _model.root.add(std::move(node));

        SceneModel scene;
        const osg::BoundingBoxd bounds(0.0, 0.0, 0.0, _size, _size, maxEdge);
        scene.walk = perspectiveWalk(walkAlong(route, WalkPace{5.0, 0.1, 6.0, 200, 1000}), 0.1, farPlaneFor(bounds));
        scene.model = std::move(_model);
        return scene;
    }

private:
    // Regular tetrahedron of the given edge, rotated, lowest vertex on the ground below `base`.
    Mesh tetrahedron(double edge, const osg::Quat& rotation, const osg::Vec3d& base)
    {
        const double s = edge / std::sqrt(8.0);
        osg::Vec3d v[4] = {{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
        double lowest = 0.0;
        for (osg::Vec3d& p : v)
        {
            p = rotation * p;
            lowest = std::min(lowest, p.z());
        }
        for (osg::Vec3d& p : v)
            p += base - osg::Vec3d(0.0, 0.0, lowest);
        const osg::Vec3d centre = (v[0] + v[1] + v[2] + v[3]) * 0.25;

        Mesh mesh;
        mesh.name = "tetra";
        mesh.colour = varied(palette::tetra, _rng, 0.2);
        static const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
        for (const auto& f : faces)
        {
            Tri t{v[f[0]], v[f[1]], v[f[2]]};
            if (((t.b - t.a) ^ (t.c - t.a)) * (t.a - centre) < 0.0)
                std::swap(t.b, t.c); // outward
            mesh.triangles.push_back(t);
        }
        return mesh;
    }

    // A loop around the inner part of the field, corners cut so the walk turns smoothly.
    std::vector<osg::Vec3d> loop() const
    {
        const double lo = walkInset * _size, hi = (1.0 - walkInset) * _size;
        const double offset = std::min(turnOffset, 0.25 * (hi - lo));
        const osg::Vec3d corners[4] = {
            {lo, lo, eyeHeight}, {hi, lo, eyeHeight}, {hi, hi, eyeHeight}, {lo, hi, eyeHeight}};
        std::vector<osg::Vec3d> points{(corners[0] + corners[1]) * 0.5};
        for (int c = 1; c <= 4; ++c)
        {
            const osg::Vec3d& corner = corners[c % 4];
            osg::Vec3d in = corner - corners[c - 1], out = corners[(c + 1) % 4] - corner;
            in.normalize();
            out.normalize();
            points.push_back(corner - in * offset);
            points.push_back(corner + out * offset);
        }
        points.push_back((corners[0] + corners[1]) * 0.5);
        return points;
    }

    static bool nearRoute(const osg::Vec2d& p, const std::vector<osg::Vec3d>& route, double distance)
    {
        for (std::size_t i = 0; i + 1 < route.size(); ++i)
            if (distanceToSegment(p, {route[i].x(), route[i].y()}, {route[i + 1].x(), route[i + 1].y()}) < distance)
                return true;
        return false;
    }

    std::size_t _count;
    double _size;
    Random _rng;
    Model _model;
};
} // namespace

SceneModel tetraModel(std::uint64_t triangles, std::uint32_t seed)
{
    return TetraBuilder(tetraCount(triangles), seed).build();
}
} // namespace osgVis::gen
