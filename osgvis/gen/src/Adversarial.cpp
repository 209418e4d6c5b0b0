// SPDX-License-Identifier: MIT
// The adversarial set: one small scene per known way culling goes wrong (DESIGN.md), each with a
// short walk. Every culling mode runs all of them against the oracle. Unless stated, the eye looks
// along +y with z up, perspective 60° fovY at 1280 × 1024, near 0.1, far 100; "target" boxes are
// red, occluders blue.
#include "Palette.h"
#include "Scenes.h"
#include "Shapes.h"
#include "WalkPath.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace osgVis::gen
{
namespace
{
constexpr double keyStep = 0.1;

osg::Vec3d along(double x, double y, double z)
{
    return {x, y, z};
}

// A geode (named after the scene) holding each mesh as its own drawable.
ModelNode& addGeode(Model& model, const std::string& name, std::vector<Mesh> meshes)
{
    ModelNode& geode = model.root.add(ModelNode::geode(name));
    for (Mesh& m : meshes)
        geode.meshes.push_back(model.addMesh(std::move(m)));
    return geode;
}

Mesh cube(const std::string& name, const osg::Vec4& colour, const osg::Vec3d& centre, double size)
{
    const osg::Vec3d h(0.5 * size, 0.5 * size, 0.5 * size);
    return boxMesh(name, colour, centre - h, centre + h);
}

// Views from each eye towards eye + (0, 1, 0), one time step apart.
std::vector<core::WalkKey> lookingAlongY(const std::vector<osg::Vec3d>& eyes)
{
    std::vector<core::WalkKey> keys;
    for (const osg::Vec3d& eye : eyes)
        keys.push_back(lookAt(keyStep * double(keys.size()), eye, eye + osg::Vec3d(0.0, 1.0, 0.0)));
    return keys;
}

// Seen from above:
//
//        +-------+            y = 5 … 6   target, 1 m cube, z 0 … 1
//        |   T   |
//        +-------+
//   ===========| |===========  y = 0      two walls 4 m wide, 3 m tall, 0.15 m thick, a 2 cm slit at x = 0
//
//              e              y = -5, -8, -10, -20 (z = 0.5): the target shows only through the slit,
//                             a few pixels wide up close and under one pixel from 20 m
SceneModel thinSlit()
{
    SceneModel scene;
    const double gap = 0.02;
    addGeode(scene.model, "thin-slit",
             {boxMesh("wall left", palette::occluder, {-4.0 - 0.5 * gap, -0.075, 0.0}, {-0.5 * gap, 0.075, 3.0}),
              boxMesh("wall right", palette::occluder, {0.5 * gap, -0.075, 0.0}, {4.0 + 0.5 * gap, 0.075, 3.0}),
              boxMesh("target", palette::target, {-0.5, 5.0, 0.0}, {0.5, 6.0, 1.0})});
    std::vector<core::WalkKey> keys;
    for (const osg::Vec3d& eye :
         {along(0, -5, 0.5), along(0.05, -5, 0.5), along(-0.03, -8, 0.5), along(0, -10, 0.5), along(0, -20, 0.5)})
        keys.push_back(lookAt(keyStep * double(keys.size()), eye, {0.0, 5.5, 0.5}));
    scene.walk = perspectiveWalk(keys, 0.1, 100.0);
    return scene;
}

// The frame seen by the eye at the origin (x right, z up, looking along +y):
//
//   S---------S---------S      S: 0.5 m plates at 10 m straddling the frame, two pixels of each inside
//   | i       i       i |      i: 0.3 m plates at 20 m wholly inside, one pixel from the border
//   S i               i S
//   | i       i       i |
//   S---------S---------S
//
// Plates (2 cm deep, facing the eye) sit at every edge midpoint and every corner; nothing else is in
// the scene.
SceneModel frameEdges()
{
    SceneModel scene;
    const double tanHalfFov = 1.0 / std::sqrt(3.0); // tan 30°
    const double aspect = 1280.0 / 1024.0;
    std::vector<Mesh> meshes;
    auto ring = [&](double distance, double size, double pixelsInside, bool straddling)
    {
        const double halfHeight = distance * tanHalfFov, halfWidth = aspect * halfHeight;
        const double pixel = 2.0 * halfHeight / 1024.0;
        for (int sz = -1; sz <= 1; ++sz)
            for (int sx = -1; sx <= 1; ++sx)
            {
                if (sx == 0 && sz == 0)
                    continue;
                // Inner face `pixelsInside` pixels inside the border; the cube extends outward (straddling)
                // or inward from there.
                auto place = [&](int side, double half)
                {
                    if (side == 0)
                        return 0.0;
                    const double inner = half - pixelsInside * pixel;
                    return side * (straddling ? inner + 0.5 * size : inner - 0.5 * size);
                };
                // Thin plates facing the eye: a deep box's side faces would reach further into the frame.
                const osg::Vec3d centre(place(sx, halfWidth), distance, place(sz, halfHeight));
                const osg::Vec3d half(0.5 * size, 0.01, 0.5 * size);
                meshes.push_back(
                    boxMesh(straddling ? "straddling" : "inside", palette::target, centre - half, centre + half));
            }
    };
    ring(10.0, 0.5, 2.0, true);
    ring(20.0, 0.3, 1.0, false);
    addGeode(scene.model, "frame-edges", std::move(meshes));
    scene.walk = perspectiveWalk(lookingAlongY({along(0, 0, 0), along(0, 0, 0), along(0, 0, 0)}), 0.1, 100.0);
    return scene;
}

// Off-centre frustum at near 0.1: left -0.02, right 0.1, bottom -0.03, top 0.05, i.e. at 20 m it
// spans x -4 … 20 and z -6 … 10 (viewport 1200 × 800). Seen by the eye at the origin:
//
//        z = 10 +------T------+
//               |             |       L R T B: 1 m cubes at 20 m with 2 cm inside each edge
//    O          L      C      R       C: a cube in the middle
//               |             |       O: cubes inside a centred 60° frustum but outside this one
//        z = -6 +------B------+
//             x = -4        x = 20
SceneModel offCentre()
{
    SceneModel scene;
    const double d = 20.5; // cube centres; their near faces are at 20 m
    addGeode(scene.model, "off-centre",
             {cube("left", palette::target, {-4.0 + 0.02 - 0.5, d, 2.0}, 1.0),
              cube("right", palette::target, {20.0 - 0.02 + 0.5, d, 2.0}, 1.0),
              cube("bottom", palette::target, {8.0, d, -6.0 + 0.02 - 0.5}, 1.0),
              cube("top", palette::target, {8.0, d, 10.0 - 0.02 + 0.5}, 1.0),
              cube("centre", palette::target, {8.0, d, 2.0}, 1.0),
              cube("outside left", palette::occluder, {-8.0, d, 0.0}, 1.0),
              cube("outside below", palette::occluder, {0.0, d, -9.0}, 1.0)});
    core::Walk& walk = scene.walk;
    walk = perspectiveWalk(lookingAlongY({along(0, 0, 0), along(0, 0, 0), along(0, 0, 0)}), 0.1, 100.0);
    walk.projection.kind = core::WalkProjection::Kind::Frustum;
    walk.projection.left = -0.02;
    walk.projection.right = 0.1;
    walk.projection.bottom = -0.03;
    walk.projection.top = 0.05;
    walk.width = 1200;
    walk.height = 800;
    return scene;
}

// Orthographic, x -10 … 10, z -8 … 8, near 0.1, far 200; eye at y = -20. Seen from above:
//
//          |      B          y = 20     B: target beside the wall's edge (x 5.3 … 6.3): visible in
//          H                 y = 10        parallel projection, hidden in any perspective from the eye
//   ===========              y = 0      wall x -5 … 5, z -4 … 4     H: hidden behind it
//                    E       y = 0 … 1  E: straddles the right frame edge x = 10
//          e                 y = -20
//          X                 y = -25    X: behind the eye, outside the near plane
//   F far away at y = 150, x = -8 (inside the far plane)
SceneModel ortho()
{
    SceneModel scene;
    addGeode(scene.model, "ortho",
             {boxMesh("wall", palette::occluder, {-5.0, 0.0, -4.0}, {5.0, 0.2, 4.0}),
              boxMesh("hidden", palette::target, {-1.0, 10.0, -1.0}, {1.0, 11.0, 1.0}),
              boxMesh("beside", palette::target, {5.3, 20.0, -0.5}, {6.3, 21.0, 0.5}),
              boxMesh("edge", palette::target, {9.9, 0.0, -0.5}, {10.9, 1.0, 0.5}),
              boxMesh("behind eye", palette::occluder, {-0.5, -25.5, -0.5}, {0.5, -24.5, 0.5}),
              boxMesh("far", palette::target, {-8.5, 150.0, -0.5}, {-7.5, 151.0, 0.5})});
    scene.walk = perspectiveWalk(lookingAlongY({along(0, -20, 0), along(0, -20, 0), along(0, -20, 0)}), 0.1, 200.0);
    scene.walk.projection.kind = core::WalkProjection::Kind::Ortho;
    scene.walk.projection.left = -10.0;
    scene.walk.projection.right = 10.0;
    scene.walk.projection.bottom = -8.0;
    scene.walk.projection.top = 8.0;
    return scene;
}

// Six 1 m target cubes at y = 20 (x = -10, -6, -2, 2, 6, 10), each behind a degenerate polygon at
// y = 5 on its line of sight (centre x/4), none of which can hide it:
//
//   zero-area   sliver      repeated      non-planar     NaN vertex        bow-tie
//      /          /|          /           |\  (left       (vertex 0 NaN:    \  /
//     /          / |    (a, b, b, a)      | | half of     the other three     \/   top wedge
//    /          /  |                      |/  the box)    would cover it)     /\   uncovered
//
// A culler that trusts any of them as an occluder culls a visible cube.
SceneModel degenerateOccluders()
{
    SceneModel scene;
    std::vector<Mesh> meshes;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double xs[6] = {-10, -6, -2, 2, 6, 10};
    const char* names[6] = {"zero-area", "sliver", "repeated-vertex", "non-planar", "nan-vertex", "bow-tie"};
    for (int i = 0; i < 6; ++i)
    {
        meshes.push_back(cube("target", palette::target, {xs[i], 20.5, 0.0}, 1.0));
        const double c = xs[i] / 4.0; // the cube's projection at y = 5 spans c ± 0.125
        auto p = [&](double dx, double dz, double dy = 0.0) { return osg::Vec3d(c + dx, 5.0 + dy, dz); };
        std::vector<osg::Vec3d> polygon;
        switch (i)
        {
        case 0:
            polygon = {p(-0.4, -0.4), p(0.0, 0.0), p(0.4, 0.4), p(0.2, 0.2)};
            break;
        case 1:
            polygon = {p(-0.4, -0.4), p(0.4, 0.4), p(0.4, 0.401)};
            break;
        case 2:
            polygon = {p(-0.4, -0.4), p(0.4, 0.4), p(0.4, 0.4), p(-0.4, -0.4)};
            break;
        case 3:
            polygon = {p(-0.45, -0.4), p(-0.02, -0.4, -0.5), p(-0.02, 0.4, 0.5), p(-0.45, 0.4)};
            break;
        case 4:
            polygon = {osg::Vec3d(nan, nan, nan), p(-0.45, -0.3), p(0.45, -0.3), p(0.0, 0.6)};
            break;
        case 5:
            polygon = {p(-0.4, -0.4), p(0.4, 0.4), p(0.4, -0.4), p(-0.4, 0.4)};
            break;
        }
        Mesh mesh;
        mesh.name = names[i];
        mesh.colour = palette::occluder;
        mesh.polygons.push_back(std::move(polygon));
        meshes.push_back(std::move(mesh));
    }
    addGeode(scene.model, "degenerate-occluders", std::move(meshes));
    scene.walk = perspectiveWalk(lookingAlongY({along(0, 0, 0), along(0.05, 0, 0), along(-0.05, 0, 0)}), 0.1, 100.0);
    return scene;
}

// Seen from above (walls 3 m tall, standing on z = 0):
//
//      A      |   B  ##   C     y = 10 … 11, z 1 … 2: target cubes
//             |      ##
//             |      ##         x = 0: a zero-thickness wall quad, y 2 … 20
//             |      ##         x = 3 … 3.15: a box wall, y 2 … 20
//             e      e          eyes at z = 1.5 on the plane x = 0, then on the plane x = 3 of the box
//                               wall's face; a third eye at z = 3 on the plane of the box wall's top
SceneModel eyeOnOccluderPlane()
{
    SceneModel scene;
    Mesh quadWall = quadMesh("wall quad", palette::occluder, Quad{{0.0, 2.0, 0.0}, {0.0, 18.0, 0.0}, {0.0, 0.0, 3.0}});
    addGeode(scene.model, "eye-on-occluder-plane",
             {std::move(quadWall), boxMesh("wall box", palette::occluder, {3.0, 2.0, 0.0}, {3.15, 20.0, 3.0}),
              boxMesh("A", palette::target, {-2.5, 10.0, 1.0}, {-1.5, 11.0, 2.0}),
              boxMesh("B", palette::target, {1.0, 10.0, 1.0}, {2.0, 11.0, 2.0}),
              boxMesh("C", palette::target, {4.5, 10.0, 1.0}, {5.5, 11.0, 2.0})});
    scene.walk = perspectiveWalk(lookingAlongY({along(0, 0, 1.5), along(3.0, 0, 1.5), along(1.5, 0, 3.0)}), 0.1, 100.0);
    return scene;
}

// One geode, eight drawables. Seen from above:
//
//                 h                 y = 14: 0.6 m cube, the only hidden one
//   o   o   o  [=====]  o   o   o   y = 10: six 0.8 m cubes and a 2 × 0.5 × 2 m box hiding h
//
//                 e                 eyes at x = 0, ±0.2
SceneModel geodeOneHidden()
{
    SceneModel scene;
    std::vector<Mesh> meshes;
    for (double x : {-6.0, -4.0, -2.0})
        meshes.push_back(cube("visible", palette::target, {x, 10.4, 0.0}, 0.8));
    meshes.push_back(boxMesh("occluder", palette::occluder, {-1.0, 10.0, -1.0}, {1.0, 10.5, 1.0}));
    meshes.push_back(cube("hidden", palette::target, {0.0, 14.3, 0.0}, 0.6));
    for (double x : {2.0, 4.0, 6.0})
        meshes.push_back(cube("visible", palette::target, {x, 10.4, 0.0}, 0.8));
    addGeode(scene.model, "geode-one-hidden", std::move(meshes));
    scene.walk = perspectiveWalk(lookingAlongY({along(0, 0, 0), along(0.2, 0, 0), along(-0.2, 0, 0)}), 0.1, 100.0);
    return scene;
}

// Seen from above:
//
//        H        V     y = 12: H hidden behind the wall, V beside it (1 m cubes)
//     ======            y = 6: 4 × 0.2 × 3 m wall under a MatrixTransform with DataVariance DYNAMIC
//        e              eyes at x = 0, 0.1, 0.2
//
// The wall does not move yet; a later scene animates its transform. A DYNAMIC object is never an
// occluder and never culled by precomputed data, so H must stay in every conservative answer that
// relies on precomputation.
SceneModel movingOccluder()
{
    SceneModel scene;
    addGeode(scene.model, "targets",
             {cube("hidden", palette::target, {0.0, 12.5, 0.0}, 1.0),
              cube("beside", palette::target, {4.0, 12.5, 0.0}, 1.0)});
    ModelNode& mover =
        scene.model.root.add(ModelNode::transform("moving wall", osg::Matrixd::translate(0.0, 6.0, 0.0)));
    mover.dynamic = true;
    mover.add(ModelNode::geode("moving wall"))
        .meshes.push_back(scene.model.addMesh(boxMesh("wall", palette::occluder, {-2.0, -0.1, -1.5}, {2.0, 0.1, 1.5})));
    scene.walk = perspectiveWalk(lookingAlongY({along(0, 0, 0), along(0.1, 0, 0), along(0.2, 0, 0)}), 0.1, 100.0);
    return scene;
}

using AdversarialBuilder = SceneModel (*)();
const std::vector<std::pair<std::string, AdversarialBuilder>>& adversarialBuilders()
{
    static const std::vector<std::pair<std::string, AdversarialBuilder>> builders = {
        {"thin-slit", thinSlit},
        {"frame-edges", frameEdges},
        {"off-centre", offCentre},
        {"ortho", ortho},
        {"degenerate-occluders", degenerateOccluders},
        {"eye-on-occluder-plane", eyeOnOccluderPlane},
        {"geode-one-hidden", geodeOneHidden},
        {"moving-occluder", movingOccluder},
    };
    return builders;
}
} // namespace

std::vector<std::string> adversarialSceneNames()
{
    std::vector<std::string> names;
    for (const auto& entry : adversarialBuilders())
        names.push_back(entry.first);
    return names;
}

SceneModel adversarialModel(const std::string& name)
{
    for (const auto& entry : adversarialBuilders())
        if (entry.first == name)
            return entry.second();
    std::string known;
    for (const std::string& n : adversarialSceneNames())
        known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown adversarial scene '" + name + "' (known: " + known + ")");
}
} // namespace osgVis::gen
