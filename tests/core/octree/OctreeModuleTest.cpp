// SPDX-License-Identifier: MIT
// The octree module on hand-built core scenes (no OSG): what a wall hides, what fused occluders
// hide that single ones cannot, the cases where nothing may be hidden (near plane, eye on a
// plane, inside geometry, orthographic views), the same answer at every thread count and with
// or without temporal coherence, and a randomized check against CPU ray casting.
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/octree/OctreeModule.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

using namespace osgVis::core;

namespace
{
void addQuad(std::vector<Triangle>& out, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
    out.push_back({Vec3f(a), Vec3f(b), Vec3f(c)});
    out.push_back({Vec3f(a), Vec3f(c), Vec3f(d)});
}

// An object made of the given triangles (bounds from them).
ObjectId addObject(Scene& scene, const std::vector<Triangle>& triangles, const std::string& name)
{
    Aabb bounds;
    for (const Triangle& t : triangles)
        for (const Vec3f& v : {t.a, t.b, t.c})
            bounds.expand(Vec3(v));
    const ObjectId id = scene.addObject(bounds, std::uint32_t(triangles.size()), OBJECT_NONE, name);
    scene.objects[id].firstTriangle = std::uint32_t(scene.triangles.size());
    scene.triangles.insert(scene.triangles.end(), triangles.begin(), triangles.end());
    return id;
}

ObjectId addBox(Scene& scene, const Vec3& lo, const Vec3& hi, const std::string& name = "box")
{
    std::vector<Triangle> t;
    const auto p = [&](int i) { return Aabb(lo, hi).corner(i); };
    addQuad(t, p(0), p(2), p(3), p(1)); // z min
    addQuad(t, p(4), p(5), p(7), p(6)); // z max
    addQuad(t, p(0), p(1), p(5), p(4)); // y min
    addQuad(t, p(2), p(6), p(7), p(3)); // y max
    addQuad(t, p(0), p(4), p(6), p(2)); // x min
    addQuad(t, p(1), p(3), p(7), p(5)); // x max
    return addObject(scene, t, name);
}

// A vertical wall in the plane y = y0 from x0 to x1, z 0..height, tessellated n×n.
ObjectId addWall(Scene& scene, double y0, double x0, double x1, double height, int n = 4)
{
    std::vector<Triangle> t;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
            const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
            const double za = height * j / n, zb = height * (j + 1) / n;
            addQuad(t, {xa, y0, za}, {xb, y0, za}, {xb, y0, zb}, {xa, y0, zb});
        }
    return addObject(scene, t, "wall");
}

View perspectiveView(const Vec3& eye, const Vec3& target, double nearDistance = 0.1, double fovDegrees = 60.0)
{
    return makeView(glm::lookAt(eye, target, Vec3(0, 0, 1)),
                    glm::perspective(glm::radians(fovDegrees), 1.25, nearDistance, 500.0));
}

VisibleSet cullWith(VisibilityModule& module, const Scene& scene, const View& view)
{
    VisibleSet visible(scene.objects.size(), true);
    module.cull(view, visible);
    return visible;
}

// Independent CPU reference: ray–triangle casting from the eye to sample points on every object's
// triangles; an object is visible when a sample is reached unobstructed and lies in the frustum.
bool rayHits(const Vec3& origin, const Vec3& direction, const Triangle& t, double& distance)
{
    const Vec3 a(t.a), b(t.b), c(t.c);
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12)
        return false;
    const Vec3 s = origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0 || u > 1)
        return false;
    const Vec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det;
    if (v < 0 || u + v > 1)
        return false;
    distance = glm::dot(e2, q) / det;
    return distance > 0;
}

