#pragma once
// What a bench run found: the run's description and one row of metrics per mode (DESIGN.md's
// metrics table; exact definitions in docs/benchmark.md). Unset optionals are metrics with no
// meaning in this run (a zero denominator, a baseline mode not run) and print as null.
#include "BenchMode.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace osgVis::bench
{
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
    std::optional<double> fps;
    std::optional<double> speedupVsOsg; // fps / fps(osg)
    std::optional<double> fpsVsExact;   // fps / fps(exact)
};

struct ModeResult
{
    BenchMode mode;
    ModeMetrics metrics;
    std::uint32_t viewsWithFalseInvisible = 0;
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
};
} // namespace osgVis::bench
