// SPDX-License-Identifier: MIT
// The octree's shadow pre-test: a box it calls missed has no point the occluder hides (checked
// by segments from the eye to sample points), and a box wholly in the shadow is never missed.
#include "octree/OccluderShadow.h"

#include <osgVis/core/geometry/ConvexPolygon.h>

#include <gtest/gtest.h>

#include <random>

using namespace osgVis::core;

namespace
{
OccluderPolygon square(double z, double half, bool oneSided = false)
{
    OccluderPolygon p;
    p.vertices = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
    p.plane = Plane::fromPointNormal(Vec3(0, 0, z), Vec3(0, 0, 1));
    p.area = 4 * half * half;
    p.centroid = Vec3(0, 0, z);
    p.neighbours.assign(4, NoNeighbour);
    p.oneSided = oneSided;
    return p;
}

// Whether the segment eye→q crosses the (convex, axial) square strictly inside.
bool crosses(const OccluderPolygon& p, const Vec3& eye, const Vec3& q)
{
    const double a = p.plane.distance(eye), b = p.plane.distance(q);
    if (a * b >= 0.0)
        return false;
    const Vec3 x = eye + (q - eye) * (a / (a - b));
    const double half = p.vertices[1].x;
    return std::abs(x.x) < half && std::abs(x.y) < half;
}
} // namespace

TEST(OccluderShadow, AMissedBoxHasNoHiddenPointAndAShadowedBoxIsNeverMissed)
{
    const OccluderPolygon wall = square(0.0, 1.0);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0), size(0.01, 1.5), unit(0.0, 1.0);
    int missed = 0, shadowed = 0;
    for (int trial = 0; trial < 4000; ++trial)
    {
        const Vec3 eye(coordinate(random), coordinate(random), trial % 2 ? 2.0 + unit(random) : -2.0 - unit(random));
        OccluderShadows shadows;
        shadows.begin(1);
        shadows.add(0, wall, eye, 1e-9);
        const Vec3 corner(coordinate(random), coordinate(random), coordinate(random));
        const Aabb box(corner, corner + Vec3(size(random), size(random), size(random)));
        if (shadows.misses(0, box))
        {
            ++missed;
            for (int s = 0; s < 64; ++s)
            {
                const Vec3 q = box.min + Vec3(unit(random), unit(random), unit(random)) * box.extent();
                ASSERT_FALSE(crosses(wall, eye, q)) << "trial " << trial;
            }
        }
        bool allHidden = true;
        for (int c = 0; c < 8 && allHidden; ++c)
            allHidden = crosses(wall, eye, box.corner(c));
        if (allHidden) // a convex shadow holds the box when it holds its corners
        {
            ++shadowed;
            EXPECT_FALSE(shadows.misses(0, box)) << "trial " << trial;
        }
    }
    EXPECT_GT(missed, 1000);
    EXPECT_GT(shadowed, 50);
}

TEST(OccluderShadow, EdgeOnEyeCulledSideAndPolygonsNotAddedBehaveAsClassifyDoes)
{
    const OccluderPolygon wall = square(0.0, 1.0, true);
    const Aabb behind(Vec3(-0.1, -0.1, -2.0), Vec3(0.1, 0.1, -1.9));
    OccluderShadows shadows;
    shadows.begin(3);
    shadows.add(0, wall, Vec3(0, 0, 1), 1e-9);  // front side: the box behind is in its shadow
    shadows.add(1, wall, Vec3(0, 0, -5), 1e-9); // one-sided, seen from its culled side
    EXPECT_FALSE(shadows.misses(0, behind));
    EXPECT_TRUE(shadows.misses(1, Aabb(Vec3(-0.1, -0.1, 1.0), Vec3(0.1, 0.1, 1.1))));
    EXPECT_FALSE(shadows.misses(2, behind)); // never added: no claim
    shadows.begin(3);
    shadows.add(0, wall, Vec3(5, 0, 0), 1e-9); // edge-on
    EXPECT_TRUE(shadows.misses(0, behind));
    shadows.begin(3); // a new frame forgets the old shadows
    EXPECT_FALSE(shadows.misses(0, behind));
}
