// SPDX-License-Identifier: MIT
// Occluder polygons from scene triangles: coplanar merging into convex polygons, links across
// shared edges, eligibility flags, face-culling orientation, welding and degenerate input.
#include <osgVis/core/occluders/OccluderBuilder.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <set>

using namespace osgVis::core;

namespace
{
// Adds an object made of `triangles` to the scene.
ObjectId addObject(Scene& scene, const std::vector<Triangle>& triangles, std::uint32_t flags = OBJECT_NONE)
{
    Aabb bounds;
    for (const Triangle& t : triangles)
    {
        for (const Vec3f& v : {t.a, t.b, t.c})
        {
            if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))
                bounds.expand(Vec3(v));
        }
    }
    const ObjectId id = scene.addObject(bounds, std::uint32_t(triangles.size()), flags);
    scene.objects[id].firstTriangle = std::uint32_t(scene.triangles.size());
    scene.triangles.insert(scene.triangles.end(), triangles.begin(), triangles.end());
    return id;
}

// A rectangle origin + [0,1]·u + [0,1]·v split into cells × cells quads, two triangles each,
// counter-clockwise around u × v. Diagonals alternate so no single direction dominates.
std::vector<Triangle> tessellatedRectangle(const Vec3& origin, const Vec3& u, const Vec3& v, int cells)
{
    std::vector<Triangle> out;
    auto at = [&](int i, int j) { return Vec3f(origin + u * (double(i) / cells) + v * (double(j) / cells)); };
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j)
        {
            const Vec3f p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
            if ((i + j) % 2 == 0)
            {
                out.push_back({p00, p10, p11});
                out.push_back({p00, p11, p01});
            }
            else
            {
                out.push_back({p00, p10, p01});
                out.push_back({p10, p11, p01});
            }
        }
    return out;
}

// The six faces of the box [lo, hi], each tessellated, wound counter-clockwise seen from outside.
std::vector<Triangle> tessellatedBox(const Vec3& lo, const Vec3& hi, int cells)
{
    const Vec3 e = hi - lo;
    const Vec3 x(e.x, 0, 0), y(0, e.y, 0), z(0, 0, e.z);
    std::vector<Triangle> out;
    auto add = [&](const Vec3& origin, const Vec3& u, const Vec3& v)
    {
        const auto face = tessellatedRectangle(origin, u, v, cells);
        out.insert(out.end(), face.begin(), face.end());
    };
    add(lo, y, x);     // bottom, −z
    add(lo + z, x, y); // top, +z
    add(lo, x, z);     // front, −y
    add(lo + y, z, x); // back, +y
    add(lo, z, y);     // left, −x
    add(lo + x, y, z); // right, +x
    return out;
}

double totalArea(const std::vector<OccluderPolygon>& polygons)
{
    double sum = 0.0;
    for (const OccluderPolygon& p : polygons)
        sum += p.area;
    return sum;
}

// Every polygon is planar, convex, counter-clockwise around its unit normal, with consistent
// area and centroid; every link is symmetric and joins the very same two vertices.
void expectWellFormed(const std::vector<OccluderPolygon>& polygons)
{
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
        const OccluderPolygon& polygon = polygons[p];
        SCOPED_TRACE("polygon " + std::to_string(p));
        ASSERT_GE(polygon.vertices.size(), 3u);
        ASSERT_EQ(polygon.neighbours.size(), polygon.vertices.size());
        const ConvexPolygon outline(polygon.vertices);
        EXPECT_TRUE(outline.isValidOccluder(0.0, 1e-6));
        EXPECT_NEAR(glm::length(polygon.plane.normal), 1.0, 1e-12);
        EXPECT_GT(glm::dot(outline.newellNormal(), polygon.plane.normal), 0.0);
        EXPECT_NEAR(outline.area(), polygon.area, 1e-9 * std::max(1.0, polygon.area));
        EXPECT_NEAR(polygon.plane.distance(polygon.centroid), 0.0, 1e-9);
        for (const Vec3& v : polygon.vertices)
            EXPECT_NEAR(polygon.plane.distance(v), 0.0, 1e-6);

        const std::size_t n = polygon.vertices.size();
        for (std::size_t i = 0; i < n; ++i)
        {
            const std::uint32_t q = polygon.neighbours[i];
            if (q == NoNeighbour)
                continue;
            ASSERT_LT(q, polygons.size());
            ASSERT_NE(q, p);
            const Vec3& a = polygon.vertices[i];
            const Vec3& b = polygon.vertices[(i + 1) % n];
            const OccluderPolygon& other = polygons[q];
            bool found = false;
            for (std::size_t j = 0; j < other.vertices.size(); ++j)
            {
                const Vec3& c = other.vertices[j];
                const Vec3& d = other.vertices[(j + 1) % other.vertices.size()];
                if (((c == b && d == a) || (c == a && d == b)) && other.neighbours[j] == p)
                    found = true;
            }
            EXPECT_TRUE(found) << "edge " << i << " links to " << q << " which does not link back";
        }
    }
}

