// SPDX-License-Identifier: MIT
// Box-vs-occluder planes (Coorg & Teller): exact classifications of hand-made configurations,
// degenerate occluders, the silhouette-corner table against brute force, connected occluders,
// and a randomized cross-check against an independent segment-polygon test.
#include "AllocationCounter.h"

#include <osgVis/core/octree/BoxOcclusion.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>
#include <limits>
#include <new>
#include <random>

using namespace osgVis::core;

namespace
{
constexpr double Margin = 1e-6;
constexpr double Pi = 3.14159265358979323846;

// A polygon with its plane from Newell's normal (counter-clockwise around it) and no neighbours.
OccluderPolygon makePolygon(const std::vector<Vec3>& vertices, bool oneSided = false)
{
    OccluderPolygon polygon;
    polygon.vertices = vertices;
    Vec3 newell(0.0);
    for (std::size_t i = 0; i < vertices.size(); ++i)
        newell += glm::cross(vertices[i], vertices[(i + 1) % vertices.size()]);
    polygon.area = 0.5 * glm::length(newell);
    polygon.plane = Plane::fromPointNormal(vertices[0], newell);
    polygon.plane.normalize();
    Vec3 sum(0.0);
    for (const Vec3& v : vertices)
        sum += v;
    polygon.centroid = sum / double(vertices.size());
    polygon.neighbours.assign(vertices.size(), NoNeighbour);
    polygon.oneSided = oneSided;
    return polygon;
}

// The square [-2, 2]^2 in the plane z = 0, facing +z.
OccluderPolygon wall(bool oneSided = false)
{
    return makePolygon({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, oneSided);
}

const Vec3 eyeAbove(0, 0, 10);

// Independent of the code under test: does the open segment eye→q pass through the polygon
// (counter-clockwise, convex)? A one-sided polygon hides only from its front.
bool segmentCrossesPolygon(const std::vector<Vec3>& polygon, bool oneSided, const Vec3& eye, const Vec3& q)
{
    Vec3 normal(0.0);
    for (std::size_t i = 0; i < polygon.size(); ++i)
        normal += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    const double de = glm::dot(normal, eye - polygon[0]);
    const double dq = glm::dot(normal, q - polygon[0]);
    if (de == 0.0 || dq == 0.0 || (de > 0.0) == (dq > 0.0) || (oneSided && de < 0.0))
        return false;
    const Vec3 x = eye + (de / (de - dq)) * (q - eye);
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % polygon.size()];
        if (glm::dot(glm::cross(b - a, x - a), normal) < 0.0)
            return false;
    }
    return true;
}

// A grid of points on the box's six faces (corners and edges included).
std::vector<Vec3> surfaceSamples(const Aabb& box, int perSide = 5)
{
    std::vector<Vec3> samples;
    for (int axis = 0; axis < 3; ++axis)
    {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int face = 0; face < 2; ++face)
            for (int i = 0; i < perSide; ++i)
                for (int j = 0; j < perSide; ++j)
                {
                    Vec3 p;
                    p[axis] = face ? box.max[axis] : box.min[axis];
                    p[u] = box.min[u] + box.extent()[u] * i / (perSide - 1);
                    p[v] = box.min[v] + box.extent()[v] * j / (perSide - 1);
                    samples.push_back(p);
                }
    }
    return samples;
}

// How many of the box's surface samples the given polygons hide from the eye.
std::size_t hiddenSamples(const std::vector<const OccluderPolygon*>& polygons, const Aabb& box, const Vec3& eye,
                          std::size_t* total = nullptr)
{
    const std::vector<Vec3> samples = surfaceSamples(box);
    std::size_t hidden = 0;
    for (const Vec3& q : samples)
    {
        for (const OccluderPolygon* polygon : polygons)
        {
            if (segmentCrossesPolygon(polygon->vertices, polygon->oneSided, eye, q))
            {
                ++hidden;
                break;
            }
        }
    }
    if (total)
        *total = samples.size();
    return hidden;
}

bool usable(const BoxOccluderPlanes& planes)
{
    return !planes.separating.empty();
}

bool noPlanes(const BoxOccluderPlanes& planes)
{
    return planes.boxSide == 0 && planes.supporting.empty() && planes.separating.empty() &&
           planes.hasSeparating.empty();
}

std::vector<Vec3> eyeGrid()
{
    std::vector<Vec3> eyes;
    for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y)
            for (int z = -3; z <= 3; ++z)
                eyes.emplace_back(4.0 * x + 0.1, 4.0 * y - 0.2, 4.0 * z + 0.3);
    eyes.emplace_back(0, 0, 0);
    eyes.emplace_back(0, 0, 10);
    eyes.emplace_back(0, 0, -10);
    return eyes;
}
} // namespace

// ---------------------------------------------------------------------------------------------
// One occluder, hand-made configurations.

TEST(BoxOcclusion, WallBetweenEyeAndBoxHidesIt)
{
    const OccluderPolygon w = wall();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    BoxOccluderPlanes planes;
    computePlanes(w, box, planes);
    EXPECT_EQ(planes.boxSide, -1);
    ASSERT_EQ(planes.supporting.size(), 4u);
    ASSERT_EQ(planes.separating.size(), 4u);
    EXPECT_EQ(planes.hasSeparating, std::vector<std::uint8_t>(4, 1));
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Invisible);
    EXPECT_EQ(classifyBox(w, box, eyeAbove, Margin), Occlusion::Invisible);
    std::size_t total = 0;
    EXPECT_EQ(hiddenSamples({&w}, box, eyeAbove, &total), total);

    // The same from the other side (box in front of the normal, eye behind it).
    const Aabb boxAbove({-0.5, -0.5, 2}, {0.5, 0.5, 3});
    EXPECT_EQ(classifyBox(w, boxAbove, Vec3(0.3, -0.2, -10), Margin), Occlusion::Invisible);
}

TEST(BoxOcclusion, BoxBesideTheShadowIsVisible)
{
    const OccluderPolygon w = wall();
    const Aabb box({5, -0.5, -3}, {6, 0.5, -2}); // the shadow reaches x = 2.6 at z = -3
    EXPECT_EQ(classifyBox(w, box, eyeAbove, Margin), Occlusion::Visible);
    EXPECT_EQ(hiddenSamples({&w}, box, eyeAbove), 0u);
    // Between the eye and the wall: on the eye's side.
    EXPECT_EQ(classifyBox(w, Aabb({-0.5, -0.5, 2}, {0.5, 0.5, 3}), eyeAbove, Margin), Occlusion::Visible);
}

