// SPDX-License-Identifier: MIT
#include "BenchOptions.h"

#include <ThreadingModel.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace osgVis::bench
{
namespace
{
std::string quotedArgument(const std::string& arg)
{
    if (!arg.empty() && arg.find_first_of(" \t\"'\\$") == std::string::npos)
        return arg;
    std::string quoted = "'";
    for (char c : arg)
        quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::uint64_t parseUnsigned(const std::string& flag, const std::string& text)
{
    // note: strtoull accepts a leading '-' and wraps it; reject it here so "--views -3" is an error.
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(flag + " expects a non-negative integer, got '" + text + "'");
    return std::strtoull(text.c_str(), nullptr, 10);
}

std::vector<std::string> splitList(const std::string& text, char separator)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, separator))
        items.push_back(item);
    if (!text.empty() && text.back() == separator)
        items.emplace_back();
    return items;
}

// A comma-separated list of integers in [1, limit], e.g. "--speeds 1,2,4".
std::vector<unsigned> parsePositiveList(const std::string& flag, const std::string& text, unsigned limit)
{
    std::vector<unsigned> values;
    for (const std::string& item : splitList(text, ','))
    {
        const std::uint64_t value = parseUnsigned(flag, item);
        if (value < 1 || value > limit)
            throw UsageError(flag + " values must lie between 1 and " + std::to_string(limit) + ", got '" + item + "'");
        values.push_back(unsigned(value));
    }
    if (values.empty())
        throw UsageError(flag + " is empty");
    return values;
}

// A comma-separated list of numbers in [0, limit], e.g. "--mask-deltas 0,0.5,1,2".
std::vector<double> parseNonNegativeList(const std::string& flag, const std::string& text, double limit)
{
    std::vector<double> values;
    for (const std::string& item : splitList(text, ','))
    {
        // note: digits and one '.' only, so "1e3", "inf", "-1" and "0x2" are all rejected
        const bool number = !item.empty() && item.find_first_not_of("0123456789.") == std::string::npos &&
                            item.find('.') == item.rfind('.') && item != ".";
        if (!number)
            throw UsageError(flag + " expects non-negative numbers, got '" + item + "'");
        const double value = std::strtod(item.c_str(), nullptr);
        if (value > limit)
            throw UsageError(flag + " values must lie between 0 and " + std::to_string(int(limit)) + ", got '" + item +
                             "'");
        values.push_back(value);
    }
    if (values.empty())
        throw UsageError(flag + " is empty");
    return values;
}

void parseSize(const std::string& text, unsigned& width, unsigned& height)
{
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos)
        throw UsageError("--size expects WxH (e.g. 640x480), got '" + text + "'");
    width = unsigned(parseUnsigned("--size", text.substr(0, x)));
    height = unsigned(parseUnsigned("--size", text.substr(x + 1)));
    if (width == 0 || height == 0 || width > 16384 || height > 16384)
        throw UsageError("--size must lie between 1x1 and 16384x16384, got '" + text + "'");
}
} // namespace

core::AsyncOptions asyncOptionsOf(const BenchOptions& options)
{
    core::AsyncOptions async;
    async.lookAheadFrames = options.asyncLookAhead;
    async.regionSize = core::Vec3(options.asyncRegion[0], options.asyncRegion[1], options.asyncRegion[2]);
    return async;
}