std::size_t linkedEdges(const OccluderPolygon& polygon)
{
    return std::size_t(std::count_if(polygon.neighbours.begin(), polygon.neighbours.end(),
                                     [](std::uint32_t q) { return q != NoNeighbour; }));
}

std::vector<Triangle> square(const Vec3& origin, const Vec3& u, const Vec3& v)
{
    return tessellatedRectangle(origin, u, v, 1);
}
} // namespace

TEST(OccluderBuilder, TessellatedWallBecomesOnePolygon)
{
    Scene scene;
    addObject(scene, tessellatedRectangle(Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 0, 4), 10));
    ASSERT_EQ(scene.triangles.size(), 200u);

    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 1u);
    expectWellFormed(polygons);
    const OccluderPolygon& wall = polygons[0];
    EXPECT_EQ(wall.vertices.size(), 4u);
    EXPECT_NEAR(wall.area, 40.0, 1e-9);
    EXPECT_NEAR(std::abs(wall.plane.normal.y), 1.0, 1e-12);
    EXPECT_NEAR(wall.centroid.x, 5.0, 1e-9);
    EXPECT_NEAR(wall.centroid.z, 2.0, 1e-9);
    EXPECT_EQ(linkedEdges(wall), 0u);
    EXPECT_FALSE(wall.oneSided);
    EXPECT_EQ(wall.owner, 0u);
}

TEST(OccluderBuilder, ShuffledTessellationStillMergesIntoOnePolygon)
{
    // Triangle soups arrive in any order; connectivity must not depend on it.
    auto triangles = tessellatedRectangle(Vec3(-3, 2, 1), Vec3(0, 6, 0), Vec3(0, 0, 6), 12);
    std::mt19937 rng(7);
    std::shuffle(triangles.begin(), triangles.end(), rng);
    Scene scene;
    addObject(scene, triangles);

    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 1u);
    expectWellFormed(polygons);
    EXPECT_EQ(polygons[0].vertices.size(), 4u);
    EXPECT_NEAR(polygons[0].area, 36.0, 1e-9);
}

TEST(OccluderBuilder, RotatedWallFarFromTheOriginStillMerges)
{
    // At 5 km, float storage rounds the grid off its plane and off its straight edges by far more
    // than the relative tolerances; the builder allows for that rounding.
    const double pi = std::acos(-1.0);
    const Vec3 u(10 * std::cos(pi / 6), 10 * std::sin(pi / 6), 0);
    Scene scene;
    addObject(scene, tessellatedRectangle(Vec3(5000, 3500, 0), u, Vec3(0, 0, 4), 10));
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_EQ(polygons[0].vertices.size(), 4u);
    EXPECT_NEAR(polygons[0].area, 40.0, 1e-2);
    EXPECT_NEAR(glm::dot(polygons[0].plane.normal, glm::normalize(u)), 0.0, 1e-4);
}

TEST(OccluderBuilder, ShallowFoldIsNotFlattened)
{
    // Two triangles meeting at 1 milliradian near the origin: well above float rounding there.
    Scene scene;
    addObject(scene,
              {{Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0)}, {Vec3f(1, 0, 0), Vec3f(1, 1, 1e-3f), Vec3f(0, 1, 0)}});
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 2u);
    expectWellFormed(polygons);
    EXPECT_EQ(linkedEdges(polygons[0]), 1u);
    EXPECT_EQ(linkedEdges(polygons[1]), 1u);
}

