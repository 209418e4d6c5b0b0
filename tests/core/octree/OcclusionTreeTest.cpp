// SPDX-License-Identifier: MIT
// The occlusion tree of the octree module's sweep (src/OcclusionTree.h): occluders that share no
// edge hide together, margins open cracks where edges only touch, and a box is hidden only when
// it lies behind the occluders. Eye at the origin looking along +y in every case.
#include "octree/OcclusionTree.h"
#include "AllocationCounter.h"

#include <gtest/gtest.h>

#include <random>

using namespace osgVis::core;

namespace
{
constexpr double Margin = 1e-3;

// Quad x0..x1, z0..z1 in the plane y = depth, facing the eye (-y).
std::vector<Vec3> quad(double x0, double x1, double z0, double z1, double depth)
{
    return {{x0, depth, z0}, {x0, depth, z1}, {x1, depth, z1}, {x1, depth, z0}};
}

Plane facingEye(double depth)
{
    return Plane(Vec3(0, -1, 0), depth); // -y + depth: the eye (y = 0) is on the positive side
}

bool insert(OcclusionTree& tree, const std::vector<Vec3>& polygon, const Plane& plane, double margin = Margin)
{
    return tree.insert(polygon, plane, std::vector<double>(polygon.size(), margin));
}

Aabb box(double x0, double x1, double y0, double y1, double z0, double z1)
{
    return Aabb(Vec3(x0, y0, z0), Vec3(x1, y1, z1));
}

OcclusionTree treeAtOrigin()
{
    OcclusionTree tree;
    tree.reset(Vec3(0.0), Vec3(0.0, 1.0, 0.0), 100.0);
    return tree;
}
} // namespace

TEST(OcclusionTree, EmptyTreeHidesNothing)
{
    const OcclusionTree tree = treeAtOrigin();
    EXPECT_FALSE(tree.hidden(box(-1, 1, 10, 11, -1, 1), 0.0));
}

TEST(OcclusionTree, OneQuadHidesWhatLiesBehindItsCone)
{
    OcclusionTree tree = treeAtOrigin();
    ASSERT_TRUE(insert(tree, quad(-2, 2, -2, 2, 5), facingEye(5)));
    EXPECT_TRUE(tree.hidden(box(-1, 1, 8, 9, -1, 1), 0.0));     // behind, inside the cone
    EXPECT_FALSE(tree.hidden(box(-1, 1, 2, 3, -1, 1), 0.0));    // in front of the quad
    EXPECT_FALSE(tree.hidden(box(-1, 1, 4.5, 6, -1, 1), 0.0));  // straddles the quad's plane
    EXPECT_FALSE(tree.hidden(box(3, 5, 10, 11, -1, 1), 0.0));   // beside the cone
    EXPECT_FALSE(tree.hidden(box(-1, 3.9, 9, 10, -1, 1), 0.0)); // reaches out of the cone (x/y up to 0.4)
    EXPECT_TRUE(tree.hidden(box(-1, 3.5, 9, 10, -1, 1), 0.0));  // x/y at most 3.5/9 < 0.4: inside
    EXPECT_FALSE(tree.hidden(box(-1, 1, 8, 9, -1, 1), 3.5));    // not 3.5 behind: z-fighting margin
}

TEST(OcclusionTree, RejectsPolygonsSeenFromBehindOrDegenerate)
{
    OcclusionTree tree = treeAtOrigin();
    EXPECT_FALSE(insert(tree, quad(-2, 2, -2, 2, 5), Plane(Vec3(0, 1, 0), -5)));             // back to the eye
    EXPECT_FALSE(insert(tree, {{0, 5, 0}, {1, 5, 0}}, facingEye(5)));                        // two vertices
    EXPECT_FALSE(insert(tree, {{0, 5, 0}, {0, 10, 0}, {1, 5, 0}}, Plane(Vec3(0, 0, 1), 0))); // eye on its plane
    EXPECT_EQ(tree.occluderCount(), 0u);
    EXPECT_FALSE(tree.hidden(box(-1, 1, 8, 9, -1, 1), 0.0));
}

