// SPDX-License-Identifier: MIT
// Micro-benchmark of what a cull pays to find changes nobody reported (issue 43): the SceneWatch
// comparison on a graph where nothing moved, and, with some transforms moved every frame, the
// comparison plus what applying the change costs today (re-extraction with stable ids and the new
// watch). The graph is what applications build: a group per block of 100 objects, each object a
// MatrixTransform over a Geode with one 12-triangle box, state sets shared per block.
// BM_WatchMovingReextracted is the way every change was applied before matrices alone were.
//
//   osgvis_change_microbench --benchmark_filter=Watch   (figures in docs/changes.md)
#include "BoxGeometry.h"
#include "Extraction.h"
#include "SceneWatch.h"

#include <osgVis/SceneExtractor>

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <benchmark/benchmark.h>

#include <vector>

namespace
{
using osgVis::bench::boxGeometry;

struct City
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    std::vector<osg::ref_ptr<osg::MatrixTransform>> transforms;

    explicit City(int objects)
    {
        osg::ref_ptr<osg::Group> block;
        for (int i = 0; i < objects; ++i)
        {
            if (i % 100 == 0)
            {
                block = new osg::Group;
                block->getOrCreateStateSet(); // shared by the block's objects
                root->addChild(block);
            }
            osg::ref_ptr<osg::Geode> geode = new osg::Geode;
            const osg::Vec3 at(float(i % 100) * 4, float(i / 100) * 4, 0);
            geode->addDrawable(boxGeometry(at, at + osg::Vec3(2, 2, 2 + i % 7)));
            osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
            transform->addChild(geode);
            block->addChild(transform);
            transforms.push_back(transform);
        }
    }

    // Moves every `stride`-th object a little, as an animation would each frame.
    void move(int stride, int frame)
    {
        for (std::size_t i = 0; i < transforms.size(); i += stride)
            transforms[i]->setMatrix(osg::Matrixd::translate(0.01 * (frame % 100), 0, 0));
    }
};

// Nothing changed: the comparison every frame's first cull makes.
void BM_WatchStatic(benchmark::State& state)
{
    City city(static_cast<int>(state.range(0)));
    osgVis::SceneWatch watch;
    watch.record(*city.root);
    for (auto _ : state)
        benchmark::DoNotOptimize(watch.changed());
    state.counters["nodes"] = static_cast<double>(watch.nodeCount());
}
BENCHMARK(BM_WatchStatic)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

// range(0) objects, range(1) of them moved every frame, found by the watch and applied by `apply`
// (scene, watch, root), timed together.
template <class Apply> void runMoving(benchmark::State& state, Apply apply)
{
    City city(static_cast<int>(state.range(0)));
    const int stride = static_cast<int>(state.range(0) / state.range(1));
    osg::ref_ptr<const osgVis::ExtractedScene> scene = osgVis::extractScene(*city.root);
    osgVis::SceneWatch watch;
    watch.record(*city.root);
    int frame = 0;
    for (auto _ : state)
    {
        state.PauseTiming();
        city.move(stride, ++frame);
        state.ResumeTiming();
        apply(scene, watch, *city.root);
    }
    state.counters["moved"] = static_cast<double>(state.range(1));
}

// As ViewCuller applies a frame that only changed matrices: the objects below them placed again in a
// copy of the extraction.
void BM_WatchMoving(benchmark::State& state)
{
    runMoving(state,
              [&](osg::ref_ptr<const osgVis::ExtractedScene>& scene, osgVis::SceneWatch& watch, osg::Node&)
              {
                  const osgVis::SceneWatch::Difference& difference = watch.compare();
                  if (difference.other || difference.moved.empty())
                      state.SkipWithError("expected moved transforms only");
                  scene = osgVis::moveObjects(*scene, difference.moved, {});
                  watch.acceptMatrices(difference);
              });
}
BENCHMARK(BM_WatchMoving)->Args({10000, 1000})->Args({10000, 10})->Unit(benchmark::kMillisecond);

// The same, applied by a re-extraction keeping ids and a new recording (what any change cost before).
void BM_WatchMovingReextracted(benchmark::State& state)
{
    runMoving(state,
              [](osg::ref_ptr<const osgVis::ExtractedScene>& scene, osgVis::SceneWatch& watch, osg::Node& root)
              {
                  if (watch.changed())
                  {
                      scene = osgVis::reextractScene(root, *scene);
                      watch.record(root);
                  }
              });
}
BENCHMARK(BM_WatchMovingReextracted)->Args({10000, 1000})->Args({10000, 10})->Unit(benchmark::kMillisecond);
} // namespace

BENCHMARK_MAIN();