TEST(OccluderBuilder, LShapedPatchSplitsIntoConvexPolygons)
{
    // A 10 × 10 grid without its 5 × 5 upper-right quarter: area 75, not convex.
    std::vector<Triangle> triangles;
    for (const Triangle& t : tessellatedRectangle(Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), 10))
    {
        const Vec3f centre = (t.a + t.b + t.c) / 3.0f;
        if (!(centre.x > 5.0f && centre.y > 5.0f))
            triangles.push_back(t);
    }
    ASSERT_EQ(triangles.size(), 150u);
    Scene scene;
    addObject(scene, triangles);

    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_GE(polygons.size(), 2u);
    EXPECT_LE(polygons.size(), 6u) << "the L should need only a few convex pieces";
    expectWellFormed(polygons);
    EXPECT_NEAR(totalArea(polygons), 75.0, 1e-9);
    for (const OccluderPolygon& p : polygons)
    {
        // Every piece lies inside the L: no vertex in the missing quarter's interior.
        for (const Vec3& v : p.vertices)
            EXPECT_FALSE(v.x > 5.0 + 1e-9 && v.y > 5.0 + 1e-9);
        EXPECT_NEAR(p.centroid.z, 0.0, 1e-12);
    }
}

TEST(OccluderBuilder, ClosedTessellatedBoxGivesSixLinkedFaces)
{
    Scene scene;
    addObject(scene, tessellatedBox(Vec3(1, 2, 3), Vec3(5, 4, 9), 4), OBJECT_CULL_BACK);

    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 6u);
    expectWellFormed(polygons);
    const Vec3 centre(3, 3, 6);
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
        const OccluderPolygon& face = polygons[p];
        EXPECT_EQ(face.vertices.size(), 4u);
        EXPECT_EQ(linkedEdges(face), 4u);
        std::set<std::uint32_t> distinct(face.neighbours.begin(), face.neighbours.end());
        EXPECT_EQ(distinct.size(), 4u) << "each edge meets a different side";
        EXPECT_TRUE(face.oneSided);
        EXPECT_GT(glm::dot(face.plane.normal, face.centroid - centre), 0.0) << "front faces point outwards";
    }
    EXPECT_NEAR(totalArea(polygons), 2 * (4 * 2 + 4 * 6 + 2 * 6), 1e-9);
}

TEST(OccluderBuilder, TwoSidedWallMergesOnEachSide)
{
    // The same tessellated wall wound both ways, as two-sided geometry is often modelled: the back
    // cannot join the front's connectivity, yet it must merge as well as the front does.
    const auto front = tessellatedRectangle(Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 0, 4), 10);
    std::vector<Triangle> back;
    for (const Triangle& t : front)
        back.push_back({t.a, t.c, t.b});
    for (const bool interleaved : {false, true})
    {
        std::vector<Triangle> triangles;
        for (std::size_t i = 0; i < front.size(); ++i)
        {
            triangles.push_back(front[i]);
            if (interleaved)
                triangles.push_back(back[i]);
        }
        if (!interleaved)
            triangles.insert(triangles.end(), back.begin(), back.end());
        Scene scene;
        addObject(scene, triangles);
        const auto polygons = buildOccluderPolygons(scene);
        expectWellFormed(polygons);
        EXPECT_NEAR(totalArea(polygons), 80.0, 1e-9);
        ASSERT_EQ(polygons.size(), 2u);
        EXPECT_NEAR(glm::dot(polygons[0].plane.normal, polygons[1].plane.normal), -1.0, 1e-12);
    }
}

TEST(OccluderBuilder, WallsOfSeparateObjectsLinkAcrossTheirCorner)
{
    // Both walls split the corner edge at the same heights; each collapses it to one edge.
    Scene scene;
    addObject(scene, tessellatedRectangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 0, 3), 3));
    addObject(scene, tessellatedRectangle(Vec3(4, 0, 0), Vec3(0, 7, 0), Vec3(0, 0, 3), 3));
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 2u);
    expectWellFormed(polygons);
    EXPECT_EQ(polygons[0].owner, 0u);
    EXPECT_EQ(polygons[1].owner, 1u);
    EXPECT_EQ(linkedEdges(polygons[0]), 1u);
    EXPECT_EQ(linkedEdges(polygons[1]), 1u);
    EXPECT_EQ(polygons[0].vertices.size(), 4u);
    EXPECT_EQ(polygons[1].vertices.size(), 4u);
}