namespace
{
// benchUsage()'s text, in sections. The synopsis: every option.
const char* usageSynopsis()
{
    return "usage: osgvisbench (--scene FILE | --generate office|city|floor|tetra|forest [--layout L]\n"
           "                   [--triangles N] [--seed S])\n"
           "                   [--walk FILE|auto|random|orbit] [--save-walk FILE] [--modes osg,osg-oq,exact,frustum,frustum+octree,...]\n"
           "                   [--views N] [--size WxH] [--supersample K] [--cube | --fov 360]\n"
           "                   [--speeds 1,2,4,8,16] [--threads 1,2] [--mask-deltas 0,1,2,4,8]\n"
           "                   [--mask-slowdown K] [--cull-only]\n"
           "                   [--dynamic] [--paged [--paging-requests N] [--paging-keep N] [--paging-keep-mb M] [--paging-prefetch N]]\n"
           "                   [--threading MODEL,...] [--async on|off|on,off]\n"
           "                   [--async-lookahead N] [--async-region X,Y,Z]\n"
           "                   [--volume X0,Y0,Z0,X1,Y1,Z1|paper [--plane-resolution N] [--planes N]\n"
           "                    [--volume-face N] [--volume-eyes N] [--volume-repeat N]]\n"
           "                   [--volume-cells N]\n"
           "                   [--json OUT.json] [--report DIR [--pictures N]] [--explain] [--backoff on|off]\n"
           "                   [--oracle-cache DIR]\n"
           "                   [--dump-visible DIR] [--clusters on|off|N]\n"
           "                   [--help]\n";
}

// What the bench does, and the walk's options.
const char* usageOverviewAndWalkOptions()
{
    return "\n"
           "Renders every mode over the same walk in one process and measures it against the\n"
           "exact-visibility oracle (docs/benchmark.md). A module chain is written with '+'; a name\n"
           "osgVis lacks loads the plugin osgvis_module_<name>.so from OSGVIS_MODULE_PATH or\n"
           "lib/osgvis-modules (docs/visapi.md).\n"
           "Default modes: osg,frustum,exact.\n"
           "--walk: a walk file (docs/walk-format.md), auto (eyes at a person's height in the model's\n"
           "  free space, never inside solid geometry), random (300 views: those eyes jittered, each\n"
           "  looking in a random direction, seeded by --seed: views nobody tuned) or orbit (around\n"
           "  the model). Default: the walk\n"
           "  beside the scene, the generator's walk with --generate, else auto (an orbit when the\n"
           "  model has nowhere to stand).\n"
           "--save-walk FILE: write the walk followed (an automatic one, too) as a walk file, to edit\n"
           "  or replay with --walk FILE.\n"
           "--dump-visible DIR: instead of the benchmark, write DIR/<mode>.visible for every module-chain\n"
           "  mode: per view of the walk (after --views and --cube), the sorted canonical identities of\n"
           "  the objects the chain answers visible, culled on the scene as a VisibilityGroup extracts it\n"
           "  (glTF node path and primitive, \"n0/n3#p1\", for models read by osgVis's glTF plugin; object\n"
           "  ids otherwise). No rendering; osgvisrawgl writes the same files from its own loader\n"
           "  (docs/visapi.md, \"A renderer that is not OSG\").\n"
           "--cube: every walk key becomes six 90-degree square views (HxH, H the walk's height),\n"
           "  the faces of a cube around the eye, so every metric covers the full sphere.\n";
}

// The cull-only sweeps.
const char* usageSweepOptions()
{
    return "--speeds, --threads: also time each module-chain mode's cull alone (no rendering) with\n"
           "  the observer S times faster (every S-th walk key) under T TBB threads, and check that\n"
           "  every thread count gives the same visible sets. A missing list means speed 1 or\n"
           "  TBB's default thread count.\n"
           "--mask-deltas: also run every mode with a mask stage (mask, mask-approx, mask-distance,\n"
           "  e.g. frustum+mask) cull-only over the same views once per image-space shrinkage\n"
           "  Delta (frame pixels; the mode's own options otherwise) and report the fraction of\n"
           "  critical frames and their reasons, the median/p99 ms of each step of a critical\n"
           "  frame (select, rasterize, pyramid, mark), the median cull ms of critical and other\n"
           "  frames, and the drawn fraction. The mask stages' top eye speed V (MaskOptions::\n"
           "  maxEyeSpeed) is set to the observer's measured top speed over the swept frames (an\n"
           "  application knows its camera's top speed), 1.01 x max |eye step| / time step.\n"
           "--mask-slowdown K: the Delta sweep's observer walks the same path K times slower\n"
           "  (default 1): K-1 frames between consecutive views, the eye moved linearly with the\n"
           "  earlier view's orientation, at the views' own time step, so consecutive frames are\n"
           "  close and the masks' temporal coherence shows. At most 200000 frames (views x K).\n"
           "--cull-only: run just these sweeps (no oracle, no GL).\n";
}

// The dynamic walk and the paged database.
const char* usageDynamicAndPagedOptions()
{
    return "--dynamic: a dynamic walk (osg and module-chain modes): 12 cars drive along the walk's\n"
           "  streets every frame, 3 buildings are dropped on existing ones at 1/4 and at 1/2 of\n"
           "  the views, 3 are deleted at 1/3 and at 2/3 (seeded by --seed); the oracle renders\n"
           "  every frame's scene, and the number of changes applied is printed.\n"
           "--paged: the scene is a paged database (osgvisgen --paged DIR: --scene DIR/root.osgb, walk\n"
           "  DIR/root.walk) walked with OSG's DatabasePager running, frames back to back; osg and\n"
           "  module-chain modes, each from a fresh read of the root. Per mode: tile files requested,\n"
           "  tiles loaded and expired, MB read, peak resident tiles, peak heap growth, pop-in (frames,\n"
           "  objects and pixels the oracle sees on the fully loaded database whose tile was not loaded\n"
           "  yet), false-invisible among loaded tiles' objects, fps and its ratio to osg\n"
           "  (docs/paging.md). --scene DIR/x.pvs: a cell-portal bake of the whole database\n"
           "  (osgvispvs DIR/root.osgb -o DIR/x.pvs), which cellportal modes use for every load\n"
           "  state; the bench pages the root file it names.\n"
           "--paging-requests N: of the visible tiles not loaded yet that a nearer one covers on\n"
           "  screen, a view asks for N per frame, nearest first (default 0: every visible one, as OSG\n"
           "  does). --paging-keep N: a loaded tile hidden for at most N\n"
           "  frames keeps its time stamps fresh (default 120), within OSG_MAX_PAGEDLOD.\n"
           "  --paging-keep-mb M: and within M MB of their geometry's arrays (default 0: no limit).\n"
           "  --paging-prefetch N: tiles the eye will pass through within N frames at its last step are\n"
           "  requested ahead at a lower priority (default 0: off), and with a baked cellportal\n"
           "  PVS the tiles some eye along that path may see.\n";
}

// The threading table.
const char* usageThreadingOptions()
{
    return "--threading M1,M2 / --async on,off: also render every osg and module-chain mode under each\n"
           "  OSG threading model (SingleThreaded, CullDrawThreadPerContext, DrawThreadPerContext,\n"
           "  CullThreadPerCameraDrawThreadPerContext; default SingleThreaded) with asynchronous\n"
           "  visibility on and/or off (default off), and print the threading table: false-invisible,\n"
           "  drawn fraction, the cull thread's median ms in osgVis and OSG's cull ms, frames that fell\n"
           "  back to a synchronous cull, fps and its ratio to the same mode SingleThreaded, and for\n"
           "  synchronous rows the views whose drawn set differs from the main table's pass. Set\n"
           "  LP_NUM_THREADS (Mesa) when timing: llvmpipe's threads compete for the same cores.\n"
           "--async-lookahead N: frames of predicted eye path an async region covers (default 4).\n"
           "--async-region X,Y,Z: an async region is at least this box around the eye (a bake\n"
           "  cell's size, for multifocal regions); default: the path alone.\n";
}

// The volume PVS and the baked cells against the volume oracle.
const char* usageVolumeOptions()
{
    return "--volume X0,Y0,Z0,X1,Y1,Z1 | paper: instead of the walk, the multifocal volume PVS of that\n"
           "  box of eyes (paper: the view volume of the generated forest's layout, docs/scenes.md),\n"
           "  timed (median of --volume-repeat N, default 3), against the volume oracle (eyes at the\n"
           "  box's 8 corners, 6 face centres and --volume-eyes N (default 48) random points, six\n"
           "  --volume-face N pixel (default 512) cube faces each, objects and triangles). Prints\n"
           "  objects and triangles kept, culled, facing away from every eye, and missing (exit\n"
           "  status 1 when any is missing), and the efficacy on the triangles not facing away.\n"
           "  --plane-resolution N (default 100) and --planes N (default 7) set the planes.\n"
           "--volume-cells N: with --scene FILE.pvs baked by osgvispvs --method multifocal, N of its\n"
           "  view cells (evenly spread over them) against the volume oracle (objects): objects the\n"
           "  oracle sees that a cell's PVS lacks (exit status 1 when any), and the triangles of the\n"
           "  PVS's objects over those of the objects seen, per cell and on average.\n";
}

// The report, the oracle cache and --explain.
const char* usageOutputOptions()
{
    return "--report DIR: also write DIR/index.html, one self-contained page (inline SVG, nothing\n"
           "  fetched): the table, per-view plots of drawn triangles for every mode against exact and of\n"
           "  cull ms, false-invisible markers, the progressive and threading tables, and N side-by-side\n"
           "  pictures DIR/view-NNNN.png (--pictures N, default 6, 0 for none) of views spread over the\n"
           "  walk: osg's frame | the best mode's frame | a top-down map of what the best mode drew\n"
           "  (green), culled in the frustum (red), left outside it (grey), and the frustum (yellow).\n"
           "  The best mode is the conservative module chain with the highest fps.\n"
           "--oracle-cache DIR: keep the oracle's exact sets of the rendered walk in DIR, one file per\n"
           "  model geometry, views, size and --supersample, and take them from there when a later run\n"
           "  has the same (then the oracle renders nothing). Not for --dynamic or --paged runs.\n"
           "--explain: also say why culling does or does not work on the model: the objects that\n"
           "  are no occluder, by reason (transparent, alpha test, polygon mode, no depth write, under\n"
           "  LOD/Switch, dynamic, degenerate, too small, ...), the occluder polygons the object-space\n"
           "  methods get, objects whose bounds span more than half the model, and the objects the\n"
           "  best mode never culled although hidden, largest first, with the likeliest reason.\n";
}

// How the modes cull: clusters, back-off.
const char* usageCullingOptions()
{
    return "--clusters on|off|N: split drawables of at least N triangles (on: the default, 4096) into\n"
           "  clusters culled as objects (docs/clusters.md); off keeps every drawable whole. Sets\n"
           "  OSGVIS_CLUSTER_THRESHOLD for every extraction of the run. With clusters the oracle's\n"
           "  objects are narrowed to clusters by a triangle-ID render.\n"
           "--backoff on: measure the modes as an application with do no harm gets them: each\n"
           "  VisibilityGroup times frames with and without its chain and skips the chain where it\n"
           "  costs more than it saves (core::BackOff; timing-dependent, so off by default: each\n"
           "  method is measured alone).\n";
}

// What every rendered mode is measured on, and the exit status.
const char* usageExitStatus()
{
    return "Every rendered mode also gets its mis-drawn pixels: pixels of the oracle's exact image\n"
           "  (display resolution) showing an object the mode culled (where the oracle counts\n"
           "  pixels per object). Approximate modes report false-invisible objects, never fail.\n"
           "Exit status: 0 ok, 1 a conservative mode culled a visible object, gave different\n"
           "visible sets at different thread counts or threading models, or the run failed;\n"
           "2 bad command line.\n";
}
} // namespace

