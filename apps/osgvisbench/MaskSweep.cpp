// SPDX-License-Identifier: MIT
#include "MaskSweep.h"

#include "BenchView.h"
#include "SampleStatistics.h"

#include <osgVis/core/api/ModuleRegistry.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace osgVis::bench
{
namespace
{
using Reason = core::MaskModule::CriticalReason;

// Every reason a frame can be critical for, in the order of the enum (None excluded).
constexpr std::array<std::pair<Reason, const char*>, 6> CriticalReasons = {{
    {Reason::First, "first"},
    {Reason::StampExpired, "stamp-expired"},
    {Reason::LeftRegion, "left-region"},
    {Reason::Turned, "turned"},
    {Reason::OccluderGone, "occluder-gone"},
    {Reason::ViewChanged, "view-changed"},
}};

std::vector<std::string> chainStages(const std::string& chain)
{
    std::vector<std::string> stages;
    std::stringstream in(chain);
    std::string stage;
    while (std::getline(in, stage, ','))
        stages.push_back(stage);
    return stages;
}

// Per-frame samples of one (mode, Δ) run.
struct MaskRun
{
    std::vector<double> selectMs, rasterizeMs, pyramidMs, markMs, delta; // critical frames only
    std::vector<double> criticalCullMs, nonCriticalCullMs;
    std::array<std::size_t, CriticalReasons.size()> reasonFrames{};
    double drawnFractionSum = 0.0;
    std::size_t views = 0;

    void add(const core::MaskModule::Statistics& statistics, double cullMs)
    {
        ++views;
        if (statistics.critical == Reason::None)
        {
            nonCriticalCullMs.push_back(cullMs);
            return;
        }
        criticalCullMs.push_back(cullMs);
        selectMs.push_back(statistics.selectMs);
        rasterizeMs.push_back(statistics.rasterizeMs);
        pyramidMs.push_back(statistics.pyramidMs);
        markMs.push_back(statistics.markMs);
        delta.push_back(statistics.delta);
        for (std::size_t r = 0; r < CriticalReasons.size(); ++r)
            if (CriticalReasons[r].first == statistics.critical)
                ++reasonFrames[r];
    }
};

StepTiming stepTiming(const std::vector<double>& samples)
{
    const std::vector<double> sorted = sortedFinite(samples);
    return {median(sorted), percentile(sorted, 0.99)};
}

double drawnFraction(const core::Scene& scene, const core::VisibleSet& visible)
{
    const double total = double(scene.totalTriangles());
    if (total <= 0.0)
        return 0.0;
    double drawn = 0.0;
    for (const core::SceneObject& object : scene.objects)
        if (visible.test(object.id))
            drawn += double(object.triangleCount);
    return drawn / total;
}

MaskRun runMaskChain(const std::string& chainName, double delta, double maxEyeSpeed, const core::Scene& scene,
                     const std::vector<core::View>& views)
{
    core::MaskModule* mask = nullptr;
    core::ModuleChain chain = createMaskChain(chainName, delta, mask, maxEyeSpeed);
    chain.setScene(scene);
    MaskRun run;
    core::VisibleSet visible;
    // note: no warm-up query: the first frame is critical ("first") and its cost is part of the walk
    for (const core::View& view : views)
    {
        const auto start = std::chrono::steady_clock::now();
        chain.cull(view, visible);
        const auto end = std::chrono::steady_clock::now();
        run.add(mask->lastStatistics(), std::chrono::duration<double, std::milli>(end - start).count());
        run.drawnFractionSum += drawnFraction(scene, visible);
    }
    return run;
}

MaskSweepRow summarize(const std::string& mode, double delta, unsigned slowdown, double maxEyeSpeed,
                       const MaskRun& run)
{
    MaskSweepRow row;
    row.mode = mode;
    row.delta = delta;
    row.slowdown = slowdown;
    row.maxEyeSpeed = maxEyeSpeed;
    row.views = run.views;
    row.criticalFrames = run.criticalCullMs.size();
    if (run.views != 0)
    {
        row.criticalFraction = double(row.criticalFrames) / double(run.views);
        row.drawnFraction = run.drawnFractionSum / double(run.views);
    }
    row.select = stepTiming(run.selectMs);
    row.rasterize = stepTiming(run.rasterizeMs);
    row.pyramid = stepTiming(run.pyramidMs);
    row.mark = stepTiming(run.markMs);
    row.regionMedian = median(sortedFinite(run.delta));
    row.cullMsCriticalMedian = median(sortedFinite(run.criticalCullMs));
    row.cullMsNonCriticalMedian = median(sortedFinite(run.nonCriticalCullMs));
    for (std::size_t r = 0; r < CriticalReasons.size(); ++r)
        row.criticalReasons.emplace_back(CriticalReasons[r].second, run.reasonFrames[r]);
    return row;
}
} // namespace

core::Walk slowedWalk(const core::Walk& walk, unsigned slowdown)
{
    if (slowdown == 0)
        throw std::invalid_argument("slowedWalk: the slowdown must be at least 1");
    const std::size_t keys = walk.keys.size();
    if (slowdown > 1 && keys != 0 && (keys - 1) * std::size_t(slowdown) + 1 > MaxMaskSweepFrames)
        throw std::length_error("--mask-slowdown " + std::to_string(slowdown) + " over " + std::to_string(keys) +
                                " views makes " + std::to_string((keys - 1) * std::size_t(slowdown) + 1) +
                                " frames, more than " + std::to_string(MaxMaskSweepFrames) +
                                ": give fewer --views or a smaller slowdown");
    if (slowdown == 1 || keys < 2)
        return walk;
    core::Walk slowed = walk;
    slowed.keys.clear();
    slowed.keys.reserve((keys - 1) * slowdown + 1);
    const double start = walk.keys.front().time;
    double segmentStart = start;
    for (std::size_t k = 0; k + 1 < keys; ++k)
    {
        const core::WalkKey& from = walk.keys[k];
        const core::WalkKey& to = walk.keys[k + 1];
        const double interval = to.time - from.time;
        for (unsigned f = 0; f < slowdown; ++f)
        {
            const double along = double(f) / double(slowdown);
            core::WalkKey frame = from;
            frame.eye = from.eye + along * (to.eye - from.eye);
            frame.center = frame.eye + (from.center - from.eye);
            frame.time = segmentStart + double(f) * interval;
            slowed.keys.push_back(frame);
        }
        segmentStart += double(slowdown) * interval;
    }
    slowed.keys.push_back(walk.keys.back());
    slowed.keys.back().time = segmentStart;
    return slowed;
}

double observedMaxEyeSpeed(const core::Walk& walk)
{
    double fastest = 0.0;
    for (std::size_t k = 0; k + 1 < walk.keys.size(); ++k)
    {
        const double interval = walk.keys[k + 1].time - walk.keys[k].time;
        if (interval > 0.0)
            fastest = std::max(fastest, glm::length(walk.keys[k + 1].eye - walk.keys[k].eye) / interval);
    }
    return std::max(1.01 * fastest, 1e-6);
}

std::optional<core::MaskOptions> maskModeOptions(const std::string& moduleName, double shrinkPixels,
                                                 std::optional<double> maxEyeSpeed)
{
    if (!core::hasModule(moduleName))
        return std::nullopt;
    // The registry is the one authority on a mode's options; only Δ (and V) change here.
    const std::unique_ptr<core::VisibilityModule> module = core::createModule(moduleName);
    const auto* mask = dynamic_cast<const core::MaskModule*>(module.get());
    if (!mask)
        return std::nullopt;
    core::MaskOptions options = mask->options();
    options.shrinkPixels = shrinkPixels;
    if (maxEyeSpeed)
        options.maxEyeSpeed = *maxEyeSpeed;
    return options;
}

bool hasMaskStage(const std::string& chain)
{
    for (const std::string& stage : chainStages(chain))
        if (maskModeOptions(stage, 0.0))
            return true;
    return false;
}

core::ModuleChain createMaskChain(const std::string& chain, double shrinkPixels, core::MaskModule*& maskStage,
                                  std::optional<double> maxEyeSpeed)
{
    core::ModuleChain modules;
    maskStage = nullptr;
    for (const std::string& stage : chainStages(chain))
    {
        if (const std::optional<core::MaskOptions> options = maskModeOptions(stage, shrinkPixels, maxEyeSpeed))
        {
            auto mask = std::make_unique<core::MaskModule>(*options);
            maskStage = mask.get();
            modules.add(std::move(mask));
        }
        else
            modules.add(core::createModule(stage));
    }
    return modules;
}

std::vector<MaskSweepRow> runMaskSweep(const core::Scene& scene, const core::Walk& walk,
                                       const std::vector<BenchMode>& modes, const std::vector<double>& deltas,
                                       unsigned slowdown)
{
    const core::Walk frames = slowedWalk(walk, slowdown);
    const std::vector<core::View> views = makeCoreViews(frames);
    std::vector<MaskSweepRow> rows;
    if (views.empty())
        return rows;
    const double maxEyeSpeed = observedMaxEyeSpeed(frames);
    std::cerr << "mask sweep: observer " << slowdown << "x slower, " << views.size() << " frames from "
              << walk.keys.size() << " views, V = " << maxEyeSpeed << " units/s (measured over the frames)"
              << std::endl;
    for (const BenchMode& mode : modes)
    {
        if (mode.kind != BenchMode::Kind::ModuleChain || !hasMaskStage(mode.chain))
            continue;
        for (double delta : deltas)
        {
            std::cerr << "mask sweep " << mode.name << ": delta " << delta << " px, " << views.size() << " frames"
                      << std::endl;
            rows.push_back(summarize(mode.name, delta, slowdown, maxEyeSpeed, runMaskChain(mode.chain, delta, maxEyeSpeed, scene, views)));
        }
    }
    return rows;
}
} // namespace osgVis::bench