TEST(BoxOcclusion, BoxHalfInTheShadowIsPartial)
{
    const OccluderPolygon w = wall();
    const Aabb box({2, -0.5, -3}, {4, 0.5, -2});
    EXPECT_EQ(classifyBox(w, box, eyeAbove, Margin), Occlusion::Partial);
    std::size_t total = 0;
    const std::size_t hidden = hiddenSamples({&w}, box, eyeAbove, &total);
    EXPECT_GT(hidden, 0u);
    EXPECT_LT(hidden, total);
}

TEST(BoxOcclusion, BoxStraddlingThePlaneIsNeverInvisible)
{
    const OccluderPolygon w = wall();
    const Aabb box({-0.5, -0.5, -1}, {0.5, 0.5, 1});
    BoxOccluderPlanes planes;
    computePlanes(w, box, planes);
    EXPECT_EQ(planes.boxSide, 0);
    EXPECT_TRUE(planes.supporting.empty());
    // Seen along any edge, the box's section crosses the polygon's half-line: nothing separates.
    EXPECT_EQ(planes.hasSeparating, std::vector<std::uint8_t>(4, 0));
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Partial);
    for (const Vec3& eye : eyeGrid())
        EXPECT_NE(classify(w, planes, eye, Margin), Occlusion::Invisible) << eye.x << ' ' << eye.y << ' ' << eye.z;

    // Straddling beside the wall: a separating plane exists for the facing edge only.
    const Aabb beside({5, -0.5, -1}, {6, 0.5, 1});
    computePlanes(w, beside, planes);
    EXPECT_EQ(planes.boxSide, 0);
    EXPECT_EQ(planes.hasSeparating, (std::vector<std::uint8_t>{0, 1, 0, 0}));
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Visible);
    EXPECT_EQ(hiddenSamples({&w}, beside, eyeAbove), 0u);
    // Low above the wall the eye looks through it at the box's lower half.
    const Vec3 lowEye(0, 0, 0.5);
    EXPECT_EQ(classify(w, planes, lowEye, Margin), Occlusion::Partial);
    EXPECT_GT(hiddenSamples({&w}, beside, lowEye), 0u);
}

TEST(BoxOcclusion, BoxTouchingThePolygonsPlane)
{
    const OccluderPolygon w = wall();
    // Touching from behind, under the wall: never Invisible, although every ray crosses it.
    const Aabb under({-0.5, -0.5, -1}, {0.5, 0.5, 0});
    BoxOccluderPlanes planes;
    computePlanes(w, under, planes);
    EXPECT_EQ(planes.boxSide, 0);
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Partial);

    // Touching beside the wall: separated from eyes high above, not from eyes low above.
    const Aabb beside({5, -0.5, -1}, {6, 0.5, 0});
    computePlanes(w, beside, planes);
    EXPECT_EQ(planes.boxSide, 0);
    EXPECT_EQ(planes.hasSeparating[1], 1);
    EXPECT_NEAR(glm::length(planes.separating[1].normal), 1.0, 1e-12);
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Visible);
    EXPECT_EQ(classify(w, planes, Vec3(0, 0, 0.5), Margin), Occlusion::Partial);

    // A box just beyond the tolerance is behind the plane again.
    computePlanes(w, Aabb({-0.5, -0.5, -1}, {0.5, 0.5, -1e-6}), planes);
    EXPECT_EQ(planes.boxSide, -1);
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Invisible);
}

TEST(BoxOcclusion, EyeOnOrNearTheOccluderPlaneIsVisible)
{
    const OccluderPolygon w = wall();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    BoxOccluderPlanes planes;
    computePlanes(w, box, planes);
    EXPECT_EQ(classify(w, planes, Vec3(0, 0, 0), Margin), Occlusion::Visible);
    EXPECT_EQ(classify(w, planes, Vec3(5, 1, 0), Margin), Occlusion::Visible);
    EXPECT_EQ(classify(w, planes, Vec3(0, 0, 0.5 * Margin), Margin), Occlusion::Visible);
    EXPECT_EQ(classify(w, planes, Vec3(0, 0, 2 * Margin), Margin), Occlusion::Invisible);
}

TEST(BoxOcclusion, EyeWithinMarginOfASupportingPlaneIsNotInvisible)
{
    const OccluderPolygon w = wall();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    BoxOccluderPlanes planes;
    computePlanes(w, box, planes);
    ASSERT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Invisible);
    for (std::size_t i = 0; i < planes.supporting.size(); ++i)
    {
        const Plane& s = planes.supporting[i];
        const double distance = s.distance(eyeAbove);
        ASSERT_GT(distance, 1.0);
        for (const double target : {-Margin, 0.0, 0.5 * Margin, 0.99 * Margin})
        {
            const Vec3 eye = eyeAbove - (distance - target) * s.normal;
            ASSERT_NEAR(s.distance(eye), target, 1e-9);
            for (std::size_t j = 0; j < planes.supporting.size(); ++j)
            {
                if (j == i)
                    continue;
                ASSERT_GT(planes.supporting[j].distance(eye), 10 * Margin); // only plane i decides
            }
            EXPECT_NE(classify(w, planes, eye, Margin), Occlusion::Invisible) << i << ' ' << target;
        }
        const Vec3 clear = eyeAbove - (distance - 3 * Margin) * s.normal;
        EXPECT_EQ(classify(w, planes, clear, Margin), Occlusion::Invisible) << i;
    }
}

TEST(BoxOcclusion, OneSidedPolygonSeenFromBehindHidesNothing)
{
    const Aabb boxAbove({-0.5, -0.5, 2}, {0.5, 0.5, 3});
    const Vec3 eyeBelow(0, 0, -10);
    EXPECT_EQ(classifyBox(wall(true), boxAbove, eyeBelow, Margin), Occlusion::Visible);
    EXPECT_EQ(classifyBox(wall(false), boxAbove, eyeBelow, Margin), Occlusion::Invisible);
    // From its front the one-sided polygon hides as usual.
    EXPECT_EQ(classifyBox(wall(true), Aabb({-0.5, -0.5, -3}, {0.5, 0.5, -2}), eyeAbove, Margin), Occlusion::Invisible);
}