std::string benchUsage()
{
    return std::string(usageSynopsis()) + usageOverviewAndWalkOptions() + usageSweepOptions() +
           usageDynamicAndPagedOptions() + usageThreadingOptions() + usageVolumeOptions() + usageOutputOptions() +
           usageCullingOptions() + usageExitStatus();
}

namespace
{
// The argument being parsed; value() takes the next one as its value.
struct Argument
{
    int argc;
    char** argv;
    int index;
    std::string flag;

    std::string value()
    {
        if (index + 1 >= argc)
            throw UsageError(flag + " needs a value");
        return argv[++index];
    }
};

// Each parse...Option below takes the options of one topic and returns whether `arg` was one of them. Flags
// are matched whole, so the order in which the topics are tried does not matter.

// What scene: a file or a generator, and how its drawables are split into clusters.
bool parseSceneOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--scene")
        options.sceneFile = arg.value();
    else if (flag == "--generate")
        options.generateKind = arg.value();
    else if (flag == "--layout")
        options.forestLayout = arg.value();
    else if (flag == "--triangles")
        options.triangles = parseUnsigned(flag, arg.value());
    else if (flag == "--seed")
        options.seed = std::uint32_t(parseUnsigned(flag, arg.value()));
    else if (flag == "--clusters")
    {
        const std::string setting = arg.value();
        std::string threshold = setting;
        if (setting == "on")
            threshold = "4096";
        else if (setting == "off")
            threshold = "0";
        else
            parseUnsigned("--clusters", setting);
        // note: every extraction of the run (the bench's, each mode's VisibilityGroup) reads it
        ::setenv("OSGVIS_CLUSTER_THRESHOLD", threshold.c_str(), 1);
    }
    else
        return false;
    return true;
}

