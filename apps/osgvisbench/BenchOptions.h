// SPDX-License-Identifier: MIT
#pragma once
// Command line of osgvisbench: what scene, which walk, which modes, at what size, and where the
// JSON goes. Parsing only: nothing here loads a file or touches GL.
#include <osgVis/ViewCuller>
#include <osgVis/core/async/AsyncVisibility.h>

#include <CommandLine.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::bench
{
// Bad command line: main prints the message and the usage, and exits with code 2.
using apps::UsageError;

// osgvisbench's subcommands, each a run of its own with only its own options. Without one the
// command is Run and takes every option, the older --dynamic, --paged, --volume, --volume-cells and
// --dump-visible choosing the others, so command lines written before the subcommands still work.
enum class BenchCommand
{
    Run,     // the walk rendered in every mode against the oracle (sweeps, threading table, report)
    Dynamic, // the same while cars drive and buildings come and go (--dynamic)
    Paged,   // a paged database walked with OSG's DatabasePager (--paged)
    Volume,  // the multifocal volume PVS against the volume oracle (--volume)
    Cells,   // a multifocal .pvs's baked cells against the volume oracle (--volume-cells)
    Dump     // the visible sets of every module chain per view, written out (--dump-visible)
};

// The most frames the mask sweep's slowed walk may have (views × --mask-slowdown): a bound on its
// run time and memory.
constexpr std::size_t MaxMaskSweepFrames = 200000;

struct BenchOptions
{
    BenchCommand command = BenchCommand::Run;
    bool commandGiven = false;        // named on the command line (then only its options are known)
    std::string sceneFile;            // --scene FILE (any format osgDB reads)
    std::string generateKind;         // --generate office|city|floor|tetra|forest (instead of --scene)
    std::string forestLayout;         // --layout single|line|dense, with --generate forest
    std::uint64_t triangles = 100000; // --triangles N, with --generate
    std::uint32_t seed = 1;           // --seed S, with --generate
    std::string walkFile;             // --walk FILE; empty: FILE.walk beside the scene, else automatic
    std::string saveWalkFile;         // --save-walk FILE: the walk as loaded or made (before --views)
    std::string dumpVisibleDir;       // --dump-visible DIR: DIR/<mode>.visible per module chain, then exit
    std::vector<std::string> modes;   // --modes a,b,c (a module chain is written a+b)
    unsigned views = 0;               // --views N: subsample the walk evenly; 0 keeps every key
    unsigned width = 0, height = 0;   // --size WxH; 0: the walk's size
    std::string jsonFile;             // --json OUT.json
    std::string oracleCacheDir;       // --oracle-cache DIR: the oracle's exact sets kept between runs (OracleCache)
    std::string reportDir;            // --report DIR: DIR/index.html (and pictures) for people
    int pictures = -1;                // --pictures N: side-by-side pictures in the report; -1: 6
    bool explain = false;             // --explain: why culling does or does not work on the model
    bool backOff = false;             // --backoff on: do no harm in every VisibilityGroup (off: each method alone)
    unsigned supersample = 2;         // --supersample K: the oracle's extra check at K× resolution
    bool cube = false;                // --cube (or --fov 360): six cube-face views per walk key
    std::vector<unsigned> speeds;     // --speeds 1,2,4: cull-only sweep over observer speeds
    std::vector<unsigned> threads;    // --threads 1,2: cull-only sweep over TBB thread counts
    std::vector<double> maskDeltas;   // --mask-deltas 0,1,2: cull-only Δ sweep of the mask modes
    unsigned maskSlowdown = 1;        // --mask-slowdown K: the Δ sweep's observer K times slower
    bool cullOnly = false;            // --cull-only: the sweeps alone, no oracle and no rendering
    bool paged = false;               // --paged: a paged database walked with OSG's DatabasePager (PagedBench)
    PagingOptions paging;             // --paging-requests N, --paging-keep N (with --paged)
    bool dynamic = false;             // --dynamic: cars, dropped and deleted buildings during the walk (DynamicWalk)
    std::vector<std::string> threading; // --threading A,B: OSG threading models of the threading table
    std::vector<bool> async;            // --async on|off|on,off: async visibility settings of that table
    unsigned asyncLookAhead = 4;        // --async-lookahead N: frames of eye path a region covers
    double asyncRegion[3] = {0, 0, 0};  // --async-region X,Y,Z: a region's least size (a bake cell's)
    std::string volume;               // --volume X0,Y0,Z0,X1,Y1,Z1|paper: a volume PVS against the volume oracle
    unsigned planeResolution = 100;   // --plane-resolution N: multifocal planes' pixels (longer side)
    unsigned planesPerDirection = 7;  // --planes N: multifocal planes per face of the volume
    unsigned volumeFaceSize = 512;    // --volume-face N: the volume oracle's cube faces, N×N pixels
    unsigned volumeEyes = 48;         // --volume-eyes N: random interior eyes of the volume oracle
    unsigned volumeRepeat = 3;        // --volume-repeat N: PVS computations timed (the median is reported)
    unsigned volumeCells = 0;         // --volume-cells N: N baked view cells of a multifocal .pvs against the volume oracle
    bool help = false;                // --help
    std::string commandLine;          // argv joined, recorded in the JSON

    bool sweeps() const { return !speeds.empty() || !threads.empty(); }
    bool maskSweep() const { return !maskDeltas.empty(); }
    bool threadingTable() const { return !threading.empty() || !async.empty(); }
};

// Throws UsageError naming the offending argument.
BenchOptions parseBenchOptions(int argc, char** argv);
// --async-lookahead and --async-region as the asynchronous visibility takes them.
core::AsyncOptions asyncOptionsOf(const BenchOptions& options);
// The help of every subcommand (no subcommand: every option), or of one.
std::string benchUsage();
std::string benchUsage(const BenchOptions& options);
} // namespace osgVis::bench
