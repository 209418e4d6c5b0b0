// SPDX-License-Identifier: MIT
// The tile rasterizer against the pixel-by-pixel reference (internal src/mask/MaskRasterPaths.h),
// over thousands of random groups drawn in sequences into masks whose sizes are not multiples of
// the tile: cut convex polygons, thin slits between abutting polygons, grazing planes, planes that
// cross the horizon, orthographic planes, degenerate polygons and non-finite ones, Δ from 0 to 2.
// Asserted: no pixel is covered that the reference leaves uncovered, no stored depth is nearer
// than the reference's, at least 99 % of the reference's pixels are covered, the tiles' depth
// bounds stay upper bounds, and the AVX2 and SSE2 kernels give the same mask bit for bit.
#include "RandomOccluderGroups.h"
#include "mask/MaskRasterPaths.h"

#include <osgVis/core/mask/OcclusionMask.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace osgVis::core;
using namespace maskTest;

namespace
{
constexpr float Inf = std::numeric_limits<float>::infinity();

struct Scene
{
    std::uint32_t width = 0, height = 0;
    std::vector<std::vector<ScreenPolygon>> groups;
    std::vector<double> shrinks;
};

// 1/depth of a plane through `point` at depth `depth` whose zero line (the horizon) runs at
// distance `horizon` px from it along a random direction: a grazing plane when the horizon is near.
DepthPlane planeWithHorizon(std::mt19937& random, glm::dvec2 point, double depth, double horizon)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double angle = unit(random) * 2.0 * M_PI;
    const glm::dvec2 gradient = glm::dvec2{std::cos(angle), std::sin(angle)} / (depth * horizon);
    DepthPlane plane;
    plane.a = gradient.x;
    plane.b = gradient.y;
    plane.c = 1.0 / depth - glm::dot(gradient, point);
    return plane;
}

ScreenPolygon degeneratePolygon(std::mt19937& random, double size)
{
    std::uniform_real_distribution<double> coordinate(-5.0, size + 5.0), unit(0.0, 1.0);
    const glm::dvec2 a{coordinate(random), coordinate(random)}, b{coordinate(random), coordinate(random)};
    ScreenPolygon polygon;
    switch (random() % 4)
    {
    case 0: // a segment
        polygon.vertices = {a, b};
        break;
    case 1: // collinear
        polygon.vertices = {a, glm::mix(a, b, unit(random)), b};
        break;
    case 2: // one point repeated
        polygon.vertices = {a, a, a, a};
        break;
    default: // a sliver far thinner than the area tolerance allows
        polygon.vertices = {a, b, glm::mix(a, b, 0.5) + glm::dvec2{1e-13, -1e-13}};
        break;
    }
    polygon.sharedEdge.assign(polygon.vertices.size(), false);
    polygon.depth.c = 0.1;
    return polygon;
}

std::vector<ScreenPolygon> randomGroup(std::mt19937& random, double size)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<glm::dvec2> hull = randomConvexPolygon(random, size);
    const int kind = int(random() % 6);
    DepthPlane plane = randomPlane(random, hull[0]);
    if (kind == 2) // grazing: the horizon a few pixels to tens of pixels away
        plane = planeWithHorizon(random, hull[0], 1.0 + 50.0 * unit(random), 2.0 + 40.0 * unit(random));
    if (kind == 3) // the horizon crosses the polygon
        plane = planeWithHorizon(random, hull[0], 5.0, 0.5 + 10.0 * unit(random));
    std::vector<ScreenPolygon> group = randomCutGroup(random, hull, 1 + int(random() % 3), plane);
    if (kind == 4) // thin slits: the pieces become separate occluders, one of them moved by < 0.6 px
    {
        for (ScreenPolygon& polygon : group)
            polygon.sharedEdge.assign(polygon.vertices.size(), false);
        const glm::dvec2 shift{(unit(random) - 0.5) * 1.2, (unit(random) - 0.5) * 1.2};
        for (glm::dvec2& v : group[random() % group.size()].vertices)
            v += random() % 2 ? shift : glm::dvec2{0.0};
    }
    if (kind == 5) // degenerate polygons veto what they touch; rarely a non-finite one spoils it all
    {
        group.push_back(degeneratePolygon(random, size));
        if (random() % 8 == 0)
            group.back().vertices[0].x = std::numeric_limits<double>::quiet_NaN();
    }
    if (random() % 10 == 0) // on half-pixel positions: edges along pixel boundaries, decided in double
        for (ScreenPolygon& polygon : group)
            for (glm::dvec2& v : polygon.vertices)
                if (std::isfinite(v.x))
                    v = glm::round(v * 2.0) / 2.0;
    return group;
}

