// SPDX-License-Identifier: MIT
#pragma once
// What a bench run found: the run's description and one row of metrics per mode (DESIGN.md's
// metrics table; exact definitions in docs/benchmark.md). Unset optionals are metrics with no
// meaning in this run (a zero denominator, a baseline mode not run) and print as null.
#include "BenchMode.h"
#include "Explain.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::bench
{
// Mis-drawn pixels (docs/benchmark.md, "Mis-drawn pixels"): pixels of the oracle's exact ID image
// at the display resolution whose object the mode culled, i.e. pixels that show the wrong thing.
struct MisdrawnPixels
{
    // Upper bounds (inclusive) of the histogram bins of pixels per frame: 0, 1-4, 5-16, 17-64, 65-256,
    // 257-1024; the last bin holds everything above.
    static constexpr std::array<std::uint64_t, 6> BinUpperBounds = {0, 4, 16, 64, 256, 1024};
    static constexpr std::size_t Bins = BinUpperBounds.size() + 1;

    std::uint32_t framesWithAny = 0;
    std::uint64_t maxPerFrame = 0;
    std::optional<double> meanPerFrame;          // over all frames
    std::array<std::uint32_t, Bins> histogram{}; // frames per bin; sums to the number of views
};

struct ModeMetrics
{
    std::uint64_t falseInvisible = 0;        // Σ_v |E(v) \ S(v)|
    std::optional<double> efficacy;          // triangle-weighted, over all views
    std::optional<double> efficacyObjects;   // object-count-weighted
    std::optional<double> occlusionEfficacy; // triangle-weighted, exact-invisible objects in the frustum
    std::optional<double> overestimation;    // Σ tri(S) / Σ tri(E)
    std::optional<double> drawnFraction;     // Σ tri(S) / (views × tri(scene))
    std::optional<double> cullMsMedian;
    std::optional<double> cullMsP99;
    std::optional<double> chainMsMedian; // osgVis's visibility query alone (extraction and OSG's traversal excluded)
    std::optional<double> chainMsP99;
    std::optional<double> fps;
    std::optional<double> speedupVsOsg;     // fps / fps(osg)
    std::optional<double> fpsVsExact;       // fps / fps(exact)
    std::optional<MisdrawnPixels> misdrawn; // nullopt: the oracle gave no pixel counts
};

// What one view drew, for per-view comparisons and plots (docs/benchmark.md, "Per view").
struct ViewRecord
{
    std::uint32_t objects = 0;        // |S(v)|
    std::uint64_t triangles = 0;      // tri(S(v))
    std::uint32_t falseInvisible = 0; // |E(v) \ S(v)|
    double cullMs = 0.0;
    std::uint64_t digest = 0; // FNV-1a 64 of S(v)'s ids, ascending: equal digests, equal sets
};

struct ModeResult
{
    BenchMode mode;
    ModeMetrics metrics;
    std::uint32_t viewsWithFalseInvisible = 0;
    std::vector<ViewRecord> perView;
};

// One point of a cull-only sweep: a module chain's own query time at one observer speed and thread
// count (docs/benchmark.md, "Sweeps").
struct SweepPoint
{
    std::string mode;
    unsigned speed = 1;
    unsigned threads = 1;
    std::size_t views = 0; // timed queries
    std::optional<double> cullMsMedian;
    std::optional<double> cullMsP99;
    std::optional<double> visibleMean; // objects in the answer, mean over the timed queries
};

// Whether a swept mode gave the same visible set for every view at every thread count.
struct SweepDeterminism
{
    std::string mode;
    bool conservative = true;
    bool identicalAcrossThreads = true;
    std::size_t differingViews = 0; // (speed, thread count, view) answers unlike the first thread count's
};

struct SweepReport
{
    std::vector<SweepPoint> points; // mode-major, then speed, then thread count
    std::vector<SweepDeterminism> determinism;
};

// One stage of the progressive cell-portal table (docs/benchmark.md, "Progressive table"): the mean
// over the views of the fraction of the scene's triangles / objects the stage keeps.
struct ProgressiveRow
{
    std::string stage; // "entire model", "cell-to-cell", "cell-to-object", "eye-to-cell", "eye-to-object"
    double drawnFraction = 0.0;
    double objectsFraction = 0.0;
};

// One step of the mask module on its critical frames: median and 99th percentile, ms.
struct StepTiming
{
    std::optional<double> median;
    std::optional<double> p99;
};

// One row of the mask Δ sweep (docs/benchmark.md, "Mask sweep"): a mode with a mask stage, re-run
// cull-only over the bench's views with image-space shrinkage Δ.
struct MaskSweepRow
{
    std::string mode;
    double delta = 0.0; // Δ, frame pixels
    std::size_t views = 0;
    std::size_t criticalFrames = 0;
    std::optional<double> criticalFraction;
    unsigned slowdown = 1;    // the observer K times slower than the rendered pass's views (--mask-slowdown)
    double maxEyeSpeed = 0.0; // V given to the mask stages: the frames' measured top eye speed, units/s
    StepTiming select, rasterize, pyramid, mark; // over the critical frames
    std::optional<double> cullMsCriticalMedian;  // whole chain, critical frames
    std::optional<double> cullMsNonCriticalMedian;
    std::optional<double> drawnFraction; // mean over the views of tri(S) / tri(scene)
    std::optional<double> regionMedian;  // median δ (world units) of the critical frames' masks
    // Critical frames per reason ("first", "stamp-expired", ...), every reason listed.
    std::vector<std::pair<std::string, std::size_t>> criticalReasons;
};

// One row of the threading table: a mode rendered under one OSG threading model, async on or off.
struct ThreadingRow
{
    std::string mode;
    std::string threading; // OSG's name of the model
    bool async = false;
    bool conservative = true;
    std::uint64_t falseInvisible = 0;
    std::uint32_t viewsWithFalseInvisible = 0;
    std::optional<double> drawnFraction;
    std::optional<double> osgVisMsMedian, osgVisMsP99; // the cull thread's time in osgVis per frame
    std::optional<double> cullMsMedian;                 // OSG's whole cull traversal
    std::optional<std::uint32_t> fallbackFrames;        // async rows whose chain answers regions
    std::optional<double> fps;
    std::optional<double> fpsVsSingleThreaded; // fps / fps of the same mode and async, SingleThreaded
    std::optional<std::size_t> differingViews; // sync rows: views drawing another set than the main table's pass
    std::vector<ViewRecord> perView;
};

struct BenchReport
{
    std::string scene;
    std::uint64_t triangles = 0;
    std::size_t objects = 0;
    std::size_t views = 0;
    bool cube = false; // views are six cube faces per walk key
    unsigned width = 0, height = 0;
    std::string command;
    unsigned supersample = 1;
    std::vector<std::uint32_t> viewsWithSupersampleExtras;
    std::uint64_t supersampleExtras = 0;
    std::vector<ModeResult> modes; // empty with --cull-only
    SweepReport sweeps;
    std::vector<ProgressiveRow> progressive; // empty unless a mode has a cellportal stage
    std::vector<MaskSweepRow> maskSweep;     // empty without --mask-deltas
    std::vector<ThreadingRow> threading;     // empty without --threading / --async
    // --report: side-by-side pictures written beside index.html (file names), the views they show
    // and the two modes they compare.
    std::vector<std::string> pictures;
    std::vector<std::size_t> pictureViews;
    std::string pictureBaseline, pictureMode;
    std::optional<Explanation> explanation; // --explain
};

} // namespace osgVis::bench