// Which walk, and the views made of it.
bool parseWalkOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--walk")
        options.walkFile = arg.value();
    else if (flag == "--save-walk")
        options.saveWalkFile = arg.value();
    else if (flag == "--views")
        options.views = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--size")
        parseSize(arg.value(), options.width, options.height);
    else if (flag == "--cube")
        options.cube = true;
    else if (flag == "--fov")
    {
        // The only field of view chosen here is the full sphere; narrower ones are the walk's.
        const std::string degrees = arg.value();
        if (degrees != "360")
            throw UsageError("--fov accepts only 360 (the six cube faces, as --cube), got '" + degrees + "'");
        options.cube = true;
    }
    else
        return false;
    return true;
}

// Which modes, and how they and the oracle run.
bool parseModeOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--modes")
        options.modes = splitList(arg.value(), ',');
    else if (flag == "--backoff")
    {
        const std::string setting = arg.value();
        if (setting != "on" && setting != "off")
            throw UsageError("--backoff takes on or off, got '" + setting + "'");
        options.backOff = setting == "on";
    }
    else if (flag == "--supersample")
        options.supersample = unsigned(parseUnsigned(flag, arg.value()));
    else
        return false;
    return true;
}

// Where the results go.
bool parseOutputOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--dump-visible")
        options.dumpVisibleDir = arg.value();
    else if (flag == "--report")
        options.reportDir = arg.value();
    else if (flag == "--pictures")
    {
        const std::uint64_t count = parseUnsigned(flag, arg.value());
        if (count > 1000)
            throw UsageError("--pictures must lie between 0 and 1000");
        options.pictures = int(count);
    }
    else if (flag == "--explain")
        options.explain = true;
    else if (flag == "--json")
        options.jsonFile = arg.value();
    else if (flag == "--oracle-cache")
        options.oracleCacheDir = arg.value();
    else
        return false;
    return true;
}