TEST(OccluderBuilder, CornerSplitDifferentlyOnEachSideLinksOnlyAfterTJunctionRepair)
{
    // Heights 0,1,2,3 against 0,0.6,…,3: T-junctions all along the corner. Repair gives each wall
    // the other's vertices on the corner edge, so the pieces between them link one to one; with
    // one neighbour all along, each wall then collapses the corner to one shared edge.
    Scene scene;
    addObject(scene, tessellatedRectangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 0, 3), 3));
    addObject(scene, tessellatedRectangle(Vec3(4, 0, 0), Vec3(0, 4, 0), Vec3(0, 0, 3), 5));
    const auto apart = buildOccluderPolygons(scene); // by default: the drawn faces keep their cracks
    ASSERT_EQ(apart.size(), 2u);
    EXPECT_EQ(linkedEdges(apart[0]), 0u);
    EXPECT_EQ(linkedEdges(apart[1]), 0u);

    OccluderBuildOptions repaired;
    repaired.repairTJunctions = true;
    const auto polygons = buildOccluderPolygons(scene, repaired);
    ASSERT_EQ(polygons.size(), 2u);
    expectWellFormed(polygons);
    EXPECT_EQ(linkedEdges(polygons[0]), 1u);
    EXPECT_EQ(linkedEdges(polygons[1]), 1u);
    EXPECT_EQ(polygons[0].vertices.size(), 4u);
    EXPECT_EQ(polygons[1].vertices.size(), 4u);
    EXPECT_NEAR(polygons[0].area, 12.0, 1e-9);
}

TEST(OccluderBuilder, TJunctionRepairLinksHalfAnEdge)
{
    // B's edge (0,0)–(1,0) covers half of A's edge (0,0)–(2,0): repaired, A gets B's corner (1,0)
    // on that edge and the halves link.
    for (const bool coplanar : {true, false})
    {
        Scene scene;
        addObject(scene, {{Vec3f(0, 0, 0), Vec3f(2, 0, 0), Vec3f(1, 2, 0)}});
        const Vec3f apex = coplanar ? Vec3f(0.5f, -1, 0) : Vec3f(0.5f, 0, -1);
        addObject(scene, {{Vec3f(1, 0, 0), Vec3f(0, 0, 0), apex}});
        const auto apart = buildOccluderPolygons(scene);
        ASSERT_EQ(apart.size(), 2u);
        for (const OccluderPolygon& p : apart)
            EXPECT_EQ(linkedEdges(p), 0u);

        OccluderBuildOptions repaired;
        repaired.repairTJunctions = true;
        const auto polygons = buildOccluderPolygons(scene, repaired);
        ASSERT_EQ(polygons.size(), 2u);
        expectWellFormed(polygons);
        const OccluderPolygon& a = polygons[0];
        ASSERT_EQ(a.vertices.size(), 4u); // (0,0), (1,0), (2,0), (1,2)
        EXPECT_EQ(linkedEdges(a), 1u);
        EXPECT_EQ(linkedEdges(polygons[1]), 1u);
        for (std::size_t i = 0; i < 4; ++i)
            if (a.neighbours[i] == 1u)
            {
                EXPECT_EQ(a.vertices[i], Vec3(0, 0, 0));
                EXPECT_EQ(a.vertices[(i + 1) % 4], Vec3(1, 0, 0));
            }
    }
}

TEST(OccluderBuilder, DegenerateTrianglesGiveNothing)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Scene scene;
    addObject(scene, {
                         {Vec3f(0, 0, 0), Vec3f(0, 0, 0), Vec3f(1, 1, 0)},      // repeated vertex
                         {Vec3f(0, 0, 0), Vec3f(1, 1, 1), Vec3f(2, 2, 2)},      // collinear
                         {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(nan, 1, 0)},    // NaN
                         {Vec3f(0, 0, 0), Vec3f(inf, 0, 0), Vec3f(0, 1, 0)},    // infinite
                         {Vec3f(0, 0, 0), Vec3f(10, 0, 0), Vec3f(5, 1e-5f, 0)}, // sliver
                         {Vec3f(3, 3, 3), Vec3f(3, 3, 3), Vec3f(3, 3, 3)},      // a point
                     });
    EXPECT_TRUE(buildOccluderPolygons(scene).empty());

    // Stated occluders are checked the same way.
    scene.occluders.push_back({ConvexPolygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}), InvalidObject});
    scene.occluders.push_back({ConvexPolygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(std::nan(""), 1, 0)}), InvalidObject});
    scene.occluders.push_back({ConvexPolygon({Vec3(0, 0, 0), Vec3(1, 0, 0)}), InvalidObject});
    EXPECT_TRUE(buildOccluderPolygons(scene).empty());

    EXPECT_TRUE(buildOccluderPolygons(Scene{}).empty());
}

