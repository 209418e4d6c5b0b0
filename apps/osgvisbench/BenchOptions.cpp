// SPDX-License-Identifier: MIT
#include "BenchOptions.h"

#include <ThreadingModel.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace osgVis::bench
{
namespace
{
using apps::CommandLine;
using apps::parseUnsigned;
using apps::splitList;

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
// Each add...Options below declares the options of one topic; a subcommand takes the topics it
// needs (subcommandOptions).

// What scene: a file or a generator, and how its drawables are split into clusters.
void addSceneOptions(CommandLine& line, BenchOptions& options)
{
    line.value({"--scene"}, options.sceneFile)
        .value({"--generate"}, options.generateKind)
        .value({"--layout"}, options.forestLayout)
        .value({"--triangles"}, [&](const std::string& v) { options.triangles = parseUnsigned("--triangles", v); })
        .value({"--seed"},
               [&](const std::string& v) { options.seed = std::uint32_t(parseUnsigned("--seed", v, 0, UINT32_MAX)); })
        .value({"--clusters"},
               [](const std::string& setting)
               {
                   std::string threshold = setting;
                   if (setting == "on")
                       threshold = "4096";
                   else if (setting == "off")
                       threshold = "0";
                   else
                       parseUnsigned("--clusters", setting);
                   // note: every extraction of the run (the bench's, each mode's VisibilityGroup) reads it
                   ::setenv("OSGVIS_CLUSTER_THRESHOLD", threshold.c_str(), 1);
               });
}

// Which walk, the views made of it, and the modes that cull them.
void addWalkAndModeOptions(CommandLine& line, BenchOptions& options)
{
    const auto number = [](unsigned& target, const char* name)
    { return [&target, name](const std::string& v) { target = unsigned(parseUnsigned(name, v, 0, UINT32_MAX)); }; };
    line.value({"--walk"}, options.walkFile)
        .value({"--save-walk"}, options.saveWalkFile)
        .value({"--views"}, number(options.views, "--views"))
        .value({"--size"}, [&](const std::string& v) { apps::parseSize("--size", v, options.width, options.height); })
        .flag({"--cube"}, options.cube)
        .value({"--fov"},
               [&](const std::string& degrees)
               {
                   // The only field of view chosen here is the full sphere; narrower ones are the walk's.
                   if (degrees != "360")
                       throw UsageError("--fov accepts only 360 (the six cube faces, as --cube), got '" + degrees + "'");
                   options.cube = true;
               })
        .value({"--modes"}, [&](const std::string& v) { options.modes = splitList(v, ','); })
        .value({"--backoff"}, [&](const std::string& v) { options.backOff = apps::parseOnOff("--backoff", v, false).front(); })
        .value({"--supersample"}, number(options.supersample, "--supersample"));
}

// The report, the oracle cache and --explain.
void addReportOptions(CommandLine& line, BenchOptions& options)
{
    line.value({"--report"}, options.reportDir)
        .value({"--pictures"},
               [&](const std::string& v) { options.pictures = int(parseUnsigned("--pictures", v, 0, 1000)); })
        .flag({"--explain"}, options.explain)
        .value({"--oracle-cache"}, options.oracleCacheDir);
}

// The cull-only sweeps: observer speeds, thread counts, the mask modes' Delta.
void addSweepOptions(CommandLine& line, BenchOptions& options)
{
    line.value({"--speeds"}, [&](const std::string& v) { options.speeds = apps::parseUnsignedList("--speeds", v, 1, 1000); })
        .value({"--threads"},
               [&](const std::string& v) { options.threads = apps::parseUnsignedList("--threads", v, 1, 256); })
        .value({"--mask-deltas"},
               [&](const std::string& v) { options.maskDeltas = parseNonNegativeList("--mask-deltas", v, 1000.0); })
        .value({"--mask-slowdown"},
               [&](const std::string& v)
               { options.maskSlowdown = unsigned(parseUnsigned("--mask-slowdown", v, 1, MaxMaskSweepFrames)); })
        .flag({"--cull-only"}, options.cullOnly);
}

// The paged database's walk.
void addPagingOptions(CommandLine& line, BenchOptions& options)
{
    PagingOptions& paging = options.paging;
    line.value({"--paging-requests"},
               [&](const std::string& v) { paging.requestsPerFrame = unsigned(parseUnsigned("--paging-requests", v, 0, UINT32_MAX)); })
        .value({"--paging-keep"},
               [&](const std::string& v) { paging.keepFrames = unsigned(parseUnsigned("--paging-keep", v, 0, UINT32_MAX)); })
        .value({"--paging-keep-mb"},
               [&](const std::string& v) { paging.keepBytes = parseUnsigned("--paging-keep-mb", v, 0, 1u << 30) * 1000000u; })
        .value({"--paging-prefetch"},
               [&](const std::string& v) { paging.prefetchFrames = unsigned(parseUnsigned("--paging-prefetch", v, 0, UINT32_MAX)); });
}

// The multifocal volume PVS and the volume oracle (the oracle's two also check baked cells).
void addVolumeOracleOptions(CommandLine& line, BenchOptions& options)
{
    line.value({"--volume-face"}, [&](const std::string& v) { options.volumeFaceSize = unsigned(parseUnsigned("--volume-face", v, 0, UINT32_MAX)); })
        .value({"--volume-eyes"}, [&](const std::string& v) { options.volumeEyes = unsigned(parseUnsigned("--volume-eyes", v, 0, UINT32_MAX)); });
}

void addVolumeOptions(CommandLine& line, BenchOptions& options)
{
    addVolumeOracleOptions(line, options);
    line.value({"--volume"}, options.volume)
        .value({"--plane-resolution"}, [&](const std::string& v) { options.planeResolution = unsigned(parseUnsigned("--plane-resolution", v, 0, UINT32_MAX)); })
        .value({"--planes"}, [&](const std::string& v) { options.planesPerDirection = unsigned(parseUnsigned("--planes", v, 0, UINT32_MAX)); })
        .value({"--volume-repeat"}, [&](const std::string& v) { options.volumeRepeat = unsigned(parseUnsigned("--volume-repeat", v, 0, UINT32_MAX)); });
}

void addCellsOptions(CommandLine& line, BenchOptions& options)
{
    line.value({"--volume-cells"},
               [&](const std::string& v) { options.volumeCells = unsigned(parseUnsigned("--volume-cells", v, 0, UINT32_MAX)); });
}

// The threading table: OSG's threading models and the asynchronous visibility.
void addThreadingOptions(CommandLine& line, BenchOptions& options)
{
    line.value({"--threading"},
               [&](const std::string& text)
               {
                   for (const std::string& name : splitList(text, ','))
                       options.threading.push_back(apps::threadingModelName(apps::parseThreadingModel(name)));
               })
        .value({"--async"}, [&](const std::string& text) { options.async = apps::parseOnOff("--async", text, true); })
        .value({"--async-region"},
               [&](const std::string& text)
               {
                   const std::vector<std::string> parts = splitList(text, ',');
                   const std::vector<double> sizes =
                       parts.size() == 3 ? parseNonNegativeList("--async-region", parts[0] + "," + parts[1] + "," + parts[2], 1e9)
                                         : std::vector<double>{};
                   if (sizes.size() != 3 || !(sizes[0] > 0.0 && sizes[1] > 0.0 && sizes[2] > 0.0))
                       throw UsageError("--async-region expects three positive sizes X,Y,Z");
                   for (int a = 0; a < 3; ++a)
                       options.asyncRegion[a] = sizes[a];
               })
        .value({"--async-lookahead"},
               [&](const std::string& v)
               {
                   const std::uint64_t frames = parseUnsigned("--async-lookahead", v);
                   if (frames < 1 || frames > 1000)
                       throw UsageError("--async-lookahead must lie between 1 and 1000");
                   options.asyncLookAhead = unsigned(frames);
               });
}

// The older options that choose a run without a subcommand.
void addRunChoosingOptions(CommandLine& line, BenchOptions& options)
{
    line.flag({"--dynamic"}, options.dynamic).flag({"--paged"}, options.paged);
}

void addDumpOption(CommandLine& line, BenchOptions& options)
{
    line.value({"--dump-visible"}, options.dumpVisibleDir);
}

void addJsonOption(CommandLine& line, BenchOptions& options)
{
    line.value({"--json"}, options.jsonFile);
}

using OptionGroup = void (*)(CommandLine&, BenchOptions&);

// The option groups of a subcommand beside the scene's (dump has no JSON: the dump is its output);
// without a subcommand, every group.
std::vector<OptionGroup> groupsOf(const BenchOptions& options)
{
    if (!options.commandGiven)
        return {addWalkAndModeOptions, addReportOptions, addSweepOptions, addPagingOptions, addVolumeOptions,
                addCellsOptions, addThreadingOptions, addRunChoosingOptions, addDumpOption, addJsonOption};
    switch (options.command)
    {
    case BenchCommand::Run:
        return {addWalkAndModeOptions, addReportOptions, addSweepOptions, addThreadingOptions, addJsonOption};
    case BenchCommand::Dynamic:
        return {addWalkAndModeOptions, addJsonOption};
    case BenchCommand::Paged:
        return {addWalkAndModeOptions, addPagingOptions, addJsonOption};
    case BenchCommand::Volume:
        return {addVolumeOptions, addJsonOption};
    case BenchCommand::Cells:
        return {addVolumeOracleOptions, addCellsOptions, addJsonOption};
    case BenchCommand::Dump:
        return {addWalkAndModeOptions, addDumpOption};
    }
    return {};
}

// The options a subcommand (or none: every option) takes.
CommandLine subcommandOptions(BenchOptions& options)
{
    CommandLine line;
    line.flag({"--help", "-h"}, options.help);
    addSceneOptions(line, options);
    for (const OptionGroup add : groupsOf(options))
        add(line, options);
    return line;
}

// The subcommand named by argv[1], if any.
bool readSubcommand(const std::string& word, BenchOptions& options)
{
    const std::pair<const char*, BenchCommand> names[] = {
        {"run", BenchCommand::Run},       {"dynamic", BenchCommand::Dynamic}, {"paged", BenchCommand::Paged},
        {"volume", BenchCommand::Volume}, {"cells", BenchCommand::Cells},     {"dump", BenchCommand::Dump}};
    for (const auto& [name, command] : names)
        if (word == name)
        {
            options.command = command;
            options.commandGiven = true;
            return true;
        }
    return false;
}

// A subcommand's run as the older options choose it, and what it cannot do without.
void settleSubcommand(BenchOptions& options)
{
    if (options.commandGiven)
    {
        options.dynamic = options.command == BenchCommand::Dynamic;
        options.paged = options.command == BenchCommand::Paged;
        if (options.command == BenchCommand::Volume && options.volume.empty())
            throw UsageError("volume needs --volume X0,Y0,Z0,X1,Y1,Z1|paper");
        if (options.command == BenchCommand::Cells && options.volumeCells == 0)
            throw UsageError("cells needs --volume-cells N (N >= 1)");
        if (options.command == BenchCommand::Dump && options.dumpVisibleDir.empty())
            throw UsageError("dump needs --dump-visible DIR");
        return;
    }
    if (options.dynamic)
        options.command = BenchCommand::Dynamic;
    else if (options.paged)
        options.command = BenchCommand::Paged;
    else if (!options.dumpVisibleDir.empty())
        options.command = BenchCommand::Dump;
    else if (!options.volume.empty())
        options.command = BenchCommand::Volume;
    else if (options.volumeCells > 0)
        options.command = BenchCommand::Cells;
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
    options.commandLine = apps::quotedCommandLine(argc, argv);
    const int first = (argc > 1 && readSubcommand(argv[1], options)) ? 2 : 1;
    try
    {
        subcommandOptions(options).parse(argc, argv, first);
    }
    catch (const apps::ThreadingNameError& error)
    {
        throw UsageError(error.what());
    }
    if (options.help)
        return options;
    settleSubcommand(options);
    // In this order: the first fault found is the one reported.
    checkSceneAndModes(options);
    checkDynamicAndPaged(options);
    checkSweepsAndOutputs(options);
    checkRunsOfTheirOwn(options);
    checkVolumeSettings(options);
    return options;
}
} // namespace osgVis::bench