// The cull-only sweeps: observer speeds, thread counts, the mask modes' Delta.
bool parseSweepOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--speeds")
        options.speeds = parsePositiveList(flag, arg.value(), 1000);
    else if (flag == "--threads")
        options.threads = parsePositiveList(flag, arg.value(), 256);
    else if (flag == "--mask-deltas")
        options.maskDeltas = parseNonNegativeList(flag, arg.value(), 1000.0);
    else if (flag == "--mask-slowdown")
    {
        const std::uint64_t slowdown = parseUnsigned(flag, arg.value());
        if (slowdown < 1 || slowdown > MaxMaskSweepFrames)
            throw UsageError(flag + " must lie between 1 and " + std::to_string(MaxMaskSweepFrames) + ", got '" +
                             std::to_string(slowdown) + "'");
        options.maskSlowdown = unsigned(slowdown);
    }
    else if (flag == "--cull-only")
        options.cullOnly = true;
    else
        return false;
    return true;
}

// The dynamic walk and the paged database's walk.
bool parseDynamicAndPagedOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--dynamic")
        options.dynamic = true;
    else if (flag == "--paged")
        options.paged = true;
    else if (flag == "--paging-requests")
        options.paging.requestsPerFrame = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--paging-keep")
        options.paging.keepFrames = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--paging-keep-mb")
        options.paging.keepBytes = parseUnsigned(flag, arg.value()) * 1000000u;
    else if (flag == "--paging-prefetch")
        options.paging.prefetchFrames = unsigned(parseUnsigned(flag, arg.value()));
    else
        return false;
    return true;
}

