// SPDX-License-Identifier: MIT
// Micro-benchmark of the mask module's inner pieces (issue 5): the conservative software
// rasterizer (triangles per millisecond into 512² and 1024² masks), the max-depth pyramid build,
// and the pyramid's rectangle test (boxes per millisecond). Screen shapes are building faces as a
// city walk sees them: 5–200 px across, log-uniformly, anywhere on the mask.
#include <osgVis/core/mask/MaskRasterizer.h>
#include <osgVis/core/mask/OcclusionMask.h>

#include <benchmark/benchmark.h>

#include <cmath>
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
} // namespace

BENCHMARK(BM_RasterizeTriangles)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterizeQuads)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildPyramid)->Arg(512)->Arg(1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RectHidden)->Arg(512)->Arg(1024)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