TEST(BoxOcclusion, PlanesAreUnitAndThroughTheEdge)
{
    const OccluderPolygon w = wall();
    BoxOccluderPlanes planes;
    computePlanes(w, Aabb({-0.5, -0.5, -3}, {0.5, 0.5, -2}), planes);
    for (std::size_t i = 0; i < 4; ++i)
    {
        for (const Plane* p : {&planes.supporting[i], &planes.separating[i]})
        {
            EXPECT_NEAR(glm::length(p->normal), 1.0, 1e-14);
            EXPECT_NEAR(p->distance(w.vertices[i]), 0.0, 1e-14);
            EXPECT_NEAR(p->distance(w.vertices[(i + 1) % 4]), 0.0, 1e-14);
        }
    }
    // Edge 0 runs along y = -2. In its section (x = y + 2 into the wall, y = -z towards the box)
    // the box's corners are (1.5, 2), (2.5, 2), (1.5, 3), (2.5, 3): the largest angle is at
    // (1.5, 3), the supporting plane's corner, the smallest at (2.5, 2), the separating one's.
    const Vec3 supportingNormal = glm::normalize(Vec3(0, 3, 1.5));
    const Vec3 separatingNormal = glm::normalize(Vec3(0, 2, 2.5));
    EXPECT_NEAR(glm::length(planes.supporting[0].normal - supportingNormal), 0.0, 1e-14);
    EXPECT_NEAR(glm::length(planes.separating[0].normal - separatingNormal), 0.0, 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Degenerate occluders: never Invisible, never a crash.

TEST(BoxOcclusionDegenerate, UnusablePolygonsGetNoPlanes)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<std::pair<const char*, OccluderPolygon>> cases;
    cases.emplace_back("empty", OccluderPolygon{});
    cases.emplace_back("two vertices", makePolygon({{-2, -2, 0}, {2, 2, 0}}));
    {
        OccluderPolygon point = wall();
        point.vertices.assign(4, Vec3(1, 1, 0));
        cases.emplace_back("zero area", point);
    }
    {
        OccluderPolygon line = wall();
        line.vertices = {{-2, 0, 0}, {0, 0, 0}, {2, 0, 0}};
        cases.emplace_back("collinear", line);
    }
    cases.emplace_back("repeated vertices", makePolygon({{-2, -2, 0}, {-2, -2, 0}, {2, 2, 0}}));
    cases.emplace_back("numerical sliver", makePolygon({{-2, 0, 0}, {2, 0, 0}, {2, 1e-9, 0}, {-2, 1e-9, 0}}));
    {
        OccluderPolygon p = wall();
        p.vertices[2].x = nan;
        cases.emplace_back("NaN vertex", p);
    }
    {
        OccluderPolygon p = wall();
        p.vertices[1].y = -inf;
        cases.emplace_back("infinite vertex", p);
    }
    {
        OccluderPolygon p = wall();
        p.plane.d = nan;
        cases.emplace_back("NaN plane", p);
    }
    {
        OccluderPolygon p = wall();
        p.plane.normal = Vec3(0, 0, 2);
        cases.emplace_back("non-unit normal", p);
    }
    {
        OccluderPolygon p = wall();
        p.plane = Plane(Vec3(0, 0, 1), -1); // z = 1, the vertices lie at z = 0
        cases.emplace_back("vertices off the plane", p);
    }
    {
        OccluderPolygon p = wall();
        p.vertices = {p.vertices[3], p.vertices[2], p.vertices[1], p.vertices[0]};
        cases.emplace_back("clockwise", p);
    }
    {
        OccluderPolygon p = wall();
        p.vertices = {{-2, -2, 0}, {2, -2, 0}, {0, -1, 0}, {2, 2, 0}, {-2, 2, 0}}; // a notch
        p.neighbours.assign(5, NoNeighbour);
        cases.emplace_back("not convex", p);
    }
    {
        OccluderPolygon p = wall();
        p.vertices[2] += Vec3(1e-13, 0, 0); // nearly coincident with a copy inserted next
        p.vertices.insert(p.vertices.begin() + 3, wall().vertices[2]);
        p.neighbours.assign(5, NoNeighbour);
        cases.emplace_back("nearly coincident vertices", p);
    }

    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    for (const auto& [name, polygon] : cases)
    {
        BoxOccluderPlanes planes;
        computePlanes(polygon, box, planes);
        EXPECT_TRUE(noPlanes(planes)) << name;
        for (const Vec3& eye : eyeGrid())
            EXPECT_NE(classify(polygon, planes, eye, Margin), Occlusion::Invisible) << name;
        EXPECT_FALSE(fusedInvisible({polygon}, {0}, {planes}, eyeAbove, Margin)) << name;
    }
}

TEST(BoxOcclusionDegenerate, BadBoxesAndEyesGetNoDecision)
{
    const OccluderPolygon w = wall();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    BoxOccluderPlanes planes;
    computePlanes(w, Aabb(), planes); // empty
    EXPECT_TRUE(noPlanes(planes));
    computePlanes(w, Aabb({-0.5, -0.5, -3}, {0.5, nan, -2}), planes);
    EXPECT_TRUE(noPlanes(planes));
    EXPECT_NE(classify(w, planes, eyeAbove, Margin), Occlusion::Invisible);

    computePlanes(w, Aabb({-0.5, -0.5, -3}, {0.5, 0.5, -2}), planes);
    EXPECT_EQ(classify(w, planes, Vec3(0, nan, 10), Margin), Occlusion::Visible);
    EXPECT_EQ(classify(w, planes, Vec3(0, 0, std::numeric_limits<double>::infinity()), Margin), Occlusion::Visible);
    EXPECT_EQ(classify(w, planes, eyeAbove, nan), Occlusion::Invisible); // NaN margin counts as 0
    // Planes of another polygon (edge count differs) never give Invisible.
    const OccluderPolygon triangle = makePolygon({{-2, -2, 0}, {2, -2, 0}, {0, 3, 0}});
    EXPECT_NE(classify(triangle, planes, eyeAbove, Margin), Occlusion::Invisible);
}

TEST(BoxOcclusionDegenerate, RepeatedVertexIsSkipped)
{
    OccluderPolygon w = wall();
    w.vertices.insert(w.vertices.begin() + 2, w.vertices[2]); // (2, 2, 0) twice
    w.neighbours.assign(5, NoNeighbour);
    BoxOccluderPlanes planes;
    computePlanes(w, Aabb({-0.5, -0.5, -3}, {0.5, 0.5, -2}), planes);
    ASSERT_EQ(planes.supporting.size(), 5u);
    EXPECT_EQ(planes.supporting[2].normal, Vec3(0.0));
    EXPECT_EQ(planes.hasSeparating, (std::vector<std::uint8_t>{1, 1, 0, 1, 1}));
    EXPECT_EQ(classify(w, planes, eyeAbove, Margin), Occlusion::Invisible);
    EXPECT_EQ(classifyBox(w, Aabb({2, -0.5, -3}, {4, 0.5, -2}), eyeAbove, Margin), Occlusion::Partial);
    EXPECT_EQ(classifyBox(w, Aabb({5, -0.5, -3}, {6, 0.5, -2}), eyeAbove, Margin), Occlusion::Visible);
}

TEST(BoxOcclusionDegenerate, SliverThinnerThanTheBoxDoesNotHideIt)
{
    const OccluderPolygon sliver = makePolygon({{-5, -0.01, 0}, {5, -0.01, 0}, {5, 0.01, 0}, {-5, 0.01, 0}});
    const Aabb box({-0.5, -0.5, -1.5}, {0.5, 0.5, -0.5});
    BoxOccluderPlanes planes;
    computePlanes(sliver, box, planes);
    EXPECT_EQ(planes.boxSide, -1);
    for (const Vec3& eye : eyeGrid())
        EXPECT_NE(classify(sliver, planes, eye, Margin), Occlusion::Invisible);
    EXPECT_EQ(classify(sliver, planes, eyeAbove, Margin), Occlusion::Partial);
}

// ---------------------------------------------------------------------------------------------
// The silhouette-corner table.

TEST(BoxOcclusionSilhouette, CountsAndExcludedCorners)
{
    const Aabb unit({0, 0, 0}, {1, 1, 1});
    for (int sz = -1; sz <= 1; ++sz)
        for (int sy = -1; sy <= 1; ++sy)
            for (int sx = -1; sx <= 1; ++sx)
            {
                const Vec3 u(sx, sy, sz);
                int corners[8];
                const int count = silhouetteCorners(u, corners);
                const int zeros = (sx == 0) + (sy == 0) + (sz == 0);
                EXPECT_EQ(count, zeros == 0 ? 6 : zeros == 3 ? 8 : 4) << sx << sy << sz;
                // No corner extreme along +-u (for an axis direction: one of each coinciding pair).
                double lo = 1e9, hi = -1e9;
                for (int c = 0; c < 8; ++c)
                {
                    lo = std::min(lo, glm::dot(u, unit.corner(c)));
                    hi = std::max(hi, glm::dot(u, unit.corner(c)));
                }
                for (int k = 0; k < count; ++k)
                {
                    ASSERT_GE(corners[k], 0);
                    ASSERT_LT(corners[k], 8);
                    if (zeros < 2)
                    {
                        EXPECT_GT(glm::dot(u, unit.corner(corners[k])), lo);
                        EXPECT_LT(glm::dot(u, unit.corner(corners[k])), hi);
                    }
                    for (int m = 0; m < k; ++m)
                        EXPECT_NE(corners[k], corners[m]);
                }
            }
}

namespace
{
struct SectionPoint
{
    double x, y;
};

// Index into `points` of the largest (or smallest) angle; all points have y > 0.
int extremeAngle(const std::vector<SectionPoint>& points, bool largest)
{
    int best = 0;
    for (int k = 1; k < int(points.size()); ++k)
    {
        const double cross = points[best].x * points[k].y - points[best].y * points[k].x;
        if (largest ? cross > 0.0 : cross < 0.0)
            best = k;
    }
    return best;
}
} // namespace

TEST(BoxOcclusionSilhouette, TableChoosesTheSamePlanesAsAllEightCorners)
{
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int compared = 0, withZeroComponent = 0;
    for (int trial = 0; trial < 20000; ++trial)
    {
        Vec3 u(unit(random), unit(random), unit(random));
        const int zeroed = trial % 4; // some directions lie in coordinate planes or along axes
        if (zeroed == 1)
            u[trial % 3] = 0.0;
        if (zeroed == 2)
            u[trial % 3] = u[(trial + 1) % 3] = 0.0;
        if (glm::length(u) < 0.1)
            continue;
        u = glm::normalize(u);
        Vec3 a = glm::cross(u, Vec3(unit(random), unit(random), unit(random)));
        if (glm::length(a) < 0.1)
            continue;
        a = glm::normalize(a);
        Vec3 b = glm::cross(u, a);
        const Vec3 origin(3 * unit(random), 3 * unit(random), 3 * unit(random));
        const Vec3 lo(3 * unit(random), 3 * unit(random), 3 * unit(random));
        const Aabb box(lo, lo + Vec3(1 + unit(random), 1 + unit(random), 1 + unit(random)));

        std::vector<SectionPoint> all;
        for (int c = 0; c < 8; ++c)
            all.push_back({glm::dot(box.corner(c) - origin, a), glm::dot(box.corner(c) - origin, b)});
        bool allPositive = true, allNegative = true;
        for (const SectionPoint& p : all)
        {
            allPositive = allPositive && p.y > 1e-3;
            allNegative = allNegative && p.y < -1e-3;
        }
        if (!allPositive && !allNegative)
            continue;
        if (allNegative)
            for (SectionPoint& p : all)
                p.y = -p.y;

        int corners[8];
        const int count = silhouetteCorners(u, corners);
        std::vector<SectionPoint> chosen;
        for (int k = 0; k < count; ++k)
            chosen.push_back(all[corners[k]]);
        for (const bool largest : {true, false})
        {
            const SectionPoint& viaTable = chosen[extremeAngle(chosen, largest)];
            const SectionPoint& viaAll = all[extremeAngle(all, largest)];
            // Same plane of the pencil: the two section points are parallel.
            const double cross = viaTable.x * viaAll.y - viaTable.y * viaAll.x;
            ASSERT_NEAR(cross / (std::hypot(viaTable.x, viaTable.y) * std::hypot(viaAll.x, viaAll.y)), 0.0, 1e-12)
                << "trial " << trial;
        }
        ++compared;
        withZeroComponent += zeroed == 1 || zeroed == 2;
    }
    EXPECT_GT(compared, 5000);
    EXPECT_GT(withZeroComponent, 2000);
}

// Every computed plane is the extreme one of its pencil: unit, through the edge, the polygon on
// its positive side and the box on the stated side, touching the box.
TEST(BoxOcclusionSilhouette, ComputedPlanesAreTheTangentsOfThePencil)
{
    std::mt19937 random(777);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const Vec3 normal = glm::normalize(Vec3(unit(random), unit(random), unit(random)) + Vec3(0, 0, 1e-3));
        const Vec3 e1 = glm::normalize(glm::cross(normal, Vec3(unit(random), unit(random), unit(random))));
        const Vec3 e2 = glm::cross(normal, e1);
        const Vec3 center(4 * unit(random), 4 * unit(random), 4 * unit(random));
        std::vector<double> angles;
        const int count = 3 + trial % 6;
        for (int k = 0; k < count; ++k)
            angles.push_back(Pi * (unit(random) + 1.0));
        std::sort(angles.begin(), angles.end());
        std::vector<Vec3> vertices;
        for (const double angle : angles)
            vertices.push_back(center + 2.0 * std::cos(angle) * e1 + 1.3 * std::sin(angle) * e2);
        const OccluderPolygon polygon = makePolygon(vertices);
        const Vec3 lo = center + Vec3(3 * unit(random), 3 * unit(random), 3 * unit(random));
        const Aabb box(lo, lo + Vec3(1.0 + unit(random), 1.0 + unit(random), 1.0 + unit(random)));

        BoxOccluderPlanes planes;
        computePlanes(polygon, box, planes);
        if (!usable(planes))
            continue;
        ASSERT_EQ(planes.separating.size(), vertices.size());
        const double tolerance = 1e-9;
        for (std::size_t i = 0; i < vertices.size(); ++i)
        {
            const auto check = [&](const Plane& plane, int boxSign)
            {
                ASSERT_NEAR(glm::length(plane.normal), 1.0, 1e-12);
                ASSERT_NEAR(plane.distance(vertices[i]), 0.0, tolerance);
                ASSERT_NEAR(plane.distance(vertices[(i + 1) % vertices.size()]), 0.0, tolerance);
                for (const Vec3& v : vertices)
                    ASSERT_GT(plane.distance(v), -tolerance);
                double nearest = 1e9;
                for (int c = 0; c < 8; ++c)
                {
                    const double distance = boxSign * plane.distance(box.corner(c));
                    ASSERT_GT(distance, -tolerance) << "trial " << trial << " edge " << i;
                    nearest = std::min(nearest, distance);
                }
                ASSERT_LT(nearest, tolerance);
            };
            if (planes.boxSide != 0)
                check(planes.supporting[i], 1);
            if (planes.hasSeparating[i])
                check(planes.separating[i], -1);
            else
                ASSERT_EQ(planes.boxSide, 0);
        }
        ++checked;
    }
    EXPECT_GT(checked, 2000);
}

