// SPDX-License-Identifier: MIT
// Micro-benchmark of what osgVis adds to OSG's own cull traversal outside its modules (issue 46): one
// osgUtil::SceneView cull per iteration, the eye turning through eight gazes, of
//  - Plain:        the scene under an osg::Group, OSG's cull visitor (the reference),
//  - Group:        the scene under an osgVis::VisibilityGroup("frustum"), OSG's cull visitor,
//  - CullVisitor:  the scene under an osg::Group, osgVis::CullVisitor("frustum").
// Adapter overhead = (Group or CullVisitor) − Plain − module_ms (the chain's own time, which the
// ViewCuller reports). Scenes: Generated, 10 000 box drawables in 1 000 groups of ten geodes, the eye
// in the middle of the grid; Map, a Quake 3 level as OSG's bsp plugin reads it, the eye at its
// bound's centre (OSGVIS_BENCH_MAP, default ~/.cache/osgvis/levels/maps/am_underworks2.bsp;
// skipped when absent).
//
//   osgvis_adapter_microbench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "BoxGeometry.h"
#include <osgVis/CullVisitor>
#include <osgVis/VisibilityGroup>

#include <osg/FrameStamp>
#include <osg/Geode>
#include <osg/Geometry>
#include <osgDB/ReadFile>
#include <osgUtil/SceneView>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace
{
using osgVis::bench::boxGeometry;

// 1 000 groups of ten geodes of one box each, on a 100 × 100 grid 4 units apart.
osg::ref_ptr<osg::Group> generatedContent()
{
    osg::ref_ptr<osg::Group> content = new osg::Group;
    for (int g = 0; g < 1000; ++g)
    {
        osg::ref_ptr<osg::Group> group = new osg::Group;
        for (int i = 0; i < 10; ++i)
        {
            const int index = g * 10 + i;
            const osg::Vec3 at(float(index % 100) * 4 - 200, float(index / 100) * 4 - 200, 0);
            osg::ref_ptr<osg::Geode> geode = new osg::Geode;
            geode->addDrawable(boxGeometry(at, at + osg::Vec3(2, 2, 2 + float(index % 7))));
            group->addChild(geode);
        }
        content->addChild(group);
    }
    return content;
}

std::string mapPath()
{
    if (const char* path = std::getenv("OSGVIS_BENCH_MAP"))
        return path;
    const char* home = std::getenv("HOME");
    return std::string(home ? home : "") + "/.cache/osgvis/levels/maps/am_underworks2.bsp";
}

osg::ref_ptr<osg::Node> mapContent()
{
    static osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile(mapPath());
    return loaded;
}

enum Culling
{
    Plain,
    Group,
    Visitor
};

void runCulls(benchmark::State& state, osg::Node* content, Culling culling)
{
    if (!content)
    {
        state.SkipWithError(("cannot read " + mapPath()).c_str());
        return;
    }
    osg::ref_ptr<osg::Group> root = culling == Group ? new osgVis::VisibilityGroup("frustum") : new osg::Group;
    root->addChild(content);
    osg::ref_ptr<osgUtil::SceneView> sceneView = new osgUtil::SceneView;
    sceneView->setDefaults();
    if (culling == Visitor)
        sceneView->setCullVisitor(new osgVis::CullVisitor("frustum"));
    sceneView->setSceneData(root.get());
    sceneView->setViewport(0, 0, 960, 768);
    sceneView->setProjectionMatrixAsPerspective(70.0, 960.0 / 768.0, 1.0, 10000.0);
    osg::ref_ptr<osg::FrameStamp> frameStamp = new osg::FrameStamp;
    sceneView->setFrameStamp(frameStamp.get());
    const osg::BoundingSphere bound = content->getBound();
    const osg::Vec3d eye = bound.center();

    unsigned frame = 0;
    double moduleMs = 0.0;
    for (auto _ : state)
    {
        const double yaw = 2.0 * M_PI * double(frame % 8) / 8.0;
        sceneView->setViewMatrixAsLookAt(eye, eye + osg::Vec3d(std::cos(yaw), std::sin(yaw), -0.1), osg::Z_AXIS);
        frameStamp->setFrameNumber(frame++);
        sceneView->cull();
        if (culling == Group)
            moduleMs += static_cast<osgVis::VisibilityGroup*>(root.get())->getLastStatistics().cullMs;
        else if (culling == Visitor)
            moduleMs += static_cast<osgVis::CullVisitor*>(sceneView->getCullVisitor())->getLastStatistics().cullMs;
    }
    state.counters["module_ms"] = benchmark::Counter(moduleMs / double(frame ? frame : 1));
}

osg::Node* generated()
{
    static osg::ref_ptr<osg::Group> content = generatedContent();
    return content.get();
}

void BM_GeneratedPlain(benchmark::State& state)
{
    runCulls(state, generated(), Plain);
}
void BM_GeneratedGroup(benchmark::State& state)
{
    runCulls(state, generated(), Group);
}
void BM_GeneratedCullVisitor(benchmark::State& state)
{
    runCulls(state, generated(), Visitor);
}
void BM_MapPlain(benchmark::State& state)
{
    runCulls(state, mapContent().get(), Plain);
}
void BM_MapGroup(benchmark::State& state)
{
    runCulls(state, mapContent().get(), Group);
}
void BM_MapCullVisitor(benchmark::State& state)
{
    runCulls(state, mapContent().get(), Visitor);
}
} // namespace

BENCHMARK(BM_GeneratedPlain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeneratedGroup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeneratedCullVisitor)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MapPlain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MapGroup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MapCullVisitor)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