TEST(OccluderBuilder, DegenerateNeighboursDoNotSpoilGoodTriangles)
{
    auto triangles = tessellatedRectangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), 2);
    triangles.push_back({Vec3f(0, 0, 0), Vec3f(2, 0, 0), Vec3f(1, 0, 0)}); // collinear along an edge
    triangles.push_back({Vec3f(0, 0, 0), Vec3f(std::nanf(""), 0, 0), Vec3f(1, 0, 0)});
    Scene scene;
    addObject(scene, triangles);
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 1u);
    expectWellFormed(polygons);
    EXPECT_NEAR(polygons[0].area, 4.0, 1e-12);
}

TEST(OccluderBuilder, TriangleRangesBeyondTheSceneAreClipped)
{
    Scene scene;
    addObject(scene, square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
    scene.objects[0].triangleCount = 1000; // claims more than there is
    const ObjectId ghost = scene.addObject(Aabb(Vec3(0), Vec3(1)), 5);
    scene.objects[ghost].firstTriangle = 999;
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_NEAR(polygons[0].area, 1.0, 1e-12);
}

TEST(OccluderBuilder, NonManifoldAndDuplicateFacesDoNotCrash)
{
    // Three fins on one edge, a doubled face, and the same face wound both ways.
    std::vector<Triangle> triangles = {
        {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0.5f, 1, 0)}, {Vec3f(1, 0, 0), Vec3f(0, 0, 0), Vec3f(0.5f, -1, 0)},
        {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0.5f, 0, 1)}, {Vec3f(1, 0, 0), Vec3f(0, 0, 0), Vec3f(0.5f, 0, -1)},
        {Vec3f(5, 0, 0), Vec3f(6, 0, 0), Vec3f(5, 1, 0)},    {Vec3f(5, 0, 0), Vec3f(6, 0, 0), Vec3f(5, 1, 0)},
        {Vec3f(5, 0, 0), Vec3f(5, 1, 0), Vec3f(6, 0, 0)},
    };
    Scene scene;
    addObject(scene, triangles);
    const auto polygons = buildOccluderPolygons(scene);
    expectWellFormed(polygons);
    EXPECT_GE(polygons.size(), 4u);
    // Every input triangle is covered by some polygon (nothing lost, nothing invented).
    EXPECT_GE(totalArea(polygons), 4 * 0.5 + 0.5 - 1e-9);
    EXPECT_LE(totalArea(polygons), 4 * 0.5 + 3 * 0.5 + 1e-9);
}

TEST(OccluderBuilder, ExclusionFlagsContributeNothing)
{
    const std::uint32_t excluded[] = {OBJECT_DYNAMIC,
                                      OBJECT_TRANSPARENT,
                                      OBJECT_ALWAYS_VISIBLE,
                                      OBJECT_NO_AUTO_OCCLUDER,
                                      OBJECT_CULL_BACK | OBJECT_CULL_FRONT,
                                      OBJECT_OCCLUDER | OBJECT_DYNAMIC,
                                      OBJECT_OCCLUDER | OBJECT_TRANSPARENT,
                                      OBJECT_OCCLUDER | OBJECT_ALWAYS_VISIBLE,
                                      OBJECT_OCCLUDER | OBJECT_CULL_BACK | OBJECT_CULL_FRONT};
    for (std::uint32_t flags : excluded)
    {
        Scene scene;
        addObject(scene, square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)), flags);
        EXPECT_TRUE(buildOccluderPolygons(scene).empty()) << "flags " << flags;
    }
}

TEST(OccluderBuilder, StatedOccluderObjectsNeedNoAutomaticEligibility)
{
    Scene scene;
    addObject(scene, square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)), OBJECT_OCCLUDER | OBJECT_NO_AUTO_OCCLUDER);
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_EQ(polygons[0].owner, 0u);
}

