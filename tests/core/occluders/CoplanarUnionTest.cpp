// SPDX-License-Identifier: MIT
// Coplanar pieces of different objects join into one occluder only where their union is exactly
// a convex polygon: abutting or overlapping wall pieces do; an L, a gap or opposite faces do not.
#include <osgVis/core/occluders/CoplanarUnion.h>

#include <gtest/gtest.h>

using namespace osgVis::core;

namespace
{
// Rectangle x0..x1, z0..z1 in the plane y = 0, facing -y (counter-clockwise seen from -y).
OccluderPolygon wallPiece(double x0, double x1, double z0, double z1, bool facingMinusY = true)
{
    OccluderPolygon p;
    if (facingMinusY)
        p.vertices = {{x0, 0, z0}, {x1, 0, z0}, {x1, 0, z1}, {x0, 0, z1}};
    else
        p.vertices = {{x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}};
    p.plane = Plane(Vec3(0, facingMinusY ? -1 : 1, 0), 0.0);
    p.area = (x1 - x0) * (z1 - z0);
    p.centroid = Vec3((x0 + x1) / 2, 0, (z0 + z1) / 2);
    p.neighbours.assign(4, NoNeighbour);
    return p;
}

Aabb boundsOf(const OccluderPolygon& p)
{
    Aabb b;
    for (const Vec3& v : p.vertices)
        b.expand(v);
    return b;
}
} // namespace

TEST(CoplanarUnion, AbuttingAndOverlappingPiecesJoinIntoOneRectangle)
{
    const std::vector<OccluderPolygon> pieces = {wallPiece(0, 4, 0, 3), wallPiece(4, 8, 0, 3),
                                                 wallPiece(7.5, 10, 0, 3)};
    const std::vector<OccluderPolygon> unions = coplanarUnions(pieces, 100.0);
    ASSERT_EQ(unions.size(), 1u);
    const OccluderPolygon& wall = unions[0];
    EXPECT_EQ(wall.vertices.size(), 4u);
    EXPECT_NEAR(wall.area, 30.0, 1e-9);
    const Aabb b = boundsOf(wall);
    EXPECT_NEAR(b.min.x, 0.0, 1e-9);
    EXPECT_NEAR(b.max.x, 10.0, 1e-9);
    EXPECT_NEAR(b.max.z, 3.0, 1e-9);
    EXPECT_NEAR(glm::dot(wall.plane.normal, Vec3(0, -1, 0)), 1.0, 1e-12);
    EXPECT_FALSE(wall.oneSided);
    for (std::uint32_t n : wall.neighbours)
        EXPECT_EQ(n, NoNeighbour);
}

TEST(CoplanarUnion, NotchesGapsAndOppositeFacesNeverJoin)
{
    // A jamb and a lintel make an L; two pieces 1 mm apart leave a gap; faces of opposite
    // orientation; a piece in a parallel plane 1 cm away.
    EXPECT_TRUE(coplanarUnions({wallPiece(0, 1, 0, 3), wallPiece(1, 2, 2.1, 3)}, 100.0).empty());
    EXPECT_TRUE(coplanarUnions({wallPiece(0, 1, 0, 3), wallPiece(1.001, 2, 0, 3)}, 100.0).empty());
    EXPECT_TRUE(coplanarUnions({wallPiece(0, 1, 0, 3), wallPiece(1, 2, 0, 3, false)}, 100.0).empty());
    OccluderPolygon offset = wallPiece(1, 2, 0, 3);
    for (Vec3& v : offset.vertices)
        v.y = 0.01;
    offset.plane.d = 0.01;
    EXPECT_TRUE(coplanarUnions({wallPiece(0, 1, 0, 3), offset}, 100.0).empty());
}

TEST(CoplanarUnion, OneSidedPiecesJoinOnlyWithOneSided)
{
    OccluderPolygon a = wallPiece(0, 1, 0, 3), b = wallPiece(1, 2, 0, 3);
    a.oneSided = true;
    EXPECT_TRUE(coplanarUnions({a, b}, 100.0).empty());
    b.oneSided = true;
    const std::vector<OccluderPolygon> unions = coplanarUnions({a, b}, 100.0);
    ASSERT_EQ(unions.size(), 1u);
    EXPECT_TRUE(unions[0].oneSided);
}
