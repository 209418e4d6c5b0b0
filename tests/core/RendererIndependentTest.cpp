// SPDX-License-Identifier: MIT
// Drives the core with no renderer at all: its own scene, its own views, and a brute-force reference
// that shares no code with the frustum module (the frustum is rebuilt from its eight corners and
// boxes are tested with the separating-axis theorem).
#include <osgVis/core/frustum/FrustumModule.h>
#include <osgVis/core/api/ModuleRegistry.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <limits>

using namespace osgVis::core;

namespace
{
using Corners = std::array<Vec3, 8>;

// A 16 × 16 × 2 grid of boxes of varying size, spaced 4 apart, centred on the origin:
//
//   z=3   ▫ ▫ ▫ ▫ ...      (second layer)
//   z=0   ▪ ▪ ▪ ▪ ...      x, y in [-30, 30]
Scene gridScene()
{
    Scene scene;
    for (int layer = 0; layer < 2; ++layer)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
            {
                const Vec3 centre(4.0 * x - 30.0, 4.0 * y - 30.0, 3.0 * layer);
                const Vec3 half(0.3 + 0.1 * ((x + y) % 7), 0.3 + 0.1 * ((x * 3 + y) % 5), 0.5 + 0.2 * layer);
                scene.addObject(Aabb(centre - half, centre + half), 12);
            }
    return scene;
}

// The frustum's corners: the clip-space cube mapped back to world space.
Corners frustumCorners(const Mat4& viewProjection)
{
    const Mat4 inverse = glm::inverse(viewProjection);
    Corners c;
    for (int i = 0; i < 8; ++i)
    {
        const Vec4 p = inverse * Vec4((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1, 1);
        c[i] = Vec3(p) / p.w;
    }
    return c;
}

Corners boxCorners(const Aabb& b)
{
    Corners c;
    for (int i = 0; i < 8; ++i)
        c[i] = Vec3((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    return c;
}

// How far the two point sets overlap along `axis` (negative: a gap separates them).
double overlapAlong(const Vec3& axis, const Corners& a, const Corners& b)
{
    double aMin = std::numeric_limits<double>::max(), aMax = std::numeric_limits<double>::lowest();
    double bMin = aMin, bMax = aMax;
    for (const Vec3& p : a)
    {
        aMin = std::min(aMin, glm::dot(axis, p));
        aMax = std::max(aMax, glm::dot(axis, p));
    }
    for (const Vec3& p : b)
    {
        bMin = std::min(bMin, glm::dot(axis, p));
        bMax = std::max(bMax, glm::dot(axis, p));
    }
    return std::min(aMax, bMax) - std::max(aMin, bMin);
}

// Separating-axis test of two convex hexahedra (corner i: bit 0 x, bit 1 y, bit 2 z of its own
// parameterisation): the face normals of both and the cross products of their edge directions.
// Returns the smallest overlap over all axes (unit axes): > 0 means the solids truly intersect.
double satOverlap(const Corners& frustum, const Corners& box)
{
    std::vector<Vec3> frustumEdges;
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit))
                frustumEdges.push_back(frustum[i | bit] - frustum[i]);
    const Vec3 boxEdges[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

    std::vector<Vec3> axes(boxEdges, boxEdges + 3);
    // Frustum face normals: each face spans two edge directions meeting at one of its corners.
    const int faces[6][3] = {{0, 2, 4}, {1, 3, 5}, {0, 1, 4}, {2, 3, 6}, {0, 1, 2}, {4, 5, 6}};
    for (const auto& f : faces)
        axes.push_back(glm::cross(frustum[f[1]] - frustum[f[0]], frustum[f[2]] - frustum[f[0]]));
    for (const Vec3& e : frustumEdges)
        for (const Vec3& b : boxEdges)
            axes.push_back(glm::cross(e, b));

    double smallest = std::numeric_limits<double>::max();
    for (const Vec3& axis : axes)
    {
        const double length = glm::length(axis);
        if (length < 1e-12)
            continue;
        smallest = std::min(smallest, overlapAlong(axis / length, frustum, box));
    }
    return smallest;
}

struct Camera
{
    Mat4 view, projection;
};

// A walk over and through the grid with each projection kind.
std::vector<Camera> cameras()
{
    std::vector<Camera> out;
    const Mat4 projections[] = {
        glm::perspective(glm::radians(60.0), 1.25, 0.1, 40.0),
        glm::frustum(-0.02, 0.1, -0.05, 0.03, 0.1, 60.0), // off-centre
        glm::ortho(-12.0, 8.0, -6.0, 10.0, 0.5, 50.0),
    };
    for (const Mat4& projection : projections)
        for (int i = 0; i < 60; ++i)
        {
            const double a = i * 0.21;
            const Vec3 eye(35.0 * std::cos(a) * (i % 2 ? 0.3 : 1.0), 35.0 * std::sin(a), 1.0 + (i % 5));
            const Vec3 target(10.0 * std::sin(3 * a), -8.0 * std::cos(a), 0.5 * (i % 3));
            out.push_back({glm::lookAt(eye, target, Vec3(0, 0, 1)), projection});
        }
    return out;
}

VisibleSet cullAlone(VisibilityModule& module, const Scene& scene, const View& view)
{
    VisibleSet visible(scene.objects.size(), true);
    module.cull(view, visible);
    return visible;
}
} // namespace

TEST(RendererIndependent, FrustumModuleKeepsEveryBoxThatIntersectsTheFrustum)
{
    const Scene scene = gridScene();
    FrustumModule module; // one instance across all views: state carried between frames must not leak
    module.setScene(scene);
    const double tolerance = 1e-7;
    std::size_t kept = 0, culled = 0, mustCull = 0;
    for (const Camera& camera : cameras())
    {
        const View view = makeView(camera.view, camera.projection);
        const VisibleSet visible = cullAlone(module, scene, view);
        const Corners frustum = frustumCorners(camera.projection * camera.view);
        for (const SceneObject& o : scene.objects)
        {
            const double overlap = satOverlap(frustum, boxCorners(o.bounds));
            if (overlap > tolerance)
            {
                EXPECT_TRUE(visible.test(o.id)) << "false-invisible: object " << o.id;
            }
            if (overlap < -tolerance)
            {
                // Separated along a face normal of the frustum: the plane test must cull it.
                ++mustCull;
            }
            (visible.test(o.id) ? kept : culled) += 1;
        }
    }
    EXPECT_GT(kept, 0u);
    EXPECT_GT(culled, 0u);
    EXPECT_GT(mustCull, culled / 2);
}

TEST(RendererIndependent, CullsBoxesOutsideOneFrustumPlane)
{
    // A box entirely on the outer side of one of the frustum's faces (computed from the corners, not
    // from the module's planes) is culled; in particular every box behind the eye.
    const Scene scene = gridScene();
    FrustumModule module;
    module.setScene(scene);
    const int faces[6][4] = {{0, 2, 4, 6}, {1, 3, 5, 7}, {0, 1, 4, 5}, {2, 3, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
    std::size_t behindEye = 0;
    for (const Camera& camera : cameras())
    {
        const View view = makeView(camera.view, camera.projection);
        const VisibleSet visible = cullAlone(module, scene, view);
        const Corners frustum = frustumCorners(camera.projection * camera.view);
        Vec3 inside(0.0);
        for (const Vec3& c : frustum)
            inside += c / 8.0;
        const Vec3 forward = -Vec3(glm::inverse(camera.view)[2]);
        for (const SceneObject& o : scene.objects)
        {
            const Corners box = boxCorners(o.bounds);
            bool outsideOneFace = false;
            for (const auto& f : faces)
            {
                Vec3 n = glm::cross(frustum[f[1]] - frustum[f[0]], frustum[f[2]] - frustum[f[0]]);
                if (glm::dot(n, inside - frustum[f[0]]) > 0)
                    n = -n; // outward
                n = glm::normalize(n);
                bool allOut = true;
                for (const Vec3& p : box)
                    allOut = allOut && glm::dot(n, p - frustum[f[0]]) > 1e-7;
                outsideOneFace = outsideOneFace || allOut;
            }
            bool behind = true;
            for (const Vec3& p : box)
                behind = behind && glm::dot(forward, p - view.eye) < 0.0;
            behindEye += behind;
            if (outsideOneFace || behind)
            {
                EXPECT_FALSE(visible.test(o.id)) << "object " << o.id << " kept although outside";
            }
        }
    }
    EXPECT_GT(behindEye, 0u);
}

TEST(RendererIndependent, HierarchyAgreesWithFlatTestAndFreshModules)
{
    // Temporal state: the same module over many views answers what a fresh module answers, and the
    // kd-tree traversal with plane masks answers what a flat per-object test answers.
    const Scene scene = gridScene();
    FrustumModule reused;
    reused.setScene(scene);
    for (const Camera& camera : cameras())
    {
        const View view = makeView(camera.view, camera.projection);
        FrustumModule fresh;
        fresh.setScene(scene);
        VisibleSet flat(scene.objects.size());
        for (const SceneObject& o : scene.objects)
        {
            if (view.frustum.classify(o.bounds) != Containment::Outside)
                flat.set(o.id);
        }
        const VisibleSet a = cullAlone(reused, scene, view);
        EXPECT_TRUE(a == cullAlone(fresh, scene, view));
        EXPECT_TRUE(a == flat);
    }
}

TEST(RendererIndependent, ChainOfTwoFrustumStagesEqualsOne)
{
    Scene scene = gridScene();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const ObjectId broken = scene.addObject(Aabb(Vec3(nan), Vec3(nan)), 7, OBJECT_ALWAYS_VISIBLE);
    ModuleChain one = createChain("frustum");
    ModuleChain two = createChain("frustum,frustum");
    one.setScene(scene);
    two.setScene(scene);
    VisibleSet a, b;
    for (const Camera& camera : cameras())
    {
        const View view = makeView(camera.view, camera.projection);
        one.cull(view, a);
        two.cull(view, b);
        EXPECT_TRUE(a == b);
        EXPECT_TRUE(a.test(broken));
        ASSERT_EQ(two.lastTimings().size(), 2u);
        EXPECT_EQ(two.lastTimings()[0].visibleAfter, two.lastTimings()[1].visibleAfter);
    }
}
