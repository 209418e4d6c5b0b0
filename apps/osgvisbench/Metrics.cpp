// SPDX-License-Identifier: MIT
#include "Metrics.h"

#include "Fnv1a.h"
#include "MisdrawnPixels.h"
#include "SampleStatistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace osgVis::bench
{
namespace
{
std::optional<double> ratio(double numerator, double denominator)
{
    if (denominator <= 0.0 || !std::isfinite(numerator) || !std::isfinite(denominator))
        return std::nullopt;
    return numerator / denominator;
}

// Culled-and-hidden over hidden, by object count and by triangles.
struct CullTally
{
    double hiddenObjects = 0, culledHiddenObjects = 0;
    double hiddenTriangles = 0, culledHiddenTriangles = 0;

    void add(bool culled, double triangles)
    {
        hiddenObjects += 1.0;
        hiddenTriangles += triangles;
        if (culled)
        {
            culledHiddenObjects += 1.0;
            culledHiddenTriangles += triangles;
        }
    }
};

// FNV-1a 64 over the ids of the set in ascending order, each as 4 little-endian bytes.
std::uint64_t setDigest(const core::VisibleSet& set)
{
    std::uint64_t hash = Fnv1aSeed;
    for (const core::ObjectId id : set.ids())
    {
        const unsigned char bytes[4] = {static_cast<unsigned char>(id), static_cast<unsigned char>(id >> 8),
                                        static_cast<unsigned char>(id >> 16), static_cast<unsigned char>(id >> 24)};
        hash = fnv1a(hash, bytes, sizeof bytes);
    }
    return hash;
}

const ModeResult* findKind(const std::vector<ModeResult>& results, BenchMode::Kind kind)
{
    for (const ModeResult& result : results)
        if (result.mode.kind == kind)
            return &result;
    return nullptr;
}
} // namespace

ModeResult measureMode(const BenchMode& mode, const core::Scene& scene, const OracleReference& reference,
                       const PassResult& pass)
{
    ModeResult result;
    result.mode = mode;
    CullTally all, inFrustum;
    double drawnTriangles = 0.0, exactTriangles = 0.0;
    MisdrawnTally misdrawn;
    for (std::size_t v = 0; v < reference.views.size(); ++v)
    {
        const ViewReference& view = reference.views[v];
        const core::VisibleSet& drawn = pass.emitted[v];
        std::uint64_t missed = view.unknownVisible;
        ViewRecord record;
        for (const core::SceneObject& object : scene.objects)
        {
            const bool visible = view.exact.test(object.id);
            const bool emitted = drawn.test(object.id);
            const double triangles = double(object.triangleCount);
            if (emitted)
            {
                drawnTriangles += triangles;
                ++record.objects;
                record.triangles += object.triangleCount;
            }
            if (visible)
            {
                exactTriangles += triangles;
                if (!emitted)
                    ++missed;
                continue;
            }
            all.add(!emitted, triangles);
            if (view.inFrustum.test(object.id))
                inFrustum.add(!emitted, triangles);
        }
        if (reference.pixelCounts)
            misdrawn.add(misdrawnPixels(view, drawn));
        result.metrics.falseInvisible += missed;
        if (missed != 0)
            ++result.viewsWithFalseInvisible;
        record.falseInvisible = std::uint32_t(missed);
        record.cullMs = v < pass.cullMs.size() ? pass.cullMs[v] : 0.0;
        record.digest = setDigest(drawn);
        result.perView.push_back(record);
    }

    ModeMetrics& m = result.metrics;
    m.efficacy = ratio(all.culledHiddenTriangles, all.hiddenTriangles);
    m.efficacyObjects = ratio(all.culledHiddenObjects, all.hiddenObjects);
    m.occlusionEfficacy = ratio(inFrustum.culledHiddenTriangles, inFrustum.hiddenTriangles);
    m.overestimation = ratio(drawnTriangles, exactTriangles);
    m.drawnFraction = ratio(drawnTriangles, double(reference.views.size()) * double(scene.totalTriangles()));
    const std::vector<double> cullMs = sortedFinite(pass.cullMs);
    m.cullMsMedian = median(cullMs);
    m.cullMsP99 = percentile(cullMs, 0.99);
    const std::vector<double> chainMs = sortedFinite(pass.chainMs);
    m.chainMsMedian = median(chainMs);
    m.chainMsP99 = percentile(chainMs, 0.99);
    m.fps = ratio(double(pass.emitted.size()), pass.renderSeconds);
    if (reference.pixelCounts)
        m.misdrawn = misdrawn.summary();
    return result;
}

void relateToBaselines(std::vector<ModeResult>& results)
{
    const ModeResult* osg = findKind(results, BenchMode::Kind::OsgDefault);
    const ModeResult* exact = findKind(results, BenchMode::Kind::Exact);
    // 0 stands for "no baseline": ratio() answers nullopt for it.
    const double osgFps = osg ? osg->metrics.fps.value_or(0.0) : 0.0;
    const double exactFps = exact ? exact->metrics.fps.value_or(0.0) : 0.0;
    for (ModeResult& result : results)
    {
        if (!result.metrics.fps)
            continue;
        result.metrics.speedupVsOsg = ratio(*result.metrics.fps, osgFps);
        result.metrics.fpsVsExact = ratio(*result.metrics.fps, exactFps);
    }
}

const ModeResult* bestCullingMode(const std::vector<ModeResult>& modes)
{
    const ModeResult* best = nullptr;
    for (const ModeResult& result : modes)
        if (result.mode.kind == BenchMode::Kind::ModuleChain && result.mode.conservative &&
            result.metrics.falseInvisible == 0 && result.metrics.fps &&
            (!best || *result.metrics.fps > *best->metrics.fps))
            best = &result;
    return best;
}

const ModeResult* baselineMode(const std::vector<ModeResult>& modes)
{
    const ModeResult* osg = findKind(modes, BenchMode::Kind::OsgDefault);
    return osg ? osg : (modes.empty() ? nullptr : &modes.front());
}

std::string bestModeSummary(const BenchReport& report)
{
    const ModeResult* best = bestCullingMode(report.modes);
    const ModeResult* base = baselineMode(report.modes);
    if (!best || !base || best == base)
        return {};
    const ModeMetrics &b = best->metrics, &o = base->metrics;
    const auto ratioText = [](const std::optional<double>& numerator, const std::optional<double>& denominator)
    {
        const std::optional<double> r =
            numerator && denominator ? ratio(*numerator, *denominator) : std::optional<double>();
        char text[32];
        std::snprintf(text, sizeof text, r ? "%.2fx" : "-", r.value_or(0.0));
        return std::string(text);
    };
    const auto ms = [](const std::optional<double>& value)
    {
        char text[32];
        std::snprintf(text, sizeof text, value ? "%.2f ms" : "- ms", value.value_or(0.0));
        return std::string(text);
    };
    return "best mode: " + best->mode.name + " vs " + base->mode.name + ": " + ratioText(b.fps, o.fps) +
           " the frame rate (frame time " + ratioText(o.fps, b.fps) + "), " + ratioText(b.drawnFraction, o.drawnFraction) +
           " the drawn triangles, cull " + ms(b.cullMsMedian) + " median (" + base->mode.name + " " + ms(o.cullMsMedian) +
           "), " + std::to_string(b.falseInvisible) + " false-invisible against the oracle" +
           (b.fps && o.fps && *b.fps < *o.fps ? " (no culling mode beat " + base->mode.name + " here)" : "");
}
} // namespace osgVis::bench
