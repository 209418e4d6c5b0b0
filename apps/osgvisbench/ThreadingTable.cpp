// SPDX-License-Identifier: MIT
#include "ThreadingTable.h"

#include "BenchViewer.h"
#include "EmittedObjects.h"
#include "Metrics.h"
#include "ModeGraph.h"
#include "ModePass.h"
#include "SampleStatistics.h"

#include <ThreadingModel.h>

#include <osgVis/VisibilityGroup>

namespace osgVis::bench
{
namespace
{
ThreadingRow measureRow(const BenchMode& mode, const std::string& threading, bool async, const core::Scene& model,
                        const OracleReference& reference, const PassResult& pass, const std::vector<double>& osgVisMs,
                        std::uint32_t fallbacks, bool regions,
                        const std::map<std::string, std::vector<core::VisibleSet>>& mainPasses)
{
    const ModeResult measured = measureMode(mode, model, reference, pass);
    ThreadingRow row;
    row.mode = mode.name;
    row.threading = threading;
    row.async = async;
    row.conservative = mode.conservative;
    row.falseInvisible = measured.metrics.falseInvisible;
    row.viewsWithFalseInvisible = measured.viewsWithFalseInvisible;
    row.drawnFraction = measured.metrics.drawnFraction;
    row.cullMsMedian = measured.metrics.cullMsMedian;
    row.fps = measured.metrics.fps;
    row.perView = measured.perView;
    const std::vector<double> sorted = sortedFinite(osgVisMs);
    row.osgVisMsMedian = median(sorted);
    row.osgVisMsP99 = percentile(sorted, 0.99);
    if (async && regions)
        row.fallbackFrames = fallbacks;
    const auto main = mainPasses.find(mode.name);
    if (!async && main != mainPasses.end() && main->second.size() == pass.emitted.size())
    {
        std::size_t differing = 0;
        for (std::size_t v = 0; v < pass.emitted.size(); ++v)
            differing += !(pass.emitted[v] == main->second[v]);
        row.differingViews = differing;
    }
    return row;
}
} // namespace

std::vector<ThreadingRow> runThreadingTable(const BenchOptions& options, const std::vector<BenchMode>& modes,
                                            const apps::LoadedScene& scene, const core::Walk& walk,
                                            const std::vector<BenchView>& views, const OracleReference& reference,
                                            const std::map<std::string, std::vector<core::VisibleSet>>& mainPasses)
{
    const std::vector<std::string> threadings =
        options.threading.empty() ? std::vector<std::string>{"SingleThreaded"} : options.threading;
    const std::vector<bool> asyncSettings = options.async.empty() ? std::vector<bool>{false} : options.async;
    const core::Scene& model = scene.objects->scene;
    EmittedObjects emittedObjects(*scene.objects);
    std::vector<ThreadingRow> rows;
    for (const std::string& threading : threadings)
    {
        BenchViewer viewer(walk.width, walk.height, walk.projection, *scene.model,
                           apps::parseThreadingModel(threading));
        for (const BenchMode& mode : modes)
        {
            if (mode.kind != BenchMode::Kind::OsgDefault && mode.kind != BenchMode::Kind::ModuleChain)
                continue; // osg-oq and exact are references, not cullers to thread
            for (const bool async : asyncSettings)
            {
                if (async && mode.kind != BenchMode::Kind::ModuleChain)
                    continue;
                osg::ref_ptr<osg::Node> graph =
                    buildModeGraph(mode, *scene.model, *scene.objects, async, asyncOptionsOf(options));
                auto* group = dynamic_cast<VisibilityGroup*>(graph.get());
                viewer.setSceneData(graph.get());
                std::vector<double> osgVisMs;
                std::uint32_t fallbacks = 0;
                bool regions = false;
                const std::string label = mode.name + " " + threading + (async ? " async" : "");
                const PassResult pass = renderModePass(
                    label, viewer, views, emittedObjects, model.objects.size(), [](std::size_t) {},
                    [&](std::size_t)
                    {
                        if (!group)
                            return;
                        const CullStatistics figures = group->getLastStatistics();
                        osgVisMs.push_back(figures.cullMs);
                        fallbacks += figures.asyncFallback;
                        regions = regions || figures.async;
                    });
                viewer.setSceneData(nullptr);
                rows.push_back(
                    measureRow(mode, threading, async, model, reference, pass, osgVisMs, fallbacks, regions, mainPasses));
            }
        }
    }
    for (ThreadingRow& row : rows)
        for (const ThreadingRow& single : rows)
            if (single.threading == "SingleThreaded" && single.mode == row.mode && single.async == row.async &&
                row.fps && single.fps && *single.fps > 0.0)
                row.fpsVsSingleThreaded = *row.fps / *single.fps;
    return rows;
}
} // namespace osgVis::bench
