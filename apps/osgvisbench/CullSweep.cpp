// SPDX-License-Identifier: MIT
#include "CullSweep.h"

#include "BenchView.h"
#include "DerivedWalks.h"
#include "SampleStatistics.h"

#include <osgVis/core/api/ModuleRegistry.h>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <iostream>

namespace osgVis::bench
{
namespace
{
struct ChainRun
{
    std::vector<double> cullMs;            // per view
    std::vector<core::VisibleSet> answers; // per view
    double visibleSum = 0.0;
};

// A fresh chain (no temporal state from another run) over `views` with at most `threads` TBB threads.
ChainRun runChain(const std::string& chainName, const core::Scene& scene, const std::vector<core::View>& views,
                  unsigned threads)
{
    // note: global_control caps every arena; the explicit arena also gets the requested count where
    // it exceeds TBB's default (more threads than cores).
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    tbb::task_arena arena(static_cast<int>(threads));
    ChainRun run;
    arena.execute(
        [&]
        {
            core::ModuleChain chain = core::createChain(chainName);
            chain.setScene(scene);
            core::VisibleSet visible;
            // Warm-up: whatever a module builds on its first query is set-up, not per-frame cost.
            chain.cull(views.front(), visible);
            for (const core::View& view : views)
            {
                const auto start = std::chrono::steady_clock::now();
                chain.cull(view, visible);
                const auto end = std::chrono::steady_clock::now();
                run.cullMs.push_back(std::chrono::duration<double, std::milli>(end - start).count());
                run.visibleSum += double(visible.count());
                run.answers.push_back(visible);
            }
        });
    return run;
}

std::size_t differingAnswers(const std::vector<core::VisibleSet>& reference, const std::vector<core::VisibleSet>& other)
{
    std::size_t differing = 0;
    for (std::size_t v = 0; v < reference.size(); ++v)
        if (!(reference[v] == other[v]))
            ++differing;
    return differing;
}

SweepPoint summarize(const std::string& mode, unsigned speed, unsigned threads, const ChainRun& run)
{
    SweepPoint point;
    point.mode = mode;
    point.speed = speed;
    point.threads = threads;
    point.views = run.cullMs.size();
    const std::vector<double> sorted = sortedFinite(run.cullMs);
    point.cullMsMedian = median(sorted);
    point.cullMsP99 = percentile(sorted, 0.99);
    if (point.views != 0)
        point.visibleMean = run.visibleSum / double(point.views);
    return point;
}
} // namespace

SweepReport runCullSweeps(const core::Scene& scene, const core::Walk& walk, const std::vector<BenchMode>& modes,
                          const SweepSettings& settings)
{
    const std::vector<unsigned> speeds = settings.speeds.empty() ? std::vector<unsigned>{1} : settings.speeds;
    const std::vector<unsigned> threadCounts =
        settings.threads.empty() ? std::vector<unsigned>{unsigned(tbb::info::default_concurrency())} : settings.threads;
    SweepReport report;
    for (const BenchMode& mode : modes)
    {
        if (mode.kind != BenchMode::Kind::ModuleChain)
            continue;
        SweepDeterminism determinism;
        determinism.mode = mode.name;
        determinism.conservative = mode.conservative;
        for (unsigned speed : speeds)
        {
            const core::Walk paced = pacedWalk(walk, speed);
            const std::vector<core::View> views = makeCoreViews(settings.cube ? cubeFaceWalk(paced) : paced);
            if (views.empty())
                continue;
            std::vector<core::VisibleSet> firstAnswers;
            for (std::size_t t = 0; t < threadCounts.size(); ++t)
            {
                std::cerr << "sweep " << mode.name << ": speed " << speed << "x, " << threadCounts[t] << " threads, "
                          << views.size() << " views" << std::endl;
                ChainRun run = runChain(mode.chain, scene, views, threadCounts[t]);
                report.points.push_back(summarize(mode.name, speed, threadCounts[t], run));
                if (t == 0)
                    firstAnswers = std::move(run.answers);
                else
                    determinism.differingViews += differingAnswers(firstAnswers, run.answers);
            }
        }
        determinism.identicalAcrossThreads = determinism.differingViews == 0;
        report.determinism.push_back(determinism);
    }
    return report;
}
} // namespace osgVis::bench
