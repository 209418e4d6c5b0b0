// SPDX-License-Identifier: MIT
#include "BenchRun.h"

#include "BenchViewer.h"
#include "CullSweep.h"
#include "DerivedWalks.h"
#include "EmittedObjects.h"
#include "ExactReplay.h"
#include "MaskSweep.h"
#include "Metrics.h"
#include "ModeGraph.h"
#include "ModePass.h"
#include "OracleCache.h"
#include "OracleReference.h"
#include "ProgressiveTable.h"
#include "TextFile.h"
#include "ThreadingTable.h"
#include "ViewPictures.h"

#include <SceneSource.h>

#include <iostream>
#include <map>
#include <memory>

namespace osgVis::bench
{
apps::LoadedScene loadBenchScene(const BenchOptions& options)
{
    apps::SceneRequest source;
    source.scenePath = options.sceneFile;
    source.generateKind = options.generateKind;
    source.triangles = options.triangles;
    source.seed = options.seed;
    source.forestLayout = options.forestLayout;
    source.walkPath = options.walkFile;
    source.width = options.width;
    source.height = options.height;
    return apps::loadScene(source);
}

core::Walk benchWalk(const core::Walk& sceneWalk, const BenchOptions& options)
{
    core::Walk walk = subsampledWalk(sceneWalk, options.views);
    if (options.cube)
        walk = cubeFaceWalk(walk);
    return walk;
}

namespace
{
bool runsMode(const std::vector<BenchMode>& modes, BenchMode::Kind kind)
{
    for (const BenchMode& mode : modes)
        if (mode.kind == kind)
            return true;
    return false;
}

// The oracle, then every mode rendered over `views` in one viewer, measured into report.modes.
void renderModes(BenchReport& report, const apps::LoadedScene& scene, const core::Walk& walk,
                 const std::vector<BenchView>& views, const std::vector<BenchMode>& modes, const BenchOptions& options)
{
    const unsigned supersample = options.supersample;
    const core::Scene& model = scene.objects->scene;
    const OracleReference reference =
        options.oracleCacheDir.empty()
            ? computeOracleReference(*scene.model, *scene.objects, views, walk.width, walk.height, supersample)
            : cachedOracleReference(options.oracleCacheDir, *scene.model, *scene.objects, views, walk.width,
                                    walk.height, supersample);
    report.supersample = reference.supersample;
    report.viewsWithSupersampleExtras = reference.viewsWithSupersampleExtras;
    report.supersampleExtras = reference.supersampleExtras;

    std::unique_ptr<ExactReplay> replay;
    if (runsMode(modes, BenchMode::Kind::Exact))
        replay = std::make_unique<ExactReplay>(reference);

    std::map<std::string, std::vector<core::VisibleSet>> mainPasses; // for the threading table
    const std::vector<std::size_t> pictured =
        options.reportDir.empty() ? std::vector<std::size_t>{}
                                  : pictureViews(views.size(), options.pictures < 0 ? 6u : unsigned(options.pictures));
    std::map<std::string, ModeFrames> frames; // per mode, for the pictures
    std::map<std::string, std::vector<core::VisibleSet>> drawnByMode; // --explain
    {
    BenchViewer viewer(walk.width, walk.height, walk.projection, *scene.model);
    EmittedObjects emittedObjects(*scene.objects);
    for (const BenchMode& mode : modes)
    {
        osg::ref_ptr<osg::Node> graph = buildModeGraph(mode, *scene.model, *scene.objects, false, {}, options.backOff);
        viewer.setSceneData(graph.get());
        const auto pointReplay = [&](std::size_t v)
        {
            if (mode.kind == BenchMode::Kind::Exact)
                replay->setCurrentView(v);
        };
        const PassResult pass =
            renderModePass(mode.name, viewer, views, emittedObjects, model.objects.size(), pointReplay);
        if (!pictured.empty())
            frames[mode.name] =
                captureModeFrames(viewer, views, pictured, emittedObjects, model.objects.size(), pointReplay);
        viewer.setSceneData(nullptr);
        if (pass.unmatchedLeaves != 0)
            std::cerr << "osgvisbench: warning: " << mode.name << ": " << pass.unmatchedLeaves
                      << " drawn leaves matched no instance of their drawable" << std::endl;
        report.modes.push_back(measureMode(mode, model, reference, pass));
        if (options.threadingTable())
            mainPasses[mode.name] = pass.emitted;
        if (options.explain)
            drawnByMode[mode.name] = pass.emitted;
    }
    }
    if (replay && replay->mismatchedQueries() != 0)
        std::cerr << "osgvisbench: warning: exact: the VisibilityGroup numbered objects differently from the "
                     "bench's extraction in "
                  << replay->mismatchedQueries() << " queries; those views drew everything" << std::endl;
    relateToBaselines(report.modes);
    report.views = views.size();
    const ModeResult* best = bestCullingMode(report.modes);
    const ModeResult* baseline = baselineMode(report.modes);
    if (options.explain)
    {
        std::vector<core::VisibleSet> hidden;
        for (const ViewReference& view : reference.views)
        {
            core::VisibleSet set(model.objects.size());
            for (const core::SceneObject& object : model.objects)
                if (view.inFrustum.test(object.id) && !view.exact.test(object.id))
                    set.set(object.id);
            hidden.push_back(std::move(set));
        }
        const osg::ref_ptr<ExtractedScene> withTriangles = extractScene(*scene.model);
        // The never-culled list is about the mode that culls most behind occluders.
        const ModeResult* occluding = nullptr;
        for (const ModeResult& result : report.modes)
            if (result.mode.kind == BenchMode::Kind::ModuleChain && result.mode.conservative &&
                result.metrics.occlusionEfficacy.value_or(0.0) > 0.0 &&
                (!occluding || *result.metrics.occlusionEfficacy > *occluding->metrics.occlusionEfficacy))
                occluding = &result;
        const std::string about = occluding ? occluding->mode.name : std::string();
        report.explanation = explainScene(*withTriangles, about, about.empty() ? std::vector<core::VisibleSet>{}
                                                                                : drawnByMode[about], hidden);
    }
    if (!pictured.empty() && best && baseline && best != baseline)
    {
        report.pictures = writeSideBySide(options.reportDir, frames[baseline->mode.name], frames[best->mode.name],
                                          model, views, pictured);
        report.pictureViews = pictured;
        report.pictureBaseline = baseline->mode.name;
        report.pictureMode = best->mode.name;
    }
    if (options.threadingTable())
        report.threading = runThreadingTable(options, modes, scene, walk, views, reference, mainPasses);
}
} // namespace

BenchReport runBench(const BenchOptions& options, const std::vector<BenchMode>& modes)
{
    if (!options.reportDir.empty())
        createFolder(options.reportDir, "report folder");
    const apps::LoadedScene scene = loadBenchScene(options);
    if (!options.saveWalkFile.empty())
        scene.walk.save(options.saveWalkFile);
    const core::Walk walk = benchWalk(scene.walk, options);
    const std::vector<BenchView> views = makeBenchViews(walk);
    const core::Scene& model = scene.objects->scene;
    std::cerr << "scene: " << scene.name << " (" << model.objects.size() << " objects, " << model.totalTriangles()
              << " triangles), walk: " << scene.walkSource << ", " << views.size() << " views at " << walk.width << "x"
              << walk.height << (options.cube ? " (six cube faces per walk key)" : "") << std::endl;

    BenchReport report;
    report.scene = scene.name;
    report.triangles = model.totalTriangles();
    report.objects = model.objects.size();
    report.cube = options.cube;
    report.width = walk.width;
    report.height = walk.height;
    report.command = options.commandLine;
    report.supersample = options.supersample;
    // note: the shared extraction keeps no triangles; object-space occluders and cells are made of them
    osg::ref_ptr<ExtractedScene> withTriangles;
    if (options.sweeps() || options.maskSweep() || wantsProgressiveTable(modes))
        withTriangles = extractScene(*scene.model);
    // Before the rendered passes: a bake made here is registered, so their cellportal modes reuse it.
    if (wantsProgressiveTable(modes))
        report.progressive = runProgressiveTable(withTriangles->scene, walk);
    if (!options.cullOnly)
        renderModes(report, scene, walk, views, modes, options);
    if (options.sweeps())
    {
        report.sweeps =
            runCullSweeps(withTriangles->scene, scene.walk, modes, {options.speeds, options.threads, options.cube});
        if (report.sweeps.points.empty())
            std::cerr << "osgvisbench: warning: no module-chain mode to sweep (osg, osg-oq and exact are not swept)"
                      << std::endl;
    }
    if (options.maskSweep())
    {
        // The rendered pass's views, so drawn fractions compare with the main table's.
        report.maskSweep = runMaskSweep(withTriangles->scene, walk, modes, options.maskDeltas, options.maskSlowdown);
        if (report.maskSweep.empty())
            std::cerr << "osgvisbench: warning: --mask-deltas: no mode has a mask stage (mask, mask-approx, "
                         "mask-distance)"
                      << std::endl;
    }
    return report;
}
} // namespace osgVis::bench
