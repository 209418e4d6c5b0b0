// SPDX-License-Identifier: MIT
// Micro-benchmark of the CDT method's occlusion record (issue 21): constraint insertion (random
// convex quads inserted as occluders, a fresh frame each time; items/s = occluders/s, the
// `constraints/s` counter = input constraint edges/s) and coverage queries (random axis-aligned
// and rotated quads against the finished record; items/s = queries/s), for 64, 256 and 2000
// occluders on a 1024 x 1024 screen scaled to a 2^20 grid. And the whole cdt cull on the test city
// (tests/core/support/BoxScenes), walking its own kd-tree or the renderer's hierarchy handed over
// as Scene::hierarchy (visibility API, ordered traversal by callback): the same kd-tree (the sets
// are identical, tests CdtHierarchy), or a BVH walked under the depth-only rule; the octree's
// cull likewise (BM_OctreeCullCity: its own BVH, or the renderer's kd-tree of disjoint cells), and
// the mask's (BM_MaskCullCity: its own kd-tree or the renderer's; the views lie farther apart
// than its speed bound allows, so every one is a critical frame: selection, rasterization, marking).
#include "BoxScenes.h"
#include "RegionSampling.h"

#include <osgVis/core/cdt/CdtModule.h>
#include <osgVis/core/cdt/CoverageTriangulation.h>
#include <osgVis/core/mask/MaskModule.h>
#include <osgVis/core/octree/OctreeModule.h>
#include <osgVis/core/spatial/DisjointCellTree.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

using namespace osgVis::core::cdt;

namespace
{
constexpr std::int32_t Scale = 1024; // grid units per pixel
constexpr std::int32_t Screen = 1024 * Scale;

/// A random convex quad (a rotated rectangle) 5-200 px across, log-uniformly, on the screen.
std::vector<GridPoint> randomQuad(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double size = 5.0 * std::pow(40.0, u(rng)) * Scale;
    const double w = size, h = size * (0.3 + 0.7 * u(rng)), angle = u(rng) * 6.283185307179586;
    const double cx = u(rng) * Screen, cy = u(rng) * Screen;
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<GridPoint> q;
    for (const auto& [x, y] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}})
        q.push_back({std::int32_t(std::lround(cx + c * x * w - s * y * h)),
                     std::int32_t(std::lround(cy + s * x * w + c * y * h))});
    return q;
}

std::vector<std::vector<GridPoint>> quads(std::size_t n, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::vector<std::vector<GridPoint>> out;
    while (out.size() < n)
        out.push_back(randomQuad(rng));
    return out;
}

void fill(CoverageTriangulation& cdt, const std::vector<std::vector<GridPoint>>& occluders)
{
    cdt.reset(0, 0, Screen, Screen);
    for (const auto& q : occluders)
        cdt.insertOccluder(q.data(), q.size(), CoverKind::DepthFree, {});
}

void BM_CdtInsertOccluders(benchmark::State& state)
{
    const auto occluders = quads(std::size_t(state.range(0)), 7);
    CoverageTriangulation cdt;
    for (auto _ : state)
    {
        fill(cdt, occluders);
        benchmark::DoNotOptimize(cdt.statistics().triangles);
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(occluders.size()));
    state.counters["constraints/s"] =
        benchmark::Counter(double(state.iterations()) * double(occluders.size()) * 4.0, benchmark::Counter::kIsRate);
    state.counters["triangles"] = double(cdt.statistics().triangles);
    state.counters["crossings"] = double(cdt.statistics().crossings);
}

void BM_CdtQueries(benchmark::State& state)
{
    const auto occluders = quads(std::size_t(state.range(0)), 7);
    const auto queries = quads(1024, 11);
    CoverageTriangulation cdt;
    fill(cdt, occluders);
    std::size_t i = 0, hiddenCount = 0, total = 0;
    for (auto _ : state)
    {
        const auto& q = queries[i++ % queries.size()];
        const bool h = cdt.hidden(q.data(), q.size(), QueryMode::DepthFree);
        hiddenCount += h;
        ++total;
        benchmark::DoNotOptimize(h);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hidden%"] = total ? 100.0 * double(hiddenCount) / double(total) : 0.0;
}
enum class Walked
{
    OwnTree,
    RendererKdTree,
};

// One module culling the city on its own tree or on a renderer's kd-tree (visibility API §3.3).
template <class Module>
void BM_CullCityOnHierarchy(benchmark::State& state)
{
    using namespace osgVis::core;
    osgVis::test::City city = osgVis::test::makeCity();
    if (Walked(state.range(0)) == Walked::RendererKdTree)
    {
        std::vector<Aabb> bounds;
        for (const SceneObject& o : city.scene.objects)
            bounds.push_back(o.bounds);
        auto tree = std::make_shared<DisjointCellTree>();
        tree->build(bounds, std::vector<bool>(bounds.size(), true), 1);
        city.scene.hierarchy = tree;
    }
    Module module;
    module.setScene(city.scene);
    std::vector<View> views;
    for (int i = 0; i < 30; ++i)
    {
        views.push_back(osgVis::test::lookFrom({-5.0 + 30.0 * (i % 6), -5.0 + 6.0 * i, 1.7},
                                               {std::sin(0.7 * i), std::cos(0.7 * i), -0.05}, {0, 0, 1}, 60.0, 640, 480));
        views.back().time = i / 30.0;
    }
    VisibleSet visible;
    std::size_t kept = 0;
    for (const View& view : views)
    {
        visible.reset(city.scene.objects.size(), true);
        module.cull(view, visible);
        kept += visible.count();
    }
    std::size_t i = 0;
    for (auto _ : state)
    {
        visible.reset(city.scene.objects.size(), true);
        module.cull(views[i++ % views.size()], visible);
        benchmark::DoNotOptimize(visible.count());
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(module.walksSceneHierarchy() ? "renderer's kd-tree" : "own kd-tree");
    state.counters["visible/view"] = double(kept) / double(views.size()); // over the 30 views, once
}
} // namespace

void BM_CdtCullCity(benchmark::State& state) { BM_CullCityOnHierarchy<osgVis::core::CdtModule>(state); }
void BM_OctreeCullCity(benchmark::State& state) { BM_CullCityOnHierarchy<osgVis::core::OctreeModule>(state); }
void BM_MaskCullCity(benchmark::State& state) { BM_CullCityOnHierarchy<osgVis::core::MaskModule>(state); }
BENCHMARK(BM_CdtCullCity)->Arg(int(Walked::OwnTree))->Arg(int(Walked::RendererKdTree))->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OctreeCullCity)->Arg(int(Walked::OwnTree))->Arg(int(Walked::RendererKdTree))->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MaskCullCity)->Arg(int(Walked::OwnTree))->Arg(int(Walked::RendererKdTree))->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CdtInsertOccluders)->Arg(64)->Arg(256)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CdtQueries)->Arg(64)->Arg(256)->Arg(2000)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