// The multifocal volume PVS and the baked cells checked against the volume oracle.
bool parseVolumeOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--volume")
        options.volume = arg.value();
    else if (flag == "--plane-resolution")
        options.planeResolution = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--planes")
        options.planesPerDirection = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--volume-face")
        options.volumeFaceSize = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--volume-eyes")
        options.volumeEyes = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--volume-repeat")
        options.volumeRepeat = unsigned(parseUnsigned(flag, arg.value()));
    else if (flag == "--volume-cells")
        options.volumeCells = unsigned(parseUnsigned(flag, arg.value()));
    else
        return false;
    return true;
}

// The threading table: OSG's threading models and the asynchronous visibility.
bool parseThreadingOption(Argument& arg, BenchOptions& options)
{
    const std::string& flag = arg.flag;
    if (flag == "--threading" || flag == "--async")
    {
        try
        {
            const std::string text = arg.value();
            if (flag == "--async")
                options.async = apps::parseOnOff(flag, text, true);
            else
                for (const std::string& name : splitList(text, ','))
                    options.threading.push_back(apps::threadingModelName(apps::parseThreadingModel(name)));
        }
        catch (const apps::ThreadingNameError& error)
        {
            throw UsageError(error.what());
        }
    }
    else if (flag == "--async-region")
    {
        const std::vector<std::string> parts = splitList(arg.value(), ',');
        const std::vector<double> sizes =
            parts.size() == 3 ? parseNonNegativeList(flag, parts[0] + "," + parts[1] + "," + parts[2], 1e9)
                              : std::vector<double>{};
        if (sizes.size() != 3 || !(sizes[0] > 0.0 && sizes[1] > 0.0 && sizes[2] > 0.0))
            throw UsageError("--async-region expects three positive sizes X,Y,Z");
        for (int a = 0; a < 3; ++a)
            options.asyncRegion[a] = sizes[a];
    }
    else if (flag == "--async-lookahead")
    {
        options.asyncLookAhead = unsigned(parseUnsigned(flag, arg.value()));
        if (options.asyncLookAhead < 1 || options.asyncLookAhead > 1000)
            throw UsageError("--async-lookahead must lie between 1 and 1000");
    }
    else
        return false;
    return true;
}

// The checks of the options together, by topic.

void checkSceneAndModes(const BenchOptions& options)
{
    if (options.sceneFile.empty() == options.generateKind.empty())
        throw UsageError("give exactly one of --scene FILE or --generate KIND");
    if (options.modes.empty())
        throw UsageError("--modes is empty");
    for (const std::string& mode : options.modes)
        if (mode.empty())
            throw UsageError("--modes contains an empty name");
    if (options.supersample < 1 || options.supersample > 8)
        throw UsageError("--supersample must lie between 1 and 8");
}

