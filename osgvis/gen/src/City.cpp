// SPDX-License-Identifier: MIT
// City: a square grid of blocks separated by streets, each block a raised pavement carrying a few
// box buildings of random footprint and height (the urban scene of Wang–Agarwal–Har-Peled's
// occlusion-mask paper). Facades are tessellated, so most triangles are hidden behind the nearest
// buildings from street level.
//
//   y
//   ^    street   street   street
//   |  +--------+--------+--------+
//   |  |  ##  # |   ###  |  #  ## |   #: buildings on a block's lots
//   |  |  ##    | L      | L   ## |   L: street lamp (one shared drawable, many transforms)
//   |  +--------+--------+--------+
//   |  |   ###  |  #  #  |        |
//   |  | L      | L      | L ###  |
//   |  +--------+--------+--------+---> x
//
// The walk drives along street centre lines at eye height, choosing straight on, left or right at
// each intersection.
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
constexpr double blockSize = 80.0;
constexpr double streetWidth = 16.0;
constexpr double pitch = blockSize + streetWidth;
constexpr double kerbHeight = 0.15;
constexpr double minHeight = 10.0, maxHeight = 80.0;
constexpr double groundDensityScale = 0.05; // the street surface is meshed 20× coarser than facades
constexpr double eyeHeight = 1.7;
// Where the walk leaves the straight line before an intersection (metres from its centre).
constexpr double turnOffset = 6.0;

// Blocks along each side; about 76 triangles per block at the coarsest meshing, blocks growing as
// triangles^0.7.
int blocksPerSide(std::uint64_t triangles)
{
    return std::max(1, int(std::lround(std::sqrt(std::pow(double(triangles), 0.7) / 70.0))));
}

Mesh lampMesh()
{
    Mesh mesh;
    mesh.name = "lamp";
    mesh.colour = palette::lamp;
    addBox(mesh, {-0.08, -0.08, 0.0}, {0.08, 0.08, 6.0}, NO_BOTTOM);
    addBox(mesh, {-0.08, 0.08, 5.8}, {0.08, 1.5, 5.95});
    return mesh;
}

class CityBuilder
{
public:
    CityBuilder(int blocks, std::uint32_t seed) : _blocks(blocks), _rng(seed) {}

    SceneModel build()
    {
        const MeshId lamp = _model.addMesh(lampMesh());
        for (int by = 0; by < _blocks; ++by)
            for (int bx = 0; bx < _blocks; ++bx)
                addBlock(bx, by, lamp);
        SceneModel scene;
        const double size = _blocks * pitch + streetWidth;
        const osg::BoundingBoxd bounds(0.0, 0.0, 0.0, size, size, maxHeight);
        scene.walk =
            perspectiveWalk(walkAlong(route(), WalkPace{10.0, 0.1, 12.0, 200, 1000}), 0.1, farPlaneFor(bounds));
        scene.model = std::move(_model);
        return scene;
    }

private:
    void addBlock(int bx, int by, MeshId lamp)
    {
        const std::string id = std::to_string(bx) + "," + std::to_string(by);
        ModelNode& block = _model.root.add(ModelNode::group("block " + id));
        ModelNode& geode = block.add(ModelNode::geode("buildings " + id));

        // The ground tile reaches to the middle of the surrounding streets; the last row and column
        // also cover the city's outer street.
        const double tx0 = bx * pitch, ty0 = by * pitch;
        const double tx1 = tx0 + pitch + (bx == _blocks - 1 ? streetWidth : 0.0);
        const double ty1 = ty0 + pitch + (by == _blocks - 1 ? streetWidth : 0.0);
        geode.meshes.push_back(_model.addMesh(
            quadMesh("street", palette::street, horizontalQuad(tx0, ty0, tx1, ty1, 0.0, true), groundDensityScale)));

        const double x0 = tx0 + streetWidth, y0 = ty0 + streetWidth;
        Mesh pavement = boxMesh("pavement", varied(palette::building, _rng, 0.05), {x0, y0, 0.0},
                                {x0 + blockSize, y0 + blockSize, kerbHeight}, NO_BOTTOM);
        pavement.densityScale = groundDensityScale;
        geode.meshes.push_back(_model.addMesh(std::move(pavement)));

        const int lotsX = _rng.between(1, 3), lotsY = _rng.between(1, 3);
        const double lotX = blockSize / lotsX, lotY = blockSize / lotsY;
        for (int j = 0; j < lotsY; ++j)
            for (int i = 0; i < lotsX; ++i)
            {
                const double setback = _rng.uniform(1.0, 4.0);
                const double height = _rng.uniform(minHeight, maxHeight);
                const osg::Vec3d lo(x0 + i * lotX + setback, y0 + j * lotY + setback, kerbHeight);
                const osg::Vec3d hi(x0 + (i + 1) * lotX - setback, y0 + (j + 1) * lotY - setback, kerbHeight + height);
                geode.meshes.push_back(
                    _model.addMesh(boxMesh("building", varied(palette::building, _rng, 0.15), lo, hi, NO_BOTTOM)));
            }

        ModelNode& lampPost =
            block.add(ModelNode::transform("lamp", quarterTurn(_rng.between(0, 3), {x0 + 1.0, y0 + 1.0, kerbHeight})));
        lampPost.add(ModelNode::geode("lamp")).meshes.push_back(lamp);
    }

    osg::Vec3d intersection(int ix, int iy) const
    {
        return {ix * pitch + 0.5 * streetWidth, iy * pitch + 0.5 * streetWidth, eyeHeight};
    }

    // A drive over the street grid: at each intersection straight on (p = 1/2), left or right, never
    // back, never off the grid.
    std::vector<osg::Vec3d> route()
    {
        static const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
        int ix = int(_rng.below(std::uint32_t(_blocks + 1))), iy = int(_rng.below(std::uint32_t(_blocks + 1)));
        auto inside = [&](int d)
        {
            const int nx = ix + dx[d], ny = iy + dy[d];
            return nx >= 0 && ny >= 0 && nx <= _blocks && ny <= _blocks;
        };
        int dir = int(_rng.below(4));
        while (!inside(dir))
            dir = (dir + 1) % 4;

        std::vector<osg::Vec3d> points{intersection(ix, iy)};
        const double wanted = 1100.0; // metres: past the walk's 1000 views
        for (double length = 0.0; length < wanted; length += pitch)
        {
            const osg::Vec3d in(dx[dir], dy[dir], 0.0);
            ix += dx[dir];
            iy += dy[dir];
            const double pick = _rng.unit();
            int next = pick < 0.5 ? dir : pick < 0.75 ? (dir + 1) % 4 : (dir + 3) % 4;
            for (int tries = 0; !inside(next) && tries < 4; ++tries)
                next = next == dir ? (dir + 1) % 4 : next == (dir + 1) % 4 ? (dir + 3) % 4 : dir;
            if (!inside(next))
                next = (dir + 2) % 4; // a 1 × 1 grid corner: nothing but back
            const osg::Vec3d out(dx[next], dy[next], 0.0);
            points.push_back(intersection(ix, iy) - in * turnOffset);
            points.push_back(intersection(ix, iy) + out * turnOffset);
            dir = next;
        }
        return points;
    }

    int _blocks;
    Random _rng;
    Model _model;
};
} // namespace

SceneModel cityModel(std::uint64_t triangles, std::uint32_t seed)
{
    return CityBuilder(blocksPerSide(triangles), seed).build();
}
} // namespace osgVis::gen