// ---------------------------------------------------------------------------------------------
// Connected occluders.

namespace
{
// The wall split along its diagonal: triangle 0 below it, triangle 1 above, sharing the edge
// (2, 2) → (-2, -2) of triangle 0, which is (-2, -2) → (2, 2) in triangle 1.
std::vector<OccluderPolygon> splitSquare()
{
    std::vector<OccluderPolygon> polygons{makePolygon({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}}),
                                          makePolygon({{-2, -2, 0}, {2, 2, 0}, {-2, 2, 0}})};
    polygons[0].neighbours[2] = 1;
    polygons[1].neighbours[0] = 0;
    return polygons;
}

std::vector<BoxOccluderPlanes> planesFor(const std::vector<OccluderPolygon>& polygons,
                                         const std::vector<std::uint32_t>& active, const Aabb& box)
{
    std::vector<BoxOccluderPlanes> planes(active.size());
    for (std::size_t j = 0; j < active.size(); ++j)
        computePlanes(polygons[active[j]], box, planes[j]);
    return planes;
}

bool fused(const std::vector<OccluderPolygon>& polygons, const std::vector<std::uint32_t>& active, const Aabb& box,
           const Vec3& eye)
{
    return fusedInvisible(polygons, active, planesFor(polygons, active, box), eye, Margin);
}