void checkDynamicAndPaged(const BenchOptions& options)
{
    if (options.dynamic && (options.cullOnly || options.sweeps() || options.maskSweep()))
        throw UsageError("--dynamic renders a walk against the oracle: no --cull-only, --speeds, --threads or --mask-deltas");
    if (options.paged &&
        (options.sceneFile.empty() || options.cullOnly || options.dynamic || options.sweeps() ||
         options.maskSweep() || options.threadingTable() || !options.reportDir.empty() || options.explain ||
         options.cube || !options.volume.empty() || options.volumeCells > 0 || !options.dumpVisibleDir.empty()))
        throw UsageError("--paged walks a paged database given by --scene DIR/root.osgb, in a run of its own: no "
                         "--generate, --cull-only, --dynamic, --threading, --async, --report, --explain, --cube, "
                         "--volume, --dump-visible or sweeps");
    const PagingOptions defaultPaging;
    if (!options.paged && (options.paging.requestsPerFrame != defaultPaging.requestsPerFrame ||
                           options.paging.keepFrames != defaultPaging.keepFrames ||
                           options.paging.keepBytes != defaultPaging.keepBytes ||
                           options.paging.prefetchFrames != defaultPaging.prefetchFrames))
        throw UsageError("--paging-requests, --paging-keep, --paging-keep-mb and --paging-prefetch go with --paged");
}

void checkSweepsAndOutputs(const BenchOptions& options)
{
    if (options.maskSlowdown != 1 && !options.maskSweep())
        throw UsageError("--mask-slowdown slows the observer of the mask sweep: give --mask-deltas too");
    // note: without --views the walk's length is known only once loaded; the sweep checks again there.
    const std::uint64_t sweptViews = std::uint64_t(options.views) * (options.cube ? 6u : 1u);
    if (sweptViews * options.maskSlowdown > MaxMaskSweepFrames)
        throw UsageError("--mask-slowdown " + std::to_string(options.maskSlowdown) + " over " +
                         std::to_string(sweptViews) + " views makes more than " + std::to_string(MaxMaskSweepFrames) +
                         " frames: give fewer --views or a smaller slowdown");
    if (options.threadingTable() && (options.cullOnly || options.dynamic))
        throw UsageError("--threading and --async render the walk: not with --cull-only or --dynamic");
    if (options.pictures >= 0 && options.reportDir.empty())
        throw UsageError("--pictures go into the report: give --report DIR too");
    if (!options.reportDir.empty() && (options.cullOnly || options.dynamic))
        throw UsageError("--report draws the rendered walk's plots: not with --cull-only or --dynamic");
    if (!options.oracleCacheDir.empty() &&
        (options.cullOnly || options.dynamic || options.paged || !options.volume.empty() || options.volumeCells > 0 ||
         !options.dumpVisibleDir.empty()))
        throw UsageError("--oracle-cache keeps the oracle of a rendered static walk: not with --cull-only, --dynamic, "
                         "--paged, --volume, --volume-cells or --dump-visible");
    if (options.explain && (options.cullOnly || options.dynamic))
        throw UsageError("--explain reads the rendered walk: not with --cull-only or --dynamic");
    if (options.cullOnly && !options.sweeps() && !options.maskSweep())
        throw UsageError("--cull-only needs a sweep: give --speeds, --threads and/or --mask-deltas");
}