// Sequences of groups: a mask each, sizes off the tile grid, the groups drawn one after another so
// that later ones meet covered tiles (the depth-bound rejection).
std::vector<Scene> randomScenes(std::uint32_t seed, int sceneCount, int groupsPerScene)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Scene> scenes{std::size_t(sceneCount)};
    for (Scene& scene : scenes)
    {
        scene.width = 40 + std::uint32_t(random() % 60);
        scene.height = 30 + std::uint32_t(random() % 50);
        for (int g = 0; g < groupsPerScene; ++g)
        {
            scene.groups.push_back(randomGroup(random, double(std::max(scene.width, scene.height))));
            scene.shrinks.push_back(random() % 3 == 0 ? double(random() % 3) : 2.0 * unit(random));
        }
    }
    return scenes;
}

template <class Rasterize> OcclusionMask draw(const Scene& scene, Rasterize rasterize)
{
    OcclusionMask mask;
    mask.reset(scene.width, scene.height);
    MaskRasterScratch scratch;
    for (std::size_t g = 0; g < scene.groups.size(); ++g)
        rasterize(mask, scene.groups[g].data(), scene.groups[g].size(), scene.shrinks[g], scratch);
    return mask;
}

OcclusionMask drawReference(const Scene& scene)
{
    return draw(
        scene, [](OcclusionMask& mask, const ScreenPolygon* p, std::size_t n, double shrink, MaskRasterScratch& scratch)
        { return rasterizeOccluderGroupReference(MaskRasterPath::Simd, mask, p, n, shrink, scratch); });
}

OcclusionMask drawTiles(const Scene& scene, MaskTileKernel kernel)
{
    return draw(scene, [kernel](OcclusionMask& mask, const ScreenPolygon* p, std::size_t n, double shrink,
                                MaskRasterScratch& scratch)
                { return rasterizeOccluderGroupTiled(kernel, mask, p, n, shrink, scratch); });
}
} // namespace

TEST(MaskTileRasterizer, NeverCoversMoreOrNearerThanTheReferenceAndCoversAlmostAll)
{
    const std::vector<Scene> scenes = randomScenes(23, 500, 6); // 3000 groups
    std::size_t referencePixels = 0, bothPixels = 0, depthCompared = 0, equalDepth = 0;
    for (std::size_t s = 0; s < scenes.size(); ++s)
    {
        const OcclusionMask reference = drawReference(scenes[s]);
        const OcclusionMask tiles = drawTiles(scenes[s], MaskTileKernel::Sse2);
        for (std::uint32_t y = 0; y < reference.height(); ++y)
            for (std::uint32_t x = 0; x < reference.width(); ++x)
            {
                const float r = reference.depth(x, y), t = tiles.depth(x, y);
                // Uncovered is +inf, so this one comparison says both: nothing the reference leaves
                // open is covered, and no depth is nearer.
                ASSERT_GE(t, r) << "scene " << s << " pixel " << x << "," << y;
                referencePixels += r < Inf;
                bothPixels += r < Inf && t < Inf;
                if (r < Inf && t < Inf)
                {
                    ++depthCompared;
                    equalDepth += t <= r * (1.0f + 1e-4f); // the margins are a few 1e-6 relative, more near the horizon
                }
            }
    }
    EXPECT_GT(referencePixels, 200000u); // the scenes cover enough to mean something
    EXPECT_GE(double(bothPixels), 0.99 * double(referencePixels));
    EXPECT_GE(double(equalDepth), 0.99 * double(depthCompared));
}