// Two walls meeting along the y axis in a V opening towards +z: A over x in [-2, 0] on the
// plane z = -x/2, B over x in [0, 2] on z = x/2, both facing up. The crease is A's edge 1 and
// B's edge 3.
std::vector<OccluderPolygon> crease()
{
    std::vector<OccluderPolygon> polygons{makePolygon({{-2, -2, 1}, {0, -2, 0}, {0, 2, 0}, {-2, 2, 1}}),
                                          makePolygon({{0, -2, 0}, {2, -2, 1}, {2, 2, 1}, {0, 2, 0}})};
    polygons[0].neighbours[1] = 1;
    polygons[1].neighbours[3] = 0;
    return polygons;
}
} // namespace

TEST(BoxOcclusionFused, TwoTrianglesHideWhatNeitherHidesAlone)
{
    const std::vector<OccluderPolygon> polygons = splitSquare();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    EXPECT_EQ(classifyBox(polygons[0], box, eyeAbove, Margin), Occlusion::Partial);
    EXPECT_EQ(classifyBox(polygons[1], box, eyeAbove, Margin), Occlusion::Partial);
    EXPECT_TRUE(fused(polygons, {0, 1}, box, eyeAbove));
    EXPECT_TRUE(fused(polygons, {1, 0}, box, eyeAbove));
    std::size_t total = 0;
    EXPECT_EQ(hiddenSamples({&polygons[0], &polygons[1]}, box, eyeAbove, &total), total);
    // Not beyond the union's outline.
    EXPECT_FALSE(fused(polygons, {0, 1}, Aabb({2, -0.5, -3}, {4, 0.5, -2}), eyeAbove));
    // Nor from an eye within the margin of their common plane.
    EXPECT_FALSE(fused(polygons, {0, 1}, box, Vec3(0, 0, 0.5 * Margin)));
    // Nor with the box on the eye's side.
    EXPECT_FALSE(fused(polygons, {0, 1}, box, Vec3(0, 0, -10)));
}

TEST(BoxOcclusionFused, NeighbourNotActiveHasItsSharedEdgeTested)
{
    const std::vector<OccluderPolygon> polygons = splitSquare();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    EXPECT_FALSE(fused(polygons, {0}, box, eyeAbove));
    EXPECT_FALSE(fused(polygons, {1}, box, eyeAbove));
    // A box inside triangle 0's own shadow is hidden by it alone, shared edge tested or not.
    const Aabb inCorner({1.0, -1.5, -1.2}, {1.5, -1.0, -1.0});
    EXPECT_EQ(classifyBox(polygons[0], inCorner, eyeAbove, Margin), Occlusion::Invisible);
    EXPECT_TRUE(fused(polygons, {0}, inCorner, eyeAbove));
    EXPECT_TRUE(fused(polygons, {0, 1}, inCorner, eyeAbove));
}