std::vector<bool> sampledVisibility(const Scene& scene, const View& view, int samplesPerTriangle)
{
    std::vector<bool> visible(scene.objects.size(), false);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const SceneObject& object : scene.objects)
        for (std::uint32_t k = 0; k < object.triangleCount && !visible[object.id]; ++k)
        {
            const Triangle& t = scene.triangles[object.firstTriangle + k];
            for (int s = 0; s < samplesPerTriangle && !visible[object.id]; ++s)
            {
                double u = unit(random), v = unit(random);
                if (u + v > 1)
                    u = 1 - u, v = 1 - v;
                const Vec3 point = Vec3(t.a) + u * (Vec3(t.b) - Vec3(t.a)) + v * (Vec3(t.c) - Vec3(t.a));
                if (!view.frustum.contains(point))
                    continue;
                const Vec3 direction = point - view.eye;
                const double length = glm::length(direction);
                bool blocked = false;
                for (std::size_t i = 0; i < scene.triangles.size() && !blocked; ++i)
                {
                    if (i >= object.firstTriangle && i < object.firstTriangle + object.triangleCount)
                        continue;
                    double distance = 0;
                    blocked = rayHits(view.eye, direction / length, scene.triangles[i], distance) &&
                              distance < length * (1 - 1e-9);
                }
                visible[object.id] = !blocked;
            }
        }
    return visible;
}

void expectConservative(VisibilityModule& module, const Scene& scene, const View& view, const std::string& where)
{
    const VisibleSet kept = cullWith(module, scene, view);
    const std::vector<bool> truth = sampledVisibility(scene, view, 24);
    for (const SceneObject& o : scene.objects)
        EXPECT_FALSE(truth[o.id] && !kept.test(o.id))
            << where << ": visible object " << o.id << " (" << o.name << ") culled";
}
} // namespace

TEST(OctreeModule, IsRegisteredInBothVariants)
{
    EXPECT_EQ(std::string(createModule("octree")->name()), "octree");
    EXPECT_EQ(std::string(createModule("octree-single")->name()), "octree-single");
    EXPECT_EQ(std::string(createModule("octree-paper")->name()), "octree-paper");
    EXPECT_FALSE(createModule("octree")->approximate());
    EXPECT_EQ(createChain("frustum+octree").size(), 2u);
}

TEST(OctreeModule, WallHidesWhatIsBehindItAndNothingElse)
{
    Scene scene;
    addWall(scene, 10, -5, 5, 3); // 0: its shadow ends at x = ±7.5 and z = 3.65 at y = 15
    const ObjectId behind = addBox(scene, {-1, 15, 0}, {1, 17, 2}, "behind");
    const ObjectId farBehind = addBox(scene, {3, 30, 0}, {5, 32, 3}, "far behind");
    const ObjectId inFront = addBox(scene, {-1, 5, 0}, {1, 7, 2}, "in front");
    const ObjectId beside = addBox(scene, {9, 15, 0}, {10, 16, 2}, "beside the shadow, in view");
    const ObjectId above = addBox(scene, {-1, 15, 5}, {1, 16, 6}, "above the shadow, in view");
    OctreeModule octree;
    octree.setScene(scene);
    const VisibleSet kept = cullWith(octree, scene, perspectiveView({0, 0, 1.7}, {0, 20, 1.7}));
    EXPECT_TRUE(kept.test(0));
    EXPECT_FALSE(kept.test(behind));
    EXPECT_FALSE(kept.test(farBehind));
    EXPECT_TRUE(kept.test(inFront));
    EXPECT_TRUE(kept.test(beside));
    EXPECT_TRUE(kept.test(above));
    EXPECT_GE(octree.lastStatistics().activeOccluders, 1u);
}

TEST(OctreeModule, ConnectedWallsFuseWhereSingleOccludersCannot)
{
    // Two walls meeting at a right-angled corner in front of the eye; the box sits behind the
    // corner, so neither wall alone covers it.
    Scene scene;
    std::vector<Triangle> corner;
    addQuad(corner, {-10, 20, 0}, {0, 10, 0}, {0, 10, 10}, {-10, 20, 10});
    addQuad(corner, {0, 10, 0}, {10, 20, 0}, {10, 20, 10}, {0, 10, 10});
    addObject(scene, corner, "corner");
    const ObjectId hidden = addBox(scene, {-1.5, 14, 2}, {1.5, 15, 4}, "behind the corner");
    const View view = perspectiveView({0, 0, 3}, {0, 20, 3});

    OctreeOptions fusedOptions; // the traversal's own fusion, without the sweep that would fuse them too
    fusedOptions.fuseDisjoint = false;
    OctreeModule fused(fusedOptions);
    fused.setScene(scene);
    EXPECT_FALSE(cullWith(fused, scene, view).test(hidden));
    OctreeOptions singleOptions = fusedOptions;
    singleOptions.fuseConnected = false;
    OctreeModule single(singleOptions);
    single.setScene(scene);
    EXPECT_TRUE(cullWith(single, scene, view).test(hidden));
    expectConservative(fused, scene, view, "corner");
}

