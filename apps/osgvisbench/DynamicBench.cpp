// SPDX-License-Identifier: MIT
#include "DynamicBench.h"

#include <SceneSource.h>
#include "BenchRun.h"
#include "BenchViewer.h"
#include "DynamicWalk.h"
#include "EmittedObjects.h"
#include "Metrics.h"
#include "ModeGraph.h"
#include "ModePass.h"
#include "OracleReference.h"



#include <iostream>
#include <stdexcept>

namespace osgVis::bench
{
namespace
{
// `set` over `size` ids (ids only grow from frame to frame).
core::VisibleSet grown(const core::VisibleSet& set, std::size_t size)
{
    core::VisibleSet out(size);
    for (core::ObjectId id : set.ids())
        out.set(id);
    return out;
}

// Each frame's extraction of the changing graph, ids stable across frames, and the oracle's visible
// set of each frame translated into them.
struct DynamicReference
{
    std::vector<osg::ref_ptr<const ExtractedScene>> frames;
    OracleReference oracle;
    core::Scene objects; // every object as it last existed (removed ones keep their triangles)
};

DynamicReference computeDynamicReference(osg::Group& root, DynamicWalk& dynamic, const std::vector<BenchView>& views,
                                         const core::Walk& walk, unsigned supersample)
{
    DynamicReference out;
    ExtractionOptions options;
    options.keepTriangles = false;
    dynamic.reset();
    osg::ref_ptr<ExtractedScene> current = extractScene(root, options);
    for (std::size_t v = 0; v < views.size(); ++v)
    {
        if (dynamic.advanceTo(v))
            current = reextractScene(root, *current, options);
        out.frames.push_back(current);
        OracleReference frame = computeOracleReference(root, *current, {views[v]}, walk.width, walk.height, supersample);
        if (v == 0)
        {
            out.oracle = std::move(frame);
            continue;
        }
        if (!frame.viewsWithSupersampleExtras.empty())
            out.oracle.viewsWithSupersampleExtras.push_back(std::uint32_t(v));
        out.oracle.supersampleExtras += frame.supersampleExtras;
        out.oracle.views.push_back(std::move(frame.views.front()));
    }
    const std::size_t count = current->scene.objects.size();
    out.objects.objects.resize(count);
    for (const auto& frame : out.frames)
        for (const core::SceneObject& object : frame->scene.objects)
            if (!frame->removed(object.id))
                out.objects.objects[object.id] = object;
    for (core::ObjectId id = 0; id < count; ++id)
        out.objects.objects[id].id = id;
    for (ViewReference& view : out.oracle.views)
    {
        view.exact = grown(view.exact, count);
        view.inFrustum = grown(view.inFrustum, count);
    }
    return out;
}

// One mode over the dynamic walk: the same changes before each frame, S(v) in frame v's ids.
PassResult renderDynamicPass(BenchViewer& viewer, osg::Node& graph, DynamicWalk& dynamic,
                             const std::vector<BenchView>& views, const DynamicReference& reference)
{
    PassResult pass;
    dynamic.reset();
    viewer.renderFrame(views.front()); // priming frame, as renderModePass
    const std::size_t count = reference.objects.objects.size();
    for (std::size_t v = 0; v < views.size(); ++v)
    {
        // note: as an application would, the walk only edits the graph; the kit finds the changes
        dynamic.advanceTo(v);
        const BenchViewer::FrameTiming timing = viewer.renderFrame(views[v]);
        pass.renderSeconds += timing.seconds;
        pass.cullMs.push_back(timing.cullMs);
        EmittedObjects emittedObjects(*reference.frames[v]);
        core::VisibleSet emitted(reference.frames[v]->scene.objects.size());
        emittedObjects.collect(viewer.lastRenderStage(), views[v].view, emitted);
        pass.emitted.push_back(grown(emitted, count));
        pass.unmatchedLeaves += emittedObjects.unmatchedLeaves();
    }
    return pass;
}
} // namespace

BenchReport runDynamicBench(const BenchOptions& options, const std::vector<BenchMode>& modes)
{
    for (const BenchMode& mode : modes)
        if (mode.kind == BenchMode::Kind::OcclusionQueries || mode.kind == BenchMode::Kind::Exact)
            throw std::invalid_argument("--dynamic runs osg and module-chain modes only, not '" + mode.name + "'");

    const apps::LoadedScene scene = loadBenchScene(options);
    const core::Walk walk = benchWalk(scene.walk, options);
    const std::vector<BenchView> views = makeBenchViews(walk);
    if (views.empty())
        throw std::runtime_error("the walk has no views");

    // The model under a root that also holds the traffic and the dropped buildings.
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->setName("dynamic scene");
    root->addChild(scene.model);
    DynamicWalk dynamic(*root, *scene.objects, scene.walk, views.size(), options.seed);

    const DynamicReference reference = computeDynamicReference(*root, dynamic, views, walk, options.supersample);
    const DynamicCounts counts = dynamic.counts();
    std::cerr << "scene: " << scene.name << " (dynamic: " << reference.objects.objects.size()
              << " objects over the walk), walk: " << scene.walkSource << ", " << views.size() << " views at "
              << walk.width << "x" << walk.height << std::endl;
    std::cout << "dynamic changes: " << counts.total() << " (" << counts.carMoves << " car moves, "
              << counts.buildingsDropped << " buildings dropped, " << counts.buildingsRemoved
              << " buildings removed)" << std::endl;

    BenchReport report;
    report.scene = scene.name;
    report.triangles = reference.objects.totalTriangles();
    report.objects = reference.objects.objects.size();
    report.cube = options.cube;
    report.width = walk.width;
    report.height = walk.height;
    report.command = options.commandLine;
    report.supersample = reference.oracle.supersample;
    report.viewsWithSupersampleExtras = reference.oracle.viewsWithSupersampleExtras;
    report.supersampleExtras = reference.oracle.supersampleExtras;

    BenchViewer viewer(walk.width, walk.height, walk.projection, *root);
    for (const BenchMode& mode : modes)
    {
        osg::ref_ptr<osg::Node> graph = buildModeGraph(mode, *root, *reference.frames.front());
        viewer.setSceneData(graph.get());
        const PassResult pass = renderDynamicPass(viewer, *graph, dynamic, views, reference);
        viewer.setSceneData(nullptr);
        if (pass.unmatchedLeaves != 0)
            std::cerr << "osgvisbench: warning: " << mode.name << ": " << pass.unmatchedLeaves
                      << " drawn leaves matched no instance of their drawable" << std::endl;
        report.modes.push_back(measureMode(mode, reference.objects, reference.oracle, pass));
    }
    relateToBaselines(report.modes);
    report.views = views.size();
    return report;
}
} // namespace osgVis::bench