TEST(OccluderBuilder, FaceCullingGivesOneSidedPolygonsFacingTheDrawnSide)
{
    // Counter-clockwise seen from +z.
    const auto triangles = square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
    struct Case
    {
        std::uint32_t flags;
        bool oneSided;
        double normalZ; // 0: either way
    };
    for (const Case& c :
         {Case{OBJECT_CULL_BACK, true, 1.0}, Case{OBJECT_CULL_FRONT, true, -1.0}, Case{OBJECT_NONE, false, 0.0}})
    {
        Scene scene;
        addObject(scene, triangles, c.flags);
        const auto polygons = buildOccluderPolygons(scene);
        ASSERT_EQ(polygons.size(), 1u);
        expectWellFormed(polygons);
        EXPECT_EQ(polygons[0].oneSided, c.oneSided);
        if (c.normalZ != 0.0)
            EXPECT_NEAR(polygons[0].plane.normal.z, c.normalZ, 1e-12);
        else
            EXPECT_NEAR(std::abs(polygons[0].plane.normal.z), 1.0, 1e-12);
    }
}

TEST(OccluderBuilder, SceneGeometryOffKeepsOnlyStatedOccluders)
{
    Scene scene;
    addObject(scene, square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));                  // plain
    addObject(scene, square(Vec3(0, 0, 5), Vec3(2, 0, 0), Vec3(0, 2, 0)), OBJECT_OCCLUDER); // stated object
    scene.occluders.push_back(
        {ConvexPolygon({Vec3(0, 0, 9), Vec3(3, 0, 9), Vec3(3, 3, 9), Vec3(0, 3, 9)}), InvalidObject});

    OccluderBuildOptions options;
    options.sceneGeometry = false;
    const auto only = buildOccluderPolygons(scene, options);
    ASSERT_EQ(only.size(), 2u);
    expectWellFormed(only);
    EXPECT_EQ(only[0].owner, 1u);
    EXPECT_NEAR(only[0].area, 4.0, 1e-12);
    EXPECT_EQ(only[1].owner, InvalidObject);
    EXPECT_FALSE(only[1].oneSided);
    EXPECT_NEAR(only[1].area, 9.0, 1e-12);
    EXPECT_EQ(only[1].vertices.size(), 4u);

    EXPECT_EQ(buildOccluderPolygons(scene).size(), 3u);
}

TEST(OccluderBuilder, StatedOccludersLinkAcrossSharedEdges)
{
    Scene scene;
    scene.occluders.push_back(
        {ConvexPolygon({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)}), InvalidObject});
    scene.occluders.push_back(
        {ConvexPolygon({Vec3(2, 0, 0), Vec3(2, 0, 2), Vec3(2, 2, 2), Vec3(2, 2, 0)}), InvalidObject});
    const auto polygons = buildOccluderPolygons(scene);
    ASSERT_EQ(polygons.size(), 2u);
    expectWellFormed(polygons);
    EXPECT_EQ(linkedEdges(polygons[0]), 1u);
    EXPECT_EQ(linkedEdges(polygons[1]), 1u);
}

TEST(OccluderBuilder, WeldingJoinsVerticesWithinTheTolerance)
{
    // Two triangles of a unit square whose shared corners differ by `gap`.
    // (Without the union pieces: apart, the two overlap in a sliver, and their union would be a
    // polygon of its own.)
    auto build = [](float gap)
    {
        Scene scene;
        addObject(scene, {{Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0)},
                          {Vec3f(gap, 0, 0), Vec3f(1, 1 + gap, 0), Vec3f(0, 1, 0)}});
        OccluderBuildOptions options;
        options.weldTolerance = 1e-4; // relative to the scene diagonal, √2
        options.coplanarAngle = 1e-3;
        options.planarUnions = false;
        return buildOccluderPolygons(scene, options);
    };
    const auto welded = build(1e-5f);
    ASSERT_EQ(welded.size(), 1u);
    expectWellFormed(welded);
    EXPECT_EQ(welded[0].vertices.size(), 4u);
    EXPECT_NEAR(welded[0].area, 1.0, 1e-4);

    const auto apart = build(1e-3f);
    ASSERT_EQ(apart.size(), 2u);
    for (const OccluderPolygon& p : apart)
        EXPECT_EQ(linkedEdges(p), 0u);
}

