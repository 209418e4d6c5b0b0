// SPDX-License-Identifier: MIT
// Micro-benchmark of the mask module's inner pieces (issue 5): the conservative software
// rasterizer (triangles per millisecond into 512² and 1024² masks), the max-depth pyramid build,
// and the pyramid's rectangle test (boxes per millisecond). Screen shapes are building faces as a
// city walk sees them: 5–200 px across, log-uniformly, anywhere on the mask.
//
// BM_Quads* (issue 23): the five configurations of Intel's Masked Occlusion Culling comparison,
// random convex quads sorted front to back, each rasterized as its own group and then the pyramid
// built ("render"), and rectangle queries against the result; `reference` is the pixel-by-pixel
// rasterizer and the earlier query, `tiles` the tile rasterizer (AVX2 where the CPU has it) and
// today's rectHidden, in the same run.
#include "mask/MaskRasterPaths.h"

#include <osgVis/core/mask/MaskRasterizer.h>
#include <osgVis/core/mask/OcclusionMask.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace osgVis::core;

namespace
{
constexpr std::size_t ShapeCount = 2048;

double faceSize(std::mt19937& random)
{
    return std::exp(std::uniform_real_distribution<double>(std::log(5.0), std::log(200.0))(random));
}

DepthPlane facePlane(std::mt19937& random)
{
    DepthPlane plane; // 1/depth gently slanted, 10..100 m away
    plane.a = std::uniform_real_distribution<double>(-1e-5, 1e-5)(random);
    plane.b = std::uniform_real_distribution<double>(-1e-5, 1e-5)(random);
    plane.c = std::uniform_real_distribution<double>(0.01, 0.1)(random);
    return plane;
}

// Triangles: three points in a square of the face's size (skipping slivers). Quads: a slanted
// rectangle as two triangles sharing their diagonal (one group).
std::vector<std::vector<ScreenPolygon>> randomGroups(std::uint32_t maskSize, bool quads)
{
    std::mt19937 random(maskSize + (quads ? 1 : 0));
    std::uniform_real_distribution<double> position(0.0, maskSize), unit(0.0, 1.0);
    std::vector<std::vector<ScreenPolygon>> groups;
    while (groups.size() < ShapeCount)
    {
        const double size = faceSize(random);
        const glm::dvec2 corner{position(random) - size / 2, position(random) - size / 2};
        const DepthPlane plane = facePlane(random);
        if (quads)
        {
            const double angle = unit(random) * M_PI, aspect = 0.3 + 0.7 * unit(random);
            const glm::dvec2 u = size * glm::dvec2{std::cos(angle), std::sin(angle)};
            const glm::dvec2 v = aspect * glm::dvec2{-u.y, u.x};
            const glm::dvec2 a = corner, b = corner + u, c = corner + u + v, d = corner + v;
            groups.push_back({ScreenPolygon{{a, b, c}, {false, false, true}, plane},
                              ScreenPolygon{{a, c, d}, {true, false, false}, plane}});
            continue;
        }
        ScreenPolygon triangle;
        for (int i = 0; i < 3; ++i)
            triangle.vertices.push_back(corner + size * glm::dvec2{unit(random), unit(random)});
        const glm::dvec2 e1 = triangle.vertices[1] - triangle.vertices[0],
                         e2 = triangle.vertices[2] - triangle.vertices[0];
        if (std::abs(e1.x * e2.y - e1.y * e2.x) < 0.1 * size * size)
            continue;
        triangle.sharedEdge.assign(3, false);
        triangle.depth = plane;
        groups.push_back({triangle});
    }
    return groups;
}

void rasterizeShapes(benchmark::State& state, bool quads)
{
    const auto maskSize = std::uint32_t(state.range(0));
    const std::vector<std::vector<ScreenPolygon>> groups = randomGroups(maskSize, quads);
    OcclusionMask mask;
    MaskRasterScratch scratch;
    std::size_t triangles = 0, covered = 0;
    for (auto _ : state)
    {
        mask.reset(maskSize, maskSize);
        for (const std::vector<ScreenPolygon>& group : groups)
        {
            covered += rasterizeOccluderGroup(mask, group.data(), group.size(), 0.0, scratch);
            triangles += group.size();
        }
        benchmark::DoNotOptimize(mask.depth(0, 0));
    }
    state.SetItemsProcessed(std::int64_t(triangles));
    state.counters["tris_per_ms"] = benchmark::Counter(double(triangles) / 1000.0, benchmark::Counter::kIsRate);
    state.counters["covered_px_per_tri"] = double(covered) / double(std::max<std::size_t>(triangles, 1));
}

void BM_RasterizeTriangles(benchmark::State& state)
{
    rasterizeShapes(state, false);
}

void BM_RasterizeQuads(benchmark::State& state)
{
    rasterizeShapes(state, true);
}

// A realistically covered mask: the quads above.
OcclusionMask coveredMask(std::uint32_t maskSize)
{
    OcclusionMask mask;
    mask.reset(maskSize, maskSize);
    MaskRasterScratch scratch;
    for (const std::vector<ScreenPolygon>& group : randomGroups(maskSize, true))
        rasterizeOccluderGroup(mask, group.data(), group.size(), 0.0, scratch);
    return mask;
}

void BM_BuildPyramid(benchmark::State& state)
{
    OcclusionMask mask = coveredMask(std::uint32_t(state.range(0)));
    for (auto _ : state)
    {
        mask.buildPyramid();
        benchmark::DoNotOptimize(mask.levelCount());
    }
    state.counters["pyramids_per_ms"] =
        benchmark::Counter(double(state.iterations()) / 1000.0, benchmark::Counter::kIsRate);
}

void BM_RectHidden(benchmark::State& state)
{
    const auto maskSize = std::uint32_t(state.range(0));
    OcclusionMask mask = coveredMask(maskSize);
    mask.buildPyramid();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> position(0.0, maskSize), unit(0.0, 1.0);
    struct Box
    {
        double x0, y0, x1, y1;
        float nearest;
    };
    std::vector<Box> boxes;
    for (std::size_t i = 0; i < 4096; ++i)
    {
        const double width = 2.0 + 98.0 * unit(random) * unit(random),
                     height = 2.0 + 98.0 * unit(random) * unit(random);
        const double x0 = std::min(position(random), maskSize - width),
                     y0 = std::min(position(random), maskSize - height);
        boxes.push_back({x0, y0, x0 + width, y0 + height, float(10.0 + 190.0 * unit(random))});
    }
    std::size_t tested = 0, hidden = 0;
    for (auto _ : state)
    {
        for (const Box& box : boxes)
            hidden += mask.rectHidden(box.x0, box.y0, box.x1, box.y1, box.nearest);
        tested += boxes.size();
    }
    state.SetItemsProcessed(std::int64_t(tested));
    state.counters["boxes_per_ms"] = benchmark::Counter(double(tested) / 1000.0, benchmark::Counter::kIsRate);
    state.counters["hidden_fraction"] = double(hidden) / double(std::max<std::size_t>(tested, 1));
}

// One configuration of the table: `quads` quads of `fraction` of the mask's area each.
struct QuadScene
{
    std::uint32_t width, height;
    std::vector<ScreenPolygon> quads; // front to back
    struct Query
    {
        double x0, y0, x1, y1;
        float nearest;
    };
    std::vector<Query> queries;
};

const QuadScene& quadScene(int configuration)
{
    struct Config
    {
        std::size_t quads;
        double fraction;
        std::uint32_t width, height;
    };
    static const Config configs[] = {{64, 0.08, 320, 256},
                                     {256, 0.04, 320, 256},
                                     {2000, 0.02, 320, 256},
                                     {2000, 0.08, 512, 256},
                                     {256, 0.04, 1280, 720}};
    static std::vector<QuadScene> scenes(std::size(configs));
    QuadScene& scene = scenes[std::size_t(configuration)];
    if (!scene.quads.empty())
        return scene;
    const Config& c = configs[configuration];
    scene.width = c.width;
    scene.height = c.height;
    std::mt19937 random(23 + std::uint32_t(configuration));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::pair<double, ScreenPolygon>> byDepth;
    while (byDepth.size() < c.quads)
    {
        // A rotated rectangle of the wanted area (aspect 1:2 to 2:1) with corners jittered by up
        // to 15 % of its size, centred anywhere on the mask; kept when still convex.
        const double area = c.fraction * c.width * c.height, aspect = std::exp((unit(random) - 0.5) * std::log(4.0));
        const double w = std::sqrt(area * aspect), h = area / w, angle = unit(random) * M_PI;
        const glm::dvec2 centre{unit(random) * c.width, unit(random) * c.height};
        const glm::dvec2 u{std::cos(angle), std::sin(angle)}, v{-u.y, u.x};
        ScreenPolygon quad;
        for (int k = 0; k < 4; ++k)
        {
            const double su = (k == 1 || k == 2) ? 0.5 : -0.5, sv = k >= 2 ? 0.5 : -0.5;
            const glm::dvec2 jitter{(unit(random) - 0.5) * 0.3 * w, (unit(random) - 0.5) * 0.3 * h};
            quad.vertices.push_back(centre + (su * w + jitter.x) * u + (sv * h + jitter.y) * v);
        }
        bool convex = true;
        for (int k = 0; k < 4; ++k)
        {
            const glm::dvec2 a = quad.vertices[k], b = quad.vertices[(k + 1) % 4], d = quad.vertices[(k + 2) % 4];
            convex = convex && (b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x) > 0.0;
        }
        if (!convex)
            continue;
        quad.sharedEdge.assign(4, false);
        // 1/depth slanted by up to ±10 % across the quad, nearest depth 1..100.
        const double depth = 1.0 + 99.0 * unit(random), size = std::sqrt(area);
        quad.depth.a = (unit(random) - 0.5) * 0.2 / depth / size;
        quad.depth.b = (unit(random) - 0.5) * 0.2 / depth / size;
        quad.depth.c = 1.0 / depth - quad.depth.a * centre.x - quad.depth.b * centre.y;
        byDepth.emplace_back(depth, std::move(quad));
    }
    std::sort(byDepth.begin(), byDepth.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& entry : byDepth)
        scene.quads.push_back(std::move(entry.second));
    // Rectangles 2 px to a quarter of the mask across (log-uniform), nearest depth 1..120.
    for (int i = 0; i < 4096; ++i)
    {
        auto side = [&](double limit) { return std::exp(std::log(2.0) + unit(random) * std::log(limit / 2.0)); };
        const double w = side(c.width / 4.0), h = side(c.height / 4.0);
        const double x0 = unit(random) * (c.width - w), y0 = unit(random) * (c.height - h);
        scene.queries.push_back({x0, y0, x0 + w, y0 + h, float(1.0 + 119.0 * unit(random))});
    }
    return scene;
}

enum class Rasterizer
{
    Reference,
    Tiles
};

void renderQuads(const QuadScene& scene, Rasterizer rasterizer, OcclusionMask& mask, MaskRasterScratch& scratch)
{
    mask.reset(scene.width, scene.height);
    for (const ScreenPolygon& quad : scene.quads)
        if (rasterizer == Rasterizer::Reference)
            rasterizeOccluderGroupReference(MaskRasterPath::Simd, mask, &quad, 1, 0.0, scratch);
        else
            rasterizeOccluderGroup(mask, &quad, 1, 0.0, scratch);
    mask.buildPyramid();
}

void quadsRender(benchmark::State& state, Rasterizer rasterizer)
{
    const QuadScene& scene = quadScene(int(state.range(0)));
    OcclusionMask mask;
    MaskRasterScratch scratch;
    for (auto _ : state)
    {
        renderQuads(scene, rasterizer, mask, scratch);
        benchmark::DoNotOptimize(mask.levelCount());
    }
    state.counters["quads"] = double(scene.quads.size());
    state.counters["covered_fraction"] = double(mask.coveredPixels()) / double(scene.width * scene.height);
}

// range(1) 0: the scene's queries (nearest depth 1..120); 1: the same rectangles with the nearest
// depth within ±5 % of the mask's depth at their centre, where coarse texels rarely decide.
// `reference` runs the reference rasterizer and the earlier query (rectHiddenReference), `tiles`
// the tile rasterizer and rectHidden: old and new in one run.
void quadsQuery(benchmark::State& state, Rasterizer rasterizer)
{
    const QuadScene& scene = quadScene(int(state.range(0)));
    OcclusionMask mask;
    MaskRasterScratch scratch;
    renderQuads(scene, rasterizer, mask, scratch);
    std::vector<QuadScene::Query> queries = scene.queries;
    if (state.range(1) == 1)
    {
        std::mt19937 random(5);
        std::uniform_real_distribution<float> factor(0.95f, 1.05f);
        for (QuadScene::Query& q : queries)
        {
            const float centre = mask.depth(std::uint32_t((q.x0 + q.x1) / 2), std::uint32_t((q.y0 + q.y1) / 2));
            q.nearest = (centre < std::numeric_limits<float>::infinity() ? centre : 50.0f) * factor(random);
        }
    }
    std::size_t tested = 0, hidden = 0;
    for (auto _ : state)
    {
        for (const QuadScene::Query& q : queries)
            hidden += rasterizer == Rasterizer::Reference ? mask.rectHiddenReference(q.x0, q.y0, q.x1, q.y1, q.nearest)
                                                          : mask.rectHidden(q.x0, q.y0, q.x1, q.y1, q.nearest);
        tested += queries.size();
    }
    state.counters["ns_per_query"] =
        benchmark::Counter(double(tested) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["hidden_fraction"] = double(hidden) / double(std::max<std::size_t>(tested, 1));
}

void BM_QuadsRender_reference(benchmark::State& state)
{
    quadsRender(state, Rasterizer::Reference);
}
void BM_QuadsRender_tiles(benchmark::State& state)
{
    quadsRender(state, Rasterizer::Tiles);
}
void BM_QuadsQuery_reference(benchmark::State& state)
{
    quadsQuery(state, Rasterizer::Reference);
}
void BM_QuadsQuery_tiles(benchmark::State& state)
{
    quadsQuery(state, Rasterizer::Tiles);
}
} // namespace

// Arguments: the row of the table (0: 64 quads 8 % 320×256, 1: 256 4 % 320×256,
// 2: 2000 2 % 320×256, 3: 2000 8 % 512×256, 4: 256 4 % 1280×720).
BENCHMARK(BM_QuadsRender_reference)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QuadsRender_tiles)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);
// Query arguments: the row, then the query set (0: random nearest depths, 1: near the surface).
BENCHMARK(BM_QuadsQuery_reference)->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_QuadsQuery_tiles)->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RasterizeTriangles)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterizeQuads)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildPyramid)->Arg(512)->Arg(1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RectHidden)->Arg(512)->Arg(1024)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