// Two quads that overlap on screen but share no edge, at different depths, hide together a box
// that neither hides alone.
TEST(OcclusionTree, DisconnectedOccludersFuse)
{
    OcclusionTree tree = treeAtOrigin();
    const Aabb target = box(-3, 3, 20, 21, -1, 1); // x/y within ±0.15: A reaches 0.1, B from -0.07
    ASSERT_TRUE(insert(tree, quad(-3, 0.5, -2, 2, 5), facingEye(5)));
    EXPECT_FALSE(tree.hidden(target, 0.0));
    OcclusionTree other = treeAtOrigin();
    ASSERT_TRUE(insert(other, quad(-0.5, 3, -2, 2, 7), facingEye(7)));
    EXPECT_FALSE(other.hidden(target, 0.0));
    ASSERT_TRUE(insert(tree, quad(-0.5, 3, -2, 2, 7), facingEye(7)));
    EXPECT_TRUE(tree.hidden(target, 0.0));
    // Between the two in depth: the part beyond A's cone (x/y > 0.1) is covered only by B, behind it.
    EXPECT_FALSE(tree.hidden(box(-1, 1, 6, 6.5, -0.5, 0.5), 0.0));
    EXPECT_TRUE(tree.hidden(box(-0.5, 0.5, 6, 6.5, -0.5, 0.5), 0.0)); // within A's cone, behind A
}

// Two triangles of one quad meet at the diagonal. With no margin on the shared edge (a real mesh
// edge) the seam is closed; inserted as strangers (margins on every edge) the seam stays open, as a
// T-junction crack could be.
TEST(OcclusionTree, SharedEdgeClosesTheSeamMarginsOpenIt)
{
    const std::vector<Vec3> lower = {{-2, 5, -2}, {2, 5, 2}, {2, 5, -2}};
    const std::vector<Vec3> upper = {{-2, 5, -2}, {-2, 5, 2}, {2, 5, 2}};
    const Aabb acrossSeam = box(-0.5, 0.5, 10, 11, -0.5, 0.5);
    const Aabb besideSeam = box(0.5, 1.0, 10, 11, -1.0, -0.8); // wholly in the lower triangle's cone

    OcclusionTree shared = treeAtOrigin();
    ASSERT_TRUE(shared.insert(lower, facingEye(5), {0.0, Margin, Margin})); // edge 0 is the diagonal
    ASSERT_TRUE(shared.insert(upper, facingEye(5), {Margin, Margin, 0.0})); // edge 2 is the diagonal
    EXPECT_TRUE(shared.hidden(acrossSeam, 0.0));

    OcclusionTree strangers = treeAtOrigin();
    ASSERT_TRUE(insert(strangers, lower, facingEye(5)));
    ASSERT_TRUE(insert(strangers, upper, facingEye(5)));
    EXPECT_FALSE(strangers.hidden(acrossSeam, 0.0));
    EXPECT_TRUE(strangers.hidden(besideSeam, 0.0));
}

// A nearer occluder inserted after a farther one still counts where they overlap.
TEST(OcclusionTree, LaterNearerOccluderJoinsTheLeaf)
{
    OcclusionTree tree = treeAtOrigin();
    ASSERT_TRUE(insert(tree, quad(-4, 4, -4, 4, 20), facingEye(20)));
    ASSERT_TRUE(insert(tree, quad(-1, 1, -1, 1, 5), facingEye(5)));
    EXPECT_TRUE(tree.hidden(box(-0.5, 0.5, 10, 11, -0.5, 0.5), 0.0)); // only the near quad is in front
    EXPECT_FALSE(tree.hidden(box(-3, 3, 10, 11, -0.5, 0.5), 0.0));    // sticks out of the near quad
}

