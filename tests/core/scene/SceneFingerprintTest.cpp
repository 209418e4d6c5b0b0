// SPDX-License-Identifier: MIT
// The two model fingerprints: sceneFingerprint (bounds, counts, flags; what version 1 .pvs files
// store) and sceneGeometryFingerprint, which also sees the triangles on a grid of 2^-20 of the
// scene's largest extent.
#include <osgVis/core/scene/SceneFingerprint.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace osgVis::core;

namespace
{
//   z
//   4 +---+---+---+---+      a wall in the plane y = 0 drawn as a 4 x 4 grid of quads (32
//     |   |   |   |   |      triangles); object 1 is a box behind it. The hole: quad (1, 1)
//   2 +---+---+---+---+      (marked #) collapses to a point, its two triangles kept, so the
//     |   |###|   |   |      wall's bounds, triangle count and flags stay as they were.
//   0 +---+---+---+---+ x
//     0   1   2   3   4
Scene makeWallScene()
{
    Scene scene;
    const ObjectId wall = scene.addObject(Aabb({0, 0, 0}, {4, 0, 4}), 32, OBJECT_NONE, "wall");
    scene.objects[wall].firstTriangle = 0;
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
        {
            const Vec3f p00(float(i), 0.0f, float(k)), p10(float(i + 1), 0.0f, float(k));
            const Vec3f p01(float(i), 0.0f, float(k + 1)), p11(float(i + 1), 0.0f, float(k + 1));
            scene.triangles.push_back({p00, p10, p11});
            scene.triangles.push_back({p00, p11, p01});
        }
    const ObjectId box = scene.addObject(Aabb({1, 1, 1}, {2, 2, 2}), 1, OBJECT_NONE, "box");
    scene.objects[box].firstTriangle = 32;
    scene.triangles.push_back({Vec3f(1, 1, 1), Vec3f(2, 1, 1), Vec3f(2, 2, 2)});
    return scene;
}

// Triangles 2 (4 i + k) and the next draw the wall's quad (i, k).
void cutHole(Scene& scene, int i, int k)
{
    for (int t = 2 * (4 * i + k); t < 2 * (4 * i + k) + 2; ++t)
        scene.triangles[t] = {Vec3f(float(i), 0, float(k)), Vec3f(float(i), 0, float(k)), Vec3f(float(i), 0, float(k))};
}

// Moves every copy of the wall's vertex `from` to `to`.
void moveWallVertex(Scene& scene, const Vec3f& from, const Vec3f& to)
{
    for (std::uint32_t t = 0; t < 32; ++t)
        for (Vec3f* v : {&scene.triangles[t].a, &scene.triangles[t].b, &scene.triangles[t].c})
            if (*v == from)
                *v = to;
}
} // namespace

TEST(SceneFingerprint, GeometryFingerprintIsStableAndCoversTheBoundsFields)
{
    const Scene scene = makeWallScene();
    EXPECT_EQ(sceneGeometryFingerprint(scene), sceneGeometryFingerprint(makeWallScene()));
    EXPECT_NE(sceneGeometryFingerprint(scene), sceneFingerprint(scene));
    Scene flagged = makeWallScene();
    flagged.objects[1].flags = OBJECT_TRANSPARENT;
    EXPECT_NE(sceneGeometryFingerprint(flagged), sceneGeometryFingerprint(scene));
    Scene moved = makeWallScene();
    moved.objects[1].bounds.max.x = 2.5;
    EXPECT_NE(sceneGeometryFingerprint(moved), sceneGeometryFingerprint(scene));
}

TEST(SceneFingerprint, HoleInAWallChangesOnlyTheGeometryFingerprint)
{
    const Scene scene = makeWallScene();
    Scene holed = makeWallScene();
    cutHole(holed, 1, 1);
    EXPECT_EQ(sceneFingerprint(holed), sceneFingerprint(scene));
    EXPECT_NE(sceneGeometryFingerprint(holed), sceneGeometryFingerprint(scene));
}

TEST(SceneFingerprint, MovesBelowTheGridKeepTheGeometryFingerprint)
{
    // The scene spans 4 along x and z: the grid step is 4 * 2^-20 = 2^-18 and (2, 0, 2) lies on it.
    const Scene scene = makeWallScene();
    Scene nudged = makeWallScene();
    moveWallVertex(nudged, Vec3f(2, 0, 2), Vec3f(2.0f + std::ldexp(1.0f, -21), 0, 2));
    EXPECT_EQ(sceneGeometryFingerprint(nudged), sceneGeometryFingerprint(scene));
    Scene shifted = makeWallScene();
    moveWallVertex(shifted, Vec3f(2, 0, 2), Vec3f(2.0f + std::ldexp(1.0f, -18), 0, 2));
    EXPECT_NE(sceneGeometryFingerprint(shifted), sceneGeometryFingerprint(scene));
}

TEST(SceneFingerprint, NonFiniteVerticesHashAsOneMarker)
{
    Scene a = makeWallScene(), b = makeWallScene();
    a.triangles[32].a.x = std::numeric_limits<float>::quiet_NaN();
    b.triangles[32].a.x = std::numeric_limits<float>::infinity();
    EXPECT_EQ(sceneGeometryFingerprint(a), sceneGeometryFingerprint(b));
    EXPECT_NE(sceneGeometryFingerprint(a), sceneGeometryFingerprint(makeWallScene()));
}

TEST(SceneFingerprint, GeometryFingerprintNeedsTheTriangles)
{
    Scene scene = makeWallScene();
    scene.triangles.clear();
    EXPECT_EQ(sceneFingerprint(scene), sceneFingerprint(makeWallScene()));
    try
    {
        sceneGeometryFingerprint(scene);
        FAIL() << "fingerprinted a scene without its triangles";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_STREQ(e.what(), "sceneGeometryFingerprint: object 0 has triangles up to 32 but the scene holds 0 "
                               "(extracted without triangles?)");
    }
}