// --dump-visible, --volume and --volume-cells are runs of their own.
void checkRunsOfTheirOwn(const BenchOptions& options)
{
    if (!options.dumpVisibleDir.empty() &&
        (options.cullOnly || options.dynamic || options.threadingTable() || !options.reportDir.empty() ||
         options.explain || options.sweeps() || options.maskSweep() || !options.volume.empty() ||
         options.volumeCells > 0 || !options.jsonFile.empty()))
        throw UsageError("--dump-visible is a run of its own: no --cull-only, --dynamic, --threading, --async, "
                         "--report, --explain, --json, --volume or sweeps");
    if (options.volumeCells > 0 && !options.volume.empty())
        throw UsageError("--volume-cells checks the cells of a baked .pvs: not with --volume");
    if (options.volumeCells > 0 &&
        (options.sceneFile.size() < 4 || options.sceneFile.compare(options.sceneFile.size() - 4, 4, ".pvs") != 0))
        throw UsageError("--volume-cells checks the view cells of a .pvs file: give --scene FILE.pvs");
    if ((!options.volume.empty() || options.volumeCells > 0) &&
        (options.cullOnly || options.dynamic || options.threadingTable() || !options.reportDir.empty() ||
         options.explain || options.sweeps() || options.maskSweep()))
        throw UsageError("--volume is a run of its own: no --cull-only, --dynamic, --threading, --async, --report, "
                         "--explain or sweeps");
}

// A --volume given: paper (with a generated forest) or a box with finite corners and a positive size.
void checkVolumeBox(const BenchOptions& options)
{
    if (options.volume == "paper")
    {
        if (options.generateKind != "forest")
            throw UsageError("--volume paper is the view volume of a generated forest: give --generate forest");
        return;
    }
    double v[6];
    char tail = 0;
    if (std::sscanf(options.volume.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf%c", v, v + 1, v + 2, v + 3, v + 4, v + 5,
                    &tail) != 6)
        throw UsageError("--volume expects X0,Y0,Z0,X1,Y1,Z1 or paper, got '" + options.volume + "'");
    for (double x : v)
        if (!std::isfinite(x))
            throw UsageError("--volume: the box's corners must be finite, got '" + options.volume + "'");
    if (!(v[0] < v[3] && v[1] < v[4] && v[2] < v[5]))
        throw UsageError("--volume: the box must have positive size along every axis, got '" + options.volume + "'");
}

void checkVolumeSettings(const BenchOptions& options)
{
    if (!options.volume.empty())
        checkVolumeBox(options);
    if (options.planeResolution < 1 || options.planeResolution > 4096)
        throw UsageError("--plane-resolution must lie between 1 and 4096");
    if (options.planesPerDirection < 1 || options.planesPerDirection > 64)
        throw UsageError("--planes must lie between 1 and 64");
    if (options.volumeFaceSize < 1 || options.volumeFaceSize > 8192)
        throw UsageError("--volume-face must lie between 1 and 8192");
    if (options.volumeRepeat < 1 || options.volumeRepeat > 1000)
        throw UsageError("--volume-repeat must lie between 1 and 1000");
}
} // namespace

BenchOptions parseBenchOptions(int argc, char** argv)
{
    BenchOptions options;
    options.modes = {"osg", "frustum", "exact"};
    for (int i = 0; i < argc; ++i)
        options.commandLine += (i ? " " : "") + quotedArgument(argv[i]);

    for (Argument arg{argc, argv, 1, {}}; arg.index < argc; ++arg.index)
    {
        arg.flag = argv[arg.index];
        if (arg.flag == "--help" || arg.flag == "-h")
            options.help = true;
        else if (!parseSceneOption(arg, options) && !parseWalkOption(arg, options) && !parseModeOption(arg, options) &&
                 !parseOutputOption(arg, options) && !parseSweepOption(arg, options) &&
                 !parseDynamicAndPagedOption(arg, options) && !parseVolumeOption(arg, options) &&
                 !parseThreadingOption(arg, options))
            throw UsageError("unknown argument '" + arg.flag + "'");
    }
    if (options.help)
        return options;
    // In this order: the first fault found is the one reported.
    checkSceneAndModes(options);
    checkDynamicAndPaged(options);
    checkSweepsAndOutputs(options);
    checkRunsOfTheirOwn(options);
    checkVolumeSettings(options);
    return options;
}
} // namespace osgVis::bench