// A polygon narrower than its margins (a sliver far away) would claim nothing: it is not added.
TEST(OcclusionTree, PolygonShrunkToNothingByItsMarginsAddsNothing)
{
    OcclusionTree tree = treeAtOrigin();
    EXPECT_FALSE(insert(tree, quad(-1, 1, -0.001, 0.001, 50), facingEye(50))); // 2 mm high, 1 mm margins
    EXPECT_EQ(tree.occluderCount(), 0u);
    EXPECT_EQ(tree.nodeCount(), 0u);
    EXPECT_TRUE(insert(tree, quad(-1, 1, -0.01, 0.01, 50), facingEye(50))); // 2 cm high: room inside
}

// A fragment reaching a leaf gets only the edge lines it touches. A small quad A (image ±0.2)
// makes 4 lines; a larger quad B behind it (image ±0.4) is split by A's lines into four outer
// pieces, touching 3, 2, 2 and 1 of B's edges, and A's own cell, which B covers whole: no line
// there, the leaf just lists both occluders. Every edge line everywhere would make 4 + 5·4 = 24.
TEST(OcclusionTree, FragmentsGetOnlyTheEdgeLinesTheyTouch)
{
    OcclusionTree tree = treeAtOrigin();
    ASSERT_TRUE(insert(tree, quad(-1, 1, -1, 1, 5), facingEye(5)));
    EXPECT_EQ(tree.nodeCount(), 4u);
    ASSERT_TRUE(insert(tree, quad(-4, 4, -4, 4, 10), facingEye(10)));
    EXPECT_EQ(tree.nodeCount(), 12u);
    EXPECT_EQ(tree.occluderCount(), 2u);
    EXPECT_TRUE(tree.hidden(box(-0.5, 0.5, 12, 13, -0.5, 0.5), 0.0)); // behind both
    EXPECT_TRUE(tree.hidden(box(-0.5, 0.5, 6, 7, -0.5, 0.5), 0.0));   // between them, within A's cone
    EXPECT_TRUE(tree.hidden(box(-6, 6, 20, 21, -6, 6), 0.0));         // behind B, beyond A's cone
    EXPECT_FALSE(tree.hidden(box(-1.5, 1.5, 6, 7, -0.5, 0.5), 0.0));  // between them, beyond A's cone
    EXPECT_FALSE(tree.hidden(box(-9, 9, 20, 21, -1, 1), 0.0));        // reaches out of B's cone
}

// A convex hull is tested by its points: a thin tilted triangle behind the edge of an occluder is
// hidden although its bounding box reaches out of the occluder's cone.
TEST(OcclusionTree, PointsTestTighterThanTheirBox)
{
    OcclusionTree tree = treeAtOrigin();
    ASSERT_TRUE(insert(tree, {{-2, 5, -2}, {-2, 5, 2}, {2, 5, -2}}, facingEye(5))); // lower-left half
    const Vec3 sliver[3] = {{-3, 10, -3.5}, {-3, 10, 2.5}, {2.5, 10, -3.5}};
    Aabb bounds;
    for (const Vec3& p : sliver)
        bounds.expand(p);
    EXPECT_TRUE(tree.hidden(sliver, 3, bounds, 0.0));
    EXPECT_FALSE(tree.hidden(bounds, 0.0));
}

