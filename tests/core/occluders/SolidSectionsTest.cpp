// SPDX-License-Identifier: MIT
// Sections through closed convex objects: a box gives its three middle sections; an open, a
// non-convex, a wrongly culled or a moving mesh gives none.
#include "BoxScenes.h"

#include <osgVis/core/occluders/SolidSections.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace osgVis::core;
using namespace osgVis::test;

TEST(SolidSections, AClosedBoxGivesItsThreeMiddleSections)
{
    Scene scene;
    addBox(scene, {0, 0, 0}, {2, 4, 6}, "box");
    const std::vector<OccluderPolygon> sections = convexSolidSections(scene);
    ASSERT_EQ(sections.size(), 3u);
    const double areas[3] = {4 * 6, 2 * 6, 2 * 4};
    for (int axis = 0; axis < 3; ++axis)
    {
        const OccluderPolygon& s = sections[axis];
        EXPECT_TRUE(s.insideSolid);
        EXPECT_FALSE(s.oneSided);
        EXPECT_EQ(s.owner, 0u);
        EXPECT_NEAR(s.area, areas[axis], 1e-9);
        EXPECT_EQ(s.plane.normal[axis], 1.0);
        for (const Vec3& v : s.vertices)
        {
            EXPECT_DOUBLE_EQ(v[axis], axis == 0 ? 1.0 : axis == 1 ? 2.0 : 3.0);
            EXPECT_TRUE(Aabb(Vec3(0), Vec3(2, 4, 6)).contains(v));
        }
        // Counter-clockwise around the normal.
        const ConvexPolygon polygon(s.vertices);
        EXPECT_GT(glm::dot(polygon.newellNormal(), s.plane.normal), 0.0);
    }
}

TEST(SolidSections, OpenNonConvexWronglyCulledOrMovingMeshesGiveNone)
{
    Scene scene;
    std::vector<Triangle> open = boxTriangles({0, 0, 0}, {1, 1, 1});
    open.pop_back();
    addTriangles(scene, open, "open box");
    // An L of two boxes: closed pieces, but one object that is not convex.
    std::vector<Triangle> ell = boxTriangles({0, 0, 0}, {2, 1, 1});
    for (const Triangle& t : boxTriangles({0, 1, 0}, {1, 2, 1}))
        ell.push_back(t);
    addTriangles(scene, ell, "two boxes");
    // Faces pointing inwards, drawn only from the front: sightlines from outside see their backs.
    std::vector<Triangle> inwards = boxTriangles({5, 5, 5}, {6, 6, 6});
    for (Triangle& t : inwards)
        std::swap(t.b, t.c);
    addTriangles(scene, inwards, "inside-out", OBJECT_CULL_BACK);
    addBox(scene, {8, 8, 8}, {9, 9, 9}, "moving", OBJECT_DYNAMIC);
    addBox(scene, {8, 0, 0}, {9, 1, 1}, "front faces culled", OBJECT_CULL_FRONT);
    EXPECT_TRUE(convexSolidSections(scene).empty());
    // Inside-out faces drawn from both sides are fine.
    scene.objects[2].flags = OBJECT_NONE;
    EXPECT_EQ(convexSolidSections(scene).size(), 3u);
}