TEST(MaskTileRasterizer, TileBoundsStayUpperBounds)
{
    for (const Scene& scene : randomScenes(7, 120, 8))
    {
        const OcclusionMask mask = drawTiles(scene, MaskTileKernel::Sse2);
        for (std::uint32_t ty = 0; ty < mask.tileRows(); ++ty)
            for (std::uint32_t tx = 0; tx < mask.tileColumns(); ++tx)
            {
                float largest = -Inf;
                for (std::uint32_t y = ty * 8; y < std::min(mask.height(), ty * 8 + 8); ++y)
                    for (std::uint32_t x = tx * 8; x < std::min(mask.width(), tx * 8 + 8); ++x)
                        largest = std::max(largest, mask.depth(x, y));
                ASSERT_GE(mask.tileBound(tx, ty), largest) << tx << "," << ty;
                ASSERT_GE(mask.blockBound(tx / OcclusionMask::BlockTiles, ty / OcclusionMask::BlockTiles),
                          mask.tileBound(tx, ty));
            }
    }
}

TEST(MaskTileRasterizer, FarGroupsBehindACoveredMaskChangeNothing)
{
    // A near wall over the whole mask, then the random groups farther than it: every one of them
    // is rejected by the tile bounds, and the mask stays the wall.
    for (const Scene& scene : randomScenes(11, 40, 6))
    {
        OcclusionMask mask;
        mask.reset(scene.width, scene.height);
        MaskRasterScratch scratch;
        ScreenPolygon wall;
        const double w = scene.width, h = scene.height;
        wall.vertices = {{-5.0, -5.0}, {w + 5.0, -5.0}, {w + 5.0, h + 5.0}, {-5.0, h + 5.0}};
        wall.sharedEdge.assign(4, false);
        wall.depth.c = 1.0; // depth 1, nearer than every random plane here
        rasterizeOccluderGroup(mask, &wall, 1, 0.0, scratch);
        ASSERT_EQ(mask.coveredPixels(), std::size_t(scene.width) * scene.height);
        for (std::size_t g = 0; g < scene.groups.size(); ++g)
        {
            bool behind = true;
            for (const ScreenPolygon& p : scene.groups[g])
                behind = behind && p.depth.inverse &&
                         p.depth.c + std::abs(p.depth.a) * (w + 20) + std::abs(p.depth.b) * (h + 20) < 0.9;
            if (behind)
            {
                EXPECT_EQ(rasterizeOccluderGroup(mask, scene.groups[g].data(), scene.groups[g].size(), scene.shrinks[g],
                                                 scratch),
                          0u);
            }
        }
        for (std::uint32_t y = 0; y < mask.height(); ++y)
            for (std::uint32_t x = 0; x < mask.width(); ++x)
                ASSERT_LE(mask.depth(x, y), 1.0f + 1e-5f);
    }
}

TEST(MaskTileRasterizer, Avx2AndSse2KernelsAgreeBitForBit)
{
    if (!maskTileKernelAvailable(MaskTileKernel::Avx2))
        GTEST_SKIP() << "this CPU or build has no AVX2: only the SSE2 kernels run";
    const std::vector<Scene> scenes = randomScenes(99, 500, 6);
    for (std::size_t s = 0; s < scenes.size(); ++s)
    {
        const OcclusionMask sse2 = drawTiles(scenes[s], MaskTileKernel::Sse2);
        const OcclusionMask avx2 = drawTiles(scenes[s], MaskTileKernel::Avx2);
        for (std::uint32_t y = 0; y < sse2.height(); ++y)
            ASSERT_EQ(std::memcmp(sse2.baseRow(y), avx2.baseRow(y), sse2.width() * sizeof(float)), 0)
                << "scene " << s << " row " << y;
        for (std::uint32_t ty = 0; ty < sse2.tileRows(); ++ty)
            for (std::uint32_t tx = 0; tx < sse2.tileColumns(); ++tx)
                ASSERT_EQ(sse2.tileBound(tx, ty), avx2.tileBound(tx, ty));
    }
}