// Conservative on random scenes: whatever the tree calls hidden, every sampled ray from the eye
// to the target's points meets an occluder first (brute force over all occluder triangles).
TEST(OcclusionTree, RandomScenesNeverHideASeenPoint)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hiddenTargets = 0;
    for (int scene = 0; scene < 100; ++scene)
    {
        OcclusionTree tree = treeAtOrigin();
        std::vector<std::vector<Vec3>> triangles;
        for (int i = 0; i < 30; ++i)
        {
            const Vec3 centre(unit(rng) * 8 - 4, 4 + unit(rng) * 8, unit(rng) * 8 - 4);
            std::vector<Vec3> t;
            for (int k = 0; k < 3; ++k)
                t.push_back(centre + Vec3(unit(rng) * 3 - 1.5, unit(rng) * 3 - 1.5, unit(rng) * 3 - 1.5));
            Vec3 normal = glm::cross(t[1] - t[0], t[2] - t[0]);
            if (glm::length(normal) < 1e-3)
                continue;
            normal = glm::normalize(normal);
            Plane plane(normal, -glm::dot(normal, t[0]));
            if (plane.distance(Vec3(0.0)) < 0.0)
            {
                std::swap(t[1], t[2]);
                plane = Plane(-normal, -plane.d);
            }
            if (insert(tree, t, plane))
                triangles.push_back(t);
        }
        for (int target = 0; target < 50; ++target)
        {
            const Vec3 centre(unit(rng) * 10 - 5, 10 + unit(rng) * 10, unit(rng) * 10 - 5);
            const Vec3 half(0.2 + unit(rng), 0.2 + unit(rng), 0.2 + unit(rng));
            const Aabb b(centre - half, centre + half);
            if (!tree.hidden(b, 0.0))
                continue;
            ++hiddenTargets;
            for (int s = 0; s < 200; ++s)
            {
                const Vec3 p(b.min.x + unit(rng) * (b.max.x - b.min.x), b.min.y + unit(rng) * (b.max.y - b.min.y),
                             b.min.z + unit(rng) * (b.max.z - b.min.z));
                bool blocked = false;
                for (const std::vector<Vec3>& t : triangles)
                {
                    // Ray from the eye (origin) towards p meets triangle t before p (Möller–Trumbore).
                    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0], h = glm::cross(p, e2);
                    const double a = glm::dot(e1, h);
                    if (std::abs(a) < 1e-12)
                        continue;
                    const Vec3 s0 = -t[0];
                    const double u = glm::dot(s0, h) / a;
                    const Vec3 q = glm::cross(s0, e1);
                    const double v = glm::dot(p, q) / a, hit = glm::dot(e2, q) / a;
                    if (u >= 0 && v >= 0 && u + v <= 1 && hit > 0 && hit < 1)
                    {
                        blocked = true;
                        break;
                    }
                }
                ASSERT_TRUE(blocked) << "scene " << scene << " target " << target << ": point seen";
            }
        }
    }
    EXPECT_GT(hiddenTargets, 50); // the check above has something to check
}

// Per frame the sweep resets the tree, inserts and queries: once its buffers have grown to a
// scene's size, doing it all again allocates nothing.
TEST(OcclusionTree, NoAllocationOnceGrown)
{
    std::vector<std::vector<Vec3>> walls;
    std::vector<Aabb> targets;
    for (int i = 0; i < 12; ++i)
    {
        const double x = -6 + i, depth = 5 + (i % 4) * 2;
        walls.push_back(quad(x, x + 1.5, -1 - i % 3, 1 + i % 2, depth));
        targets.push_back(box(x, x + 0.5, 14 + i, 15 + i, -0.5, i % 3 == 0 ? 8 : 0.5)); // every third rises over
    }
    const std::vector<double> margins(4, Margin);
    OcclusionTree tree;
    std::size_t hiddenCount = 0;
    const auto frame = [&]
    {
        tree.reset(Vec3(0.0), Vec3(0.0, 1.0, 0.0), 100.0);
        hiddenCount = 0;
        for (const std::vector<Vec3>& wall : walls)
            tree.insert(wall, facingEye(wall[0].y), margins);
        for (const Aabb& target : targets)
            hiddenCount += tree.hidden(target, 0.0) ? 1 : 0;
    };
    frame();
    const std::size_t warmHidden = hiddenCount;
    const std::size_t before = osgVis::test::allocationCount();
    frame();
    EXPECT_EQ(osgVis::test::allocationCount() - before, 0u);
    EXPECT_EQ(hiddenCount, warmHidden);
    EXPECT_EQ(hiddenCount, 8u); // all but the four that rise over the walls
}