TEST(OccluderBuilder, MinAreaDropsSmallPolygons)
{
    Scene scene;
    addObject(scene, square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
    addObject(scene, square(Vec3(5, 0, 0), Vec3(0.01, 0, 0), Vec3(0, 0.01, 0)));
    OccluderBuildOptions options;
    options.minArea = 0.5;
    const auto polygons = buildOccluderPolygons(scene, options);
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_EQ(polygons[0].owner, 0u);
}

TEST(OccluderBuilder, ManySidedDiscIsCutBelowTheVertexCap)
{
    // A 64-gon fan: convex, but too many corners for one occluder.
    std::vector<Triangle> triangles;
    const int sides = 64;
    const double pi = std::acos(-1.0);
    for (int i = 0; i < sides; ++i)
    {
        const double a0 = 2 * pi * i / sides, a1 = 2 * pi * (i + 1) / sides;
        triangles.push_back({Vec3f(0, 0, 0), Vec3f(float(10 * std::cos(a0)), float(10 * std::sin(a0)), 0),
                             Vec3f(float(10 * std::cos(a1)), float(10 * std::sin(a1)), 0)});
    }
    Scene scene;
    addObject(scene, triangles);
    OccluderBuildOptions merged; // the merge alone (united again, the pieces would come twice)
    merged.planarUnions = false;
    const auto polygons = buildOccluderPolygons(scene, merged);
    ASSERT_GE(polygons.size(), 2u);
    EXPECT_LE(polygons.size(), 8u);
    expectWellFormed(polygons);
    double fan = 0.0;
    for (const Triangle& t : triangles)
        fan += 0.5 * glm::length(glm::cross(Vec3(t.b - t.a), Vec3(t.c - t.a)));
    EXPECT_NEAR(totalArea(polygons), fan, 1e-9 * fan);
    for (const OccluderPolygon& p : polygons)
        EXPECT_LE(p.vertices.size(), 34u); // 32 corners, plus at most the fan's centre on a straight run
}

TEST(OccluderBuilder, GeneratedBlocksOfBoxesKeepEveryFace)
{
    // A small synthetic town: tessellated boxes on a tessellated ground, one object each.
    Scene scene;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> height(5.0, 40.0);
    addObject(scene, tessellatedRectangle(Vec3(-5, -5, 0), Vec3(210, 0, 0), Vec3(0, 210, 0), 42));
    const int blocks = 10;
    for (int i = 0; i < blocks; ++i)
        for (int j = 0; j < blocks; ++j)
        {
            const Vec3 lo(i * 20.0, j * 20.0, 0.0);
            addObject(scene, tessellatedBox(lo, lo + Vec3(12, 12, height(rng)), 6), OBJECT_CULL_BACK);
        }

    const auto polygons = buildOccluderPolygons(scene);
    expectWellFormed(polygons);
    ASSERT_EQ(polygons.size(), 1u + 6u * blocks * blocks);
    for (std::size_t p = 1; p < polygons.size(); ++p)
        EXPECT_EQ(linkedEdges(polygons[p]), 4u);
}

namespace
{
std::vector<const OccluderPolygon*> unionsOf(const std::vector<OccluderPolygon>& polygons)
{
    std::vector<const OccluderPolygon*> out;
    for (const OccluderPolygon& p : polygons)
        if (!p.parts.empty())
            out.push_back(&p);
    return out;
}
} // namespace

TEST(OccluderBuilder, AWallOfSeveralObjectsAlsoHidesAsOnePolygonNamingThemAll)
{
    // A BSP compiler's wall: the lower face spans the two upper ones (a T-junction at (1, 0, 1)),
    // each a drawable of its own, two-sided and wound either way.
    Scene scene;
    addObject(scene, square(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 0, 1)));
    addObject(scene, square(Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(1, 0, 0))); // wound the other way
    addObject(scene, square(Vec3(1, 0, 1), Vec3(1, 0, 0), Vec3(0, 0, 1)));
    EXPECT_TRUE(unionsOf(buildOccluderPolygons(scene)).empty()) << "off by default";
    OccluderBuildOptions united;
    united.planarUnions = true;
    const auto polygons = buildOccluderPolygons(scene, united);
    expectWellFormed(polygons);
    const auto unions = unionsOf(polygons);
    ASSERT_EQ(unions.size(), 1u);
    EXPECT_NEAR(unions[0]->area, 4.0, 1e-9);
    // The square, with the faces' corners on its outline kept where a link starts or ends.
    Aabb bounds;
    for (const Vec3& v : unions[0]->vertices)
        bounds.expand(v);
    EXPECT_EQ(bounds.min, Vec3(0, 0, 0));
    EXPECT_EQ(bounds.max, Vec3(2, 0, 2));
    EXPECT_EQ(unions[0]->parts, (std::vector<ObjectId>{0, 1, 2}));
    EXPECT_EQ(unions[0]->owner, 0u);
    EXPECT_EQ(polygons.size(), 4u) << "the faces stay, with their links";

}