TEST(OctreeModule, SweepFusesOccludersThatShareNoEdge)
{
    // Two separate walls, the left one nearer, overlapping on screen; the box behind the overlap
    // sticks out of each wall's shadow alone. Only the occlusion-tree sweep hides it.
    Scene scene;
    addWall(scene, 10, -8, 0.5, 6);
    addWall(scene, 14, -0.5, 8, 6);
    const ObjectId hidden = addBox(scene, {-2.5, 30, 1}, {2.5, 31, 2}, "behind both walls");
    const ObjectId peeking = addBox(scene, {-1, 30, 6}, {1, 31, 30}, "rising over them");
    const View view = perspectiveView({0, 0, 1.7}, {0, 20, 1.7});

    OctreeOptions sweep;
    sweep.fuseDisjoint = true;
    OctreeModule octree(sweep);
    octree.setScene(scene);
    const VisibleSet kept = cullWith(octree, scene, view);
    EXPECT_FALSE(kept.test(hidden));
    EXPECT_TRUE(kept.test(peeking));
    EXPECT_EQ(octree.lastStatistics().sweptHidden, 1u);
    EXPECT_GE(octree.lastStatistics().sweptOccluders, 2u);
    expectConservative(octree, scene, view, "two walls");

    OctreeOptions noSweep;
    noSweep.fuseDisjoint = false;
    OctreeModule traversalOnly(noSweep);
    traversalOnly.setScene(scene);
    EXPECT_TRUE(cullWith(traversalOnly, scene, view).test(hidden));
}

TEST(OctreeModule, OccluderReachingInFrontOfTheNearPlaneHidesNothing)
{
    Scene scene;
    addWall(scene, 10, -20, 20, 8);
    const ObjectId behind = addBox(scene, {-1, 15, 0}, {1, 17, 2});
    OctreeModule octree;
    octree.setScene(scene);
    // Near plane at 11 m: the wall at 10 m is clipped away and the box behind it is in view.
    const View view = perspectiveView({0, 0, 1.7}, {0, 20, 1.7}, 11.0);
    EXPECT_TRUE(cullWith(octree, scene, view).test(behind));
}

TEST(OctreeModule, EyeOnTheOccluderPlaneOrInsideGeometryHidesNothingVisible)
{
    Scene scene;
    addWall(scene, 10, -20, 20, 8);
    addBox(scene, {-1, 15, 0}, {1, 17, 2});
    addBox(scene, {-3, -3, 0}, {3, 3, 4}, "room around the eye");
    addBox(scene, {8, 4, 0}, {9, 5, 1});
    OctreeModule octree;
    octree.setScene(scene);
    // Eye exactly in the wall's plane, looking along it; then inside the closed box.
    expectConservative(octree, scene, perspectiveView({0, 10, 1.7}, {20, 10, 1.7}), "on the wall plane");
    expectConservative(octree, scene, perspectiveView({0, 10, 1.7}, {0, 30, 1.7}), "in the wall looking through");
    const View inside = perspectiveView({0, 0, 1.7}, {0, 20, 1.7});
    const VisibleSet kept = cullWith(octree, scene, inside);
    EXPECT_TRUE(kept.test(2)) << "the box around the eye is drawn";
}

TEST(OctreeModule, OrthographicViewsOnlyCullTheFrustum)
{
    Scene scene;
    addWall(scene, 10, -20, 20, 8);
    const ObjectId behind = addBox(scene, {-1, 15, 0}, {1, 17, 2});
    OctreeModule octree;
    octree.setScene(scene);
    const View view = makeView(glm::lookAt(Vec3(0, 0, 1.7), Vec3(0, 20, 1.7), Vec3(0, 0, 1)),
                               glm::ortho(-30.0, 30.0, -20.0, 20.0, 0.1, 500.0));
    EXPECT_TRUE(cullWith(octree, scene, view).test(behind));
}