TEST(BoxOcclusionFused, NeighbourLinkWithoutASharedEdgeIsTested)
{
    // Triangle 0 claims triangle 1 across its bottom edge, which triangle 1 does not have.
    std::vector<OccluderPolygon> polygons = splitSquare();
    polygons[0].neighbours[0] = 1;
    // The box's shadow crosses only that bottom edge (and the real, shared diagonal).
    const Aabb box({-0.5, -2.5, -3}, {0.5, -1.5, -2});
    EXPECT_GT(hiddenSamples({&polygons[0], &polygons[1]}, box, eyeAbove), 0u);
    std::size_t total = 0;
    EXPECT_LT(hiddenSamples({&polygons[0], &polygons[1]}, box, eyeAbove, &total), total);
    EXPECT_FALSE(fused(polygons, {0, 1}, box, eyeAbove));
    // The same shared edge traversed the same way in both (inconsistent orientation) is tested too.
    std::vector<OccluderPolygon> flipped = splitSquare();
    flipped[1] = makePolygon({{2, 2, 0}, {-2, -2, 0}, {-2, 2, 0}}); // clockwise around +z
    flipped[1].neighbours[0] = 0;
    const Aabb middle({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    EXPECT_FALSE(fused(flipped, {0, 1}, middle, eyeAbove));
}

TEST(BoxOcclusionFused, LShapeDoesNotHideTheNotch)
{
    // Squares [0,1]x[0,1] (0), [1,2]x[0,1] (1), [0,1]x[1,2] (2) in z = 0; the notch is [1,2]x[1,2].
    std::vector<OccluderPolygon> polygons{makePolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}),
                                          makePolygon({{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}),
                                          makePolygon({{0, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}})};
    polygons[0].neighbours = {NoNeighbour, 1, 2, NoNeighbour};
    polygons[1].neighbours = {NoNeighbour, NoNeighbour, NoNeighbour, 0};
    polygons[2].neighbours = {0, NoNeighbour, NoNeighbour, NoNeighbour};
    const std::vector<std::uint32_t> all{0, 1, 2};

    const Vec3 overNotch(1.5, 1.5, 10);
    const Aabb behindNotch({1.2, 1.2, -2}, {1.8, 1.8, -1.5});
    EXPECT_FALSE(fused(polygons, all, behindNotch, overNotch));
    EXPECT_EQ(hiddenSamples({&polygons[0], &polygons[1], &polygons[2]}, behindNotch, overNotch), 0u);

    // Around the reflex corner: inside the L's convex hull, partly behind the notch.
    const Vec3 overCorner(1, 1, 10);
    const Aabb aroundCorner({0.8, 0.8, -0.6}, {1.2, 1.2, -0.5});
    EXPECT_FALSE(fused(polygons, all, aroundCorner, overCorner));

    // Across squares 0 and 1 only: hidden by the union, not by either square.
    const Vec3 overEdge(1, 0.5, 10);
    const Aabb acrossEdge({0.7, 0.3, -0.6}, {1.3, 0.7, -0.5});
    EXPECT_EQ(classifyBox(polygons[0], acrossEdge, overEdge, Margin), Occlusion::Partial);
    EXPECT_EQ(classifyBox(polygons[1], acrossEdge, overEdge, Margin), Occlusion::Partial);
    EXPECT_TRUE(fused(polygons, {0, 1}, acrossEdge, overEdge));
    EXPECT_FALSE(fused(polygons, {0}, acrossEdge, overEdge));
}

TEST(BoxOcclusionFused, CreaseSeenFromTheFrontOfBothHides)
{
    const std::vector<OccluderPolygon> polygons = crease();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    EXPECT_EQ(classifyBox(polygons[0], box, eyeAbove, Margin), Occlusion::Partial);
    EXPECT_EQ(classifyBox(polygons[1], box, eyeAbove, Margin), Occlusion::Partial);
    EXPECT_TRUE(fused(polygons, {0, 1}, box, eyeAbove));
    std::size_t total = 0;
    EXPECT_EQ(hiddenSamples({&polygons[0], &polygons[1]}, box, eyeAbove, &total), total);
}

TEST(BoxOcclusionFused, CreaseOnTheSilhouetteIsTested)
{
    // Far to the right and low: in front of A, behind B, so the crease is a fold of the outline.
    const std::vector<OccluderPolygon> polygons = crease();
    const Vec3 eye(10, 0, 1);
    ASSERT_GT(polygons[0].plane.distance(eye), 1.0);
    ASSERT_LT(polygons[1].plane.distance(eye), -1.0);
    // Under A and above B's extension: behind both planes from the eye; rays to its lower part
    // pass below the crease and meet neither wall.
    const Aabb box({-1.2, -0.5, -0.3}, {-0.8, 0.5, 0.2});
    const std::vector<std::uint32_t> active{0, 1};
    const std::vector<BoxOccluderPlanes> planes = planesFor(polygons, active, box);
    ASSERT_EQ(planes[0].boxSide, -1);
    ASSERT_EQ(planes[1].boxSide, 1);
    // Only the crease edges (A's 1, B's 3) have the eye off their supporting plane's inner side:
    // skipping them would wrongly answer true.
    for (std::size_t j = 0; j < 2; ++j)
        for (std::size_t i = 0; i < 4; ++i)
        {
            const bool creaseEdge = (j == 0 && i == 1) || (j == 1 && i == 3);
            EXPECT_EQ(planes[j].supporting[i].distance(eye) > Margin, !creaseEdge) << j << ' ' << i;
        }
    EXPECT_FALSE(fusedInvisible(polygons, active, planes, eye, Margin));
    std::size_t total = 0;
    const std::size_t hidden = hiddenSamples({&polygons[0], &polygons[1]}, box, eye, &total);
    EXPECT_GT(hidden, 0u);
    EXPECT_LT(hidden, total);
}

TEST(BoxOcclusionFused, OneSidedSeenFromBehindOrEdgeOnFails)
{
    std::vector<OccluderPolygon> polygons = splitSquare();
    const Aabb boxAbove({-0.5, -0.5, 2}, {0.5, 0.5, 3});
    const Vec3 eyeBelow(0, 0, -10);
    EXPECT_TRUE(fused(polygons, {0, 1}, boxAbove, eyeBelow));
    polygons[1].oneSided = true;
    EXPECT_FALSE(fused(polygons, {0, 1}, boxAbove, eyeBelow));
    // Planes missing or for the wrong polygons.
    EXPECT_FALSE(fusedInvisible(polygons, {0, 1}, {}, eyeBelow, Margin));
    EXPECT_FALSE(fusedInvisible(polygons, {}, {}, eyeBelow, Margin));
    EXPECT_FALSE(fusedInvisible(polygons, {0, 7}, planesFor(polygons, {0, 0}, boxAbove), eyeBelow, Margin));
}

// ---------------------------------------------------------------------------------------------
// classify and fusedInvisible allocate nothing.

TEST(BoxOcclusion, ClassifyAndFusedAllocateNothing)
{
    const std::vector<OccluderPolygon> polygons = splitSquare();
    const Aabb box({-0.5, -0.5, -3}, {0.5, 0.5, -2});
    const std::vector<std::uint32_t> active{0, 1};
    const std::vector<BoxOccluderPlanes> planes = planesFor(polygons, active, box);
    BoxOccluderPlanes reused = planes[0];
    PreparedOccluder prepared;
    prepareOccluder(polygons[1], prepared);
    int invisible = 0, fusedCount = 0;
    const std::size_t before = osgVis::test::allocationCount();
    for (int k = 0; k < 1000; ++k)
    {
        const Vec3 eye(0.001 * k, -0.002 * k, 10.0 - 0.01 * k);
        invisible += classify(polygons[0], planes[0], eye, Margin) == Occlusion::Invisible;
        fusedCount += fusedInvisible(polygons, active, planes, eye, Margin);
        computePlanes(prepared, box, reused); // reuses the vectors' capacity
    }
    EXPECT_EQ(osgVis::test::allocationCount() - before, 0u);
    EXPECT_GT(fusedCount, 0);
    EXPECT_GT(invisible, 0); // low eyes far off-centre see the box through triangle 0 alone
}

// ---------------------------------------------------------------------------------------------
// Randomized cross-check against the independent segment-polygon test.

namespace
{
struct RandomScene
{
    std::mt19937 random{20240611};
    std::uniform_real_distribution<double> unit{-1.0, 1.0};
    std::uniform_real_distribution<double> zeroOne{0.0, 1.0};

    Vec3 vec(double scale) { return scale * Vec3(unit(random), unit(random), unit(random)); }

    // A convex polygon: points at sorted random angles on an ellipse in a random plane.
    std::vector<Vec3> convexPolygon(const Vec3& center, const Vec3& normal)
    {
        const Vec3 e1 = glm::normalize(glm::cross(normal, glm::normalize(vec(1.0) + Vec3(1e-3, 0, 0))));
        const Vec3 e2 = glm::cross(normal, e1);
        const double r1 = 0.5 + 2.5 * zeroOne(random), r2 = 0.5 + 2.5 * zeroOne(random);
        const int count = 3 + int(6 * zeroOne(random));
        std::vector<double> angles;
        for (int k = 0; k < count; ++k)
            angles.push_back(2.0 * Pi * zeroOne(random));
        std::sort(angles.begin(), angles.end());
        std::vector<Vec3> vertices;
        for (const double angle : angles)
            vertices.push_back(center + r1 * std::cos(angle) * e1 + r2 * std::sin(angle) * e2);
        return vertices;
    }

    // An eye clear of every polygon's plane, and a box around a point seen through a random
    // point of one of them (or anywhere).
    Vec3 eye(const std::vector<const OccluderPolygon*>& polygons)
    {
        for (;;)
        {
            const Vec3 e = vec(15.0);
            bool clear = true;
            for (const OccluderPolygon* p : polygons)
                clear = clear && std::abs(p->plane.distance(e)) > 1e-3;
            if (clear)
                return e;
        }
    }

    Aabb box(const OccluderPolygon& through, const Vec3& eye)
    {
        const std::vector<Vec3>& v = through.vertices;
        const double s = zeroOne(random);
        return boxBehind((1 - s) * through.centroid + s * v[std::size_t(zeroOne(random) * v.size())], eye, 1.2);
    }

    // Mostly a box seen through `point` from beyond it, sometimes anywhere; half-sizes up to
    // `size`.
    Aabb boxBehind(const Vec3& point, const Vec3& eye, double size)
    {
        Vec3 center = vec(10.0);
        if (zeroOne(random) < 0.85)
            center = eye + (1.05 + 2.0 * zeroOne(random)) * (point - eye) + vec(0.3);
        const Vec3 half = Vec3(0.02) + size * Vec3(zeroOne(random), zeroOne(random), zeroOne(random));
        return Aabb(center - half, center + half);
    }
};
} // namespace

TEST(BoxOcclusionRandom, ClassifyAgreesWithRayCasting)
{
    RandomScene scene;
    int invisible = 0, visible = 0, partial = 0, partialAllHidden = 0, partialNoneHidden = 0, unusable = 0;
    BoxOccluderPlanes planes;
    for (int trial = 0; trial < 4000; ++trial)
    {
        const Vec3 normal = glm::normalize(scene.vec(1.0) + Vec3(0, 0, 1e-3));
        OccluderPolygon polygon = makePolygon(scene.convexPolygon(scene.vec(5.0), normal), trial % 5 == 0);
        const Vec3 eye = scene.eye({&polygon});
        const Aabb box = scene.box(polygon, eye);
        computePlanes(polygon, box, planes);
        unusable += !usable(planes);
        const Occlusion result = classify(polygon, planes, eye, Margin);
        std::size_t total = 0;
        const std::size_t hidden = hiddenSamples({&polygon}, box, eye, &total);
        if (result == Occlusion::Invisible)
        {
            ++invisible;
            ASSERT_EQ(hidden, total) << "trial " << trial;
        }
        else if (result == Occlusion::Visible)
        {
            ++visible;
            ASSERT_EQ(hidden, 0u) << "trial " << trial;
        }
        else
        {
            ++partial;
            partialAllHidden += hidden == total;
            partialNoneHidden += hidden == 0;
        }
    }
    std::printf("classify: %d Invisible, %d Visible, %d Partial (all samples hidden %d, none %d); "
                "%d with no planes\n",
                invisible, visible, partial, partialAllHidden, partialNoneHidden, unusable);
    EXPECT_GT(invisible, 200);
    EXPECT_GT(visible, 200);
    EXPECT_GT(partial, 200);
}

TEST(BoxOcclusionRandom, FusedPairsAgreeWithRayCasting)
{
    RandomScene scene;
    int fusedTrue = 0, fusedOnly = 0, fusedFalse = 0;
    for (int trial = 0; trial < 4000; ++trial)
    {
        // A: a random convex polygon. B: a trapezoid on the far side of A's edge i, folded about
        // that edge's line by a random angle; it traverses the shared edge the other way round.
        const Vec3 normal = glm::normalize(scene.vec(1.0) + Vec3(0, 0, 1e-3));
        std::vector<OccluderPolygon> polygons{makePolygon(scene.convexPolygon(scene.vec(5.0), normal))};
        const OccluderPolygon& a = polygons[0];
        const std::size_t i = std::size_t(scene.zeroOne(scene.random) * a.vertices.size());
        const Vec3 start = a.vertices[i], end = a.vertices[(i + 1) % a.vertices.size()];
        const double length = glm::length(end - start);
        if (length < 0.2)
            continue;
        const Vec3 along = (end - start) / length;
        const Vec3 outward = -glm::cross(a.plane.normal, along);
        const double fold = 2.4 * scene.unit(scene.random);
        const Vec3 away = std::cos(fold) * outward + std::sin(fold) * a.plane.normal;
        const double depth = 0.3 + 2.0 * scene.zeroOne(scene.random);
        const double shiftStart = 0.4 * length * scene.unit(scene.random);
        const double shiftEnd = 0.4 * length * scene.unit(scene.random);
        polygons.push_back(
            makePolygon({end, start, start + depth * away + shiftStart * along, end + depth * away + shiftEnd * along},
                        trial % 7 == 0));
        polygons[0].neighbours[i] = 1;
        polygons[1].neighbours[0] = 0;

        const Vec3 eye = scene.eye({&polygons[0], &polygons[1]});
        // Half of the boxes are seen across the shared edge, where only the pair can hide them.
        const double t = 0.2 + 0.6 * scene.zeroOne(scene.random);
        const Aabb box =
            trial % 2 ? scene.box(polygons[trial % 4 / 2], eye) : scene.boxBehind((1 - t) * start + t * end, eye, 0.5);
        const std::vector<std::uint32_t> active{0, 1};
        const std::vector<BoxOccluderPlanes> planes = planesFor(polygons, active, box);
        const bool result = fusedInvisible(polygons, active, planes, eye, Margin);

        // Alone, fusedInvisible is exactly classify's Invisible.
        for (std::uint32_t j = 0; j < 2; ++j)
            ASSERT_EQ(fusedInvisible(polygons, {j}, {planes[j]}, eye, Margin),
                      classify(polygons[j], planes[j], eye, Margin) == Occlusion::Invisible)
                << "trial " << trial;

        std::size_t total = 0;
        const std::size_t hidden = hiddenSamples({&polygons[0], &polygons[1]}, box, eye, &total);
        if (result)
        {
            ++fusedTrue;
            ASSERT_EQ(hidden, total) << "trial " << trial;
            fusedOnly += classify(polygons[0], planes[0], eye, Margin) != Occlusion::Invisible &&
                         classify(polygons[1], planes[1], eye, Margin) != Occlusion::Invisible;
        }
        else
            ++fusedFalse;
    }
    std::printf("fused: %d true (%d hidden by neither polygon alone), %d false\n", fusedTrue, fusedOnly, fusedFalse);
    EXPECT_GT(fusedTrue, 200);
    EXPECT_GT(fusedOnly, 100);
    EXPECT_GT(fusedFalse, 1000);
}

// ---------------------------------------------------------------------------------------------
// A volume of eyes (regions of viewpoints): a decision for the box of eyes holds for each of its
// eyes, and the volume decides exactly like a point when it shrinks to one.

TEST(EyeVolume, HiddenForTheVolumeIsHiddenForEveryEyeInIt)
{
    std::mt19937 random(4242);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), size(0.0, 1.5);
    const OccluderPolygon polygon = wall();
    int hidden = 0, visible = 0, partial = 0;
    for (int trial = 0; trial < 4000; ++trial)
    {
        const Vec3 lo(3 * unit(random), 3 * unit(random), -6 + 2 * unit(random));
        const Aabb box(lo, lo + Vec3(0.2 + size(random), 0.2 + size(random), 0.2 + size(random)));
        const EyeVolume eyes{Vec3(4 * unit(random), 4 * unit(random), 4 + 3 * unit(random)),
                             Vec3(size(random), size(random), size(random))};
        BoxOccluderPlanes planes;
        computePlanes(polygon, box, planes);
        const Occlusion forVolume = classify(polygon, planes, eyes, Margin);
        EXPECT_EQ(classify(polygon, planes, EyeVolume{eyes.center, Vec3(0.0)}, Margin),
                  classify(polygon, planes, eyes.center, Margin));
        (forVolume == Occlusion::Invisible ? hidden : forVolume == Occlusion::Visible ? visible : partial)++;
        if (forVolume != Occlusion::Invisible)
            continue;
        for (int k = 0; k < 16; ++k)
        {
            // Corners first, then random points of the volume.
            const Vec3 pick = k < 8 ? Vec3((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0)
                                    : Vec3(unit(random), unit(random), unit(random));
            const Vec3 eye = eyes.center + pick * eyes.halfExtent;
            ASSERT_EQ(classify(polygon, planes, eye, Margin), Occlusion::Invisible) << "trial " << trial << " eye " << k;
            for (int c = 0; c < 8; ++c)
                ASSERT_TRUE(segmentCrossesPolygon(polygon.vertices, false, eye, box.corner(c)));
        }
    }
    // Every outcome occurs, so the check above is not vacuous.
    EXPECT_GT(hidden, 100);
    EXPECT_GT(visible, 100);
    EXPECT_GT(partial, 100);
}

TEST(EyeVolume, FusedOccludersHideFromEveryEyeOnlyWhenTheVolumeClearsTheSilhouette)
{
    const std::vector<OccluderPolygon> polygons = splitSquare();
    const std::vector<std::uint32_t> active{0, 1};
    const Aabb box(Vec3(-1.9, -1.9, -3), Vec3(1.9, 1.9, -2)); // behind the seam of the square
    std::vector<BoxOccluderPlanes> planes(2);
    computePlanes(polygons[0], box, planes[0]);
    computePlanes(polygons[1], box, planes[1]);
    EXPECT_TRUE(fusedInvisible(polygons, active, planes, EyeVolume{Vec3(0, 0, 5), Vec3(0.1)}, Margin));
    // Eyes far to the side see past the square's edge.
    EXPECT_FALSE(fusedInvisible(polygons, active, planes, EyeVolume{Vec3(0, 0, 5), Vec3(4, 0.1, 0.1)}, Margin));
    // A volume reaching through the plane is on both sides of it.
    EXPECT_FALSE(fusedInvisible(polygons, active, planes, EyeVolume{Vec3(0, 0, 1), Vec3(0.1, 0.1, 2)}, Margin));
}