TEST(OccluderBuilder, OnlyFacesInOnePlaneFacingAlikeUnite)
{
    const auto unionCount = [](float offset, std::uint32_t flagsA, std::uint32_t flagsB, bool flipB)
    {
        Scene scene;
        addObject(scene, square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)), flagsA);
        addObject(scene,
                  flipB ? square(Vec3(1, 0, offset), Vec3(0, 1, 0), Vec3(1, 0, 0))
                        : square(Vec3(1, 0, offset), Vec3(1, 0, 0), Vec3(0, 1, 0)),
                  flagsB);
        OccluderBuildOptions united;
        united.planarUnions = true;
        return unionsOf(buildOccluderPolygons(scene, united)).size();
    };
    EXPECT_EQ(unionCount(0.0f, OBJECT_NONE, OBJECT_NONE, false), 1u);
    EXPECT_EQ(unionCount(0.0f, OBJECT_NONE, OBJECT_NONE, true), 1u) << "two-sided: either winding";
    EXPECT_EQ(unionCount(1e-3f, OBJECT_NONE, OBJECT_NONE, false), 0u) << "a step of 1e-3 is another plane";
    EXPECT_EQ(unionCount(0.0f, OBJECT_CULL_BACK, OBJECT_CULL_BACK, false), 1u);
    EXPECT_EQ(unionCount(0.0f, OBJECT_CULL_BACK, OBJECT_CULL_BACK, true), 0u) << "one-sided, facing away";
    EXPECT_EQ(unionCount(0.0f, OBJECT_CULL_BACK, OBJECT_NONE, false), 0u) << "one-sided with two-sided";
    EXPECT_EQ(unionCount(0.0f, OBJECT_NONE, OBJECT_DYNAMIC, false), 0u) << "a moving object is no occluder";
}

// A wall split into two clusters of one drawable (SceneObject::group): the halves merge as one
// polygon naming both clusters, while as two plain objects they stay two polygons of one owner each.
TEST(OccluderBuilder, ClustersOfOneDrawableMergeIntoOnePolygonNamingThemAll)
{
    const std::vector<Triangle> wall = tessellatedRectangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 0, 2), 4);
    const std::size_t half = wall.size() / 2; // cells i = 0, 1: the left half of the wall
    const std::vector<Triangle> left(wall.begin(), wall.begin() + long(half));
    const std::vector<Triangle> right(wall.begin() + long(half), wall.end());

    Scene plain;
    addObject(plain, left);
    addObject(plain, right);
    const std::vector<OccluderPolygon> apart = buildOccluderPolygons(plain);
    ASSERT_EQ(apart.size(), 2u);
    for (const OccluderPolygon& p : apart)
    {
        EXPECT_TRUE(p.parts.empty());
        EXPECT_NEAR(p.area, 4.0, 1e-9);
    }

    Scene clustered = plain;
    clustered.objects[0].group = 0;
    clustered.objects[1].group = 0;
    // a third, separate object keeps its own polygon
    const ObjectId lone = addObject(clustered, tessellatedRectangle(Vec3(0, 5, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), 1));
    const std::vector<OccluderPolygon> joined = buildOccluderPolygons(clustered);
    ASSERT_EQ(joined.size(), 2u);
    EXPECT_NEAR(joined[0].area, 8.0, 1e-9);
    EXPECT_EQ(joined[0].owner, 0u);
    EXPECT_EQ(joined[0].parts, (std::vector<ObjectId>{0, 1}));
    EXPECT_EQ(joined[1].owner, lone);
    EXPECT_TRUE(joined[1].parts.empty());

    // A polygon lying in one cluster only names no parts: its owner is that cluster.
    Scene oneSide;
    addObject(oneSide, left);
    addObject(oneSide, tessellatedRectangle(Vec3(0, 3, 0), Vec3(0, 2, 0), Vec3(0, 0, 2), 2)); // another plane
    oneSide.objects[0].group = oneSide.objects[1].group = 0;
    for (const OccluderPolygon& p : buildOccluderPolygons(oneSide))
        EXPECT_TRUE(p.parts.empty());
}