namespace
{
// A city-like field: rows of tessellated buildings and small objects between them.
Scene blockField(std::uint32_t seed, int rows)
{
    Scene scene;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < rows; ++j)
        {
            const double x = i * 12.0, y = j * 12.0;
            if ((i + j) % 3 == 0)
                addBox(scene, {x, y, 0}, {x + 8 + jitter(random), y + 8 + jitter(random), 6 + 4 * jitter(random)},
                       "building");
            else
                addBox(scene, {x + 4, y + 4, 0}, {x + 5, y + 5, 1 + jitter(random) * 0.5}, "kiosk");
        }
    return scene;
}

std::vector<View> walkThrough(int rows, int count)
{
    std::vector<View> views;
    for (int k = 0; k < count; ++k)
    {
        const double t = double(k) / count;
        const Vec3 eye(10.0 + t * 12.0 * (rows - 2), 10.0 + 0.5 * t * 12.0 * (rows - 2), 1.7);
        views.push_back(perspectiveView(eye, eye + Vec3(std::cos(t * 6.0), std::sin(t * 6.0), 0.0)));
    }
    return views;
}
} // namespace

TEST(OctreeModule, SameAnswerAtEveryThreadCountAndWithoutCoherence)
{
    const Scene scene = blockField(3, 24); // 576 objects: above the parallel threshold
    const std::vector<View> views = walkThrough(24, 40);
    const auto run = [&](const OctreeOptions& options, int threads)
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
        OctreeModule octree(options);
        octree.setScene(scene);
        std::vector<VisibleSet> sets;
        std::size_t hidden = 0;
        for (const View& view : views)
        {
            sets.push_back(cullWith(octree, scene, view));
            hidden += octree.lastStatistics().nodesInvisible;
        }
        EXPECT_GT(hidden, 0u) << "the walk must exercise occlusion";
        return sets;
    };
    const std::vector<VisibleSet> one = run(OctreeOptions(), 1);
    EXPECT_EQ(run(OctreeOptions(), 2), one);
    OctreeOptions noCoherence;
    noCoherence.temporalCoherence = false;
    EXPECT_EQ(run(noCoherence, 2), one);
}

TEST(OctreeModule, TemporalCoherenceReusesPlanes)
{
    const Scene scene = blockField(5, 12);
    OctreeModule octree;
    octree.setScene(scene);
    const View first = perspectiveView({10, 10, 1.7}, {60, 40, 1.7});
    cullWith(octree, scene, first);
    const View next = perspectiveView({10.05, 10.02, 1.7}, {60, 40, 1.7});
    cullWith(octree, scene, next);
    EXPECT_GT(octree.lastStatistics().cachedDecisions, 0u);
}

TEST(OctreeModule, NeverCullsAnObjectRayCastingSees)
{
    for (std::uint32_t seed : {11u, 12u, 13u})
    {
        const Scene scene = blockField(seed, 7);
        for (const char* mode : {"octree", "octree-single"})
        {
            auto module = createModule(mode);
            module->setScene(scene);
            const std::vector<View> views = walkThrough(7, 12);
            for (std::size_t k = 0; k < views.size(); ++k)
                expectConservative(*module, scene, views[k],
                                   std::string(mode) + " seed " + std::to_string(seed) + " view " + std::to_string(k));
        }
    }
}

TEST(OctreeModule, DebugRecordDescribesTheLastQuery)
{
    Scene scene;
    addWall(scene, 10, -20, 20, 8);
    addBox(scene, {-1, 15, 0}, {1, 17, 2});
    addBox(scene, {100, -50, 0}, {101, -49, 1}); // behind the eye: outside the frustum
    OctreeModule octree;
    DebugRecord record;
    octree.setDebugRecord(&record);
    octree.setScene(scene);
    cullWith(octree, scene, perspectiveView({0, 0, 1.7}, {0, 20, 1.7}));
    EXPECT_FALSE(record.activeOccluders.empty());
    EXPECT_FALSE(record.eyeCell.empty());
    EXPECT_TRUE(record.eyeCell.contains(Vec3(0, 0, 1.7)));
    bool invisible = false, outside = false;
    for (const DebugRecord::Node& node : record.nodes)
    {
        invisible = invisible || node.state == NodeState::Invisible;
        outside = outside || node.state == NodeState::OutsideFrustum;
    }
    EXPECT_TRUE(invisible);
    EXPECT_TRUE(outside);
}
