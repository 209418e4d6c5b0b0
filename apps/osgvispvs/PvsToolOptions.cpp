// SPDX-License-Identifier: MIT
#include "PvsToolOptions.h"

#include <array>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <vector>

namespace osgVis::pvstool
{
using apps::CommandLine;
using apps::parseNumber;
using apps::parseUnsigned;

namespace
{
// Shortest decimal form: 0.3 and 0.0001 rather than std::to_string's 0.300000 and 0.000100.
std::string shortNumber(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}
} // namespace

std::string pvsToolUsage()
{
    const core::BakeOptions defaults;
    return "usage: osgvispvs MODEL -o OUT.pvs [options]\n"
           "       osgvispvs merge IN1.pvs IN2.pvs ... -o OUT.pvs [--complete]   (osgvispvs merge --help)\n"
           "       osgvispvs --help | --version\n"
           "\n"
           "Bakes cell-and-portal visibility (Teller & Sequin) for MODEL (any format osgDB reads, e.g. a\n"
           "scene from osgvisgen) and writes it to OUT.pvs, which names MODEL by its path relative to\n"
           "OUT.pvs's folder. Loading OUT.pvs through osgDB then gives MODEL under a cellportal\n"
           "VisibilityGroup that uses the baked data. Prints the bake's statistics.\n"
           "\n"
           "  -o, --output OUT.pvs   where the baked data go (required)\n"
           "  --min-coverage F       split a cell along a plane where opaque axis-aligned faces cover at\n"
           "                         least this fraction of its cross-section, 0 to 1 (default " +
           shortNumber(defaults.subdivision.minCoverage) +
           ")\n"
           "  --min-face-area A      ... or at least this area in square world units, >= 0 (default 0: the\n"
           "                         coverage alone decides)\n"
           "  --min-cell-size F      no cell thinner than this fraction of the scene's diagonal, 0 to 1\n"
           "                         (default " +
           shortNumber(defaults.subdivision.minCellSize) +
           ")\n"
           "  --max-cells N          at most N cells, 1 to 100000000 (default " +
           std::to_string(defaults.subdivision.maxCells) +
           ")\n"
           "  --stab-budget N        stab-tree nodes one cell's search may grow before it gives up and\n"
           "                         counts every reachable cell visible (default " +
           std::to_string(defaults.stabBudget) +
           ")\n"
           "  --cells-from S         faces (default): cells split at the model's opaque axis-aligned faces;\n"
           "                         solids: cells are the open space between the solids the model proves\n"
           "                         (a Quake 3 level's box brushes; docs/cellportal.md, \"Solid space\")\n"
           "  --explain              say what the subdivision found and, where few cells came out, why\n"
           "  --threads N            worker threads, 0 = all cores (default 0); results do not depend on it\n"
           "  --method M             cellportal (default) or multifocal: a PVS per view cell, for every\n"
           "                         eye in the cell (Marsden & Guibas; docs/multifocal.md), no portals\n"
           "\n"
           "With --method multifocal, the view cells are (the first that applies):\n"
           "  --grid X0,Y0,Z0,X1,Y1,Z1  cells of --cell-size over that box\n"
           "  --walk FILE            the cells of the grid through --cell-origin X,Y,Z (default 0,0,0)\n"
           "                         that the walk's eyes stand in\n"
           "  osgVis::Cell markers in the model; else the walk beside the model (its stem + .walk),\n"
           "  else a grid over the model's bounds.\n"
           "  --cell-size X,Y,Z      cell edges (default: 1/50 of the model's diagonal each)\n"
           "  --near D               the near-plane reach views will have, at most (default: twice the\n"
           "                         walk's, else 1/1000 of the diagonal); farther-reaching views keep all\n"
           "  --plane-resolution N   pixels along each plane's longer side (default 100)\n"
           "  --planes N             planes per face of a cell (default 7)\n"
           "\n"
           "Splitting a bake (both methods; the output is byte-identical however it is split):\n"
           "  --cells A:B            bake cells A to B-1 only (view cells, or cell-portal source cells)\n"
           "                         into a range file; join range files with osgvispvs merge\n"
           "  --shard K/N            the K-th of N equal cell ranges (1 <= K <= N), as --cells does;\n"
           "                         --shard slurm takes K and N from a Slurm job array\n"
           "                         (SLURM_ARRAY_TASK_ID, _MIN and _COUNT)\n"
           "  --unit-cells N         cells per work unit (default: the cells in 1024 units for\n"
           "                         multifocal, 64 for cellportal, at least 4 units a rank)\n"
           "  Finished units go to OUT.pvs.units/ as they finish; the same command run again after a\n"
           "  crash or kill bakes only the rest. The folder goes once OUT.pvs is written.\n"
           "  Under mpirun (osgvispvs built with MPI): rank 0 hands units to the ranks as they finish,\n"
           "  bakes too, and writes OUT.pvs; each rank loads the model. --threads is per rank\n"
           "  (default: the cores divided among the ranks on a machine).\n"
           "\n"
           "  --json FILE            also write the statistics as JSON to FILE\n"
           "  --progress             draw the progress bar even when stderr is not a terminal\n"
           "  --help                 this text\n"
           "  --version              the osgVis version\n"
           "\n"
           "A progress bar with percentage and ETA goes to stderr when it is a terminal; one closing line\n"
           "always. Exit status: 0 done, 1 the model or an output could not be read or written (or the\n"
           "scene is empty), 2 bad command line.\n";
}

namespace
{
// "K/N" with 1 <= K <= N, or "slurm": this array task's K of N from Slurm's variables.
std::pair<std::uint32_t, std::uint32_t> parseShard(const std::string& text, const char* (*environment)(const char*))
{
    if (text == "slurm")
    {
        const char* id = environment("SLURM_ARRAY_TASK_ID");
        const char* count = environment("SLURM_ARRAY_TASK_COUNT");
        const char* min = environment("SLURM_ARRAY_TASK_MIN");
        if (!id || !count)
            throw UsageError("--shard slurm needs SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT (run it in a Slurm "
                             "job array, sbatch --array)");
        const std::uint64_t n = parseUnsigned("SLURM_ARRAY_TASK_COUNT", count, 1, 1000000);
        const std::uint64_t first = min ? parseUnsigned("SLURM_ARRAY_TASK_MIN", min, 0, 100000000) : 0;
        const std::uint64_t task = parseUnsigned("SLURM_ARRAY_TASK_ID", id, first, first + n - 1);
        return {std::uint32_t(task - first + 1), std::uint32_t(n)};
    }
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos)
        throw UsageError("--shard expects K/N (the K-th of N cell ranges, 1 <= K <= N) or slurm, got '" + text + "'");
    const std::uint64_t n = parseUnsigned("--shard", text.substr(slash + 1), 1, 1000000);
    const std::uint64_t k = parseUnsigned("--shard", text.substr(0, slash), 1, n);
    return {std::uint32_t(k), std::uint32_t(n)};
}

// "A:B" with A < B: cells A to B-1.
std::pair<std::uint32_t, std::uint32_t> parseCellRange(const std::string& range)
{
    const std::size_t colon = range.find(':');
    if (colon == std::string::npos)
        throw UsageError("--cells expects A:B (cells A to B-1), got '" + range + "'");
    const std::uint64_t first = parseUnsigned("--cells", range.substr(0, colon), 0, 4000000000u);
    const std::uint64_t end = parseUnsigned("--cells", range.substr(colon + 1), 0, 4000000000u);
    if (first >= end)
        throw UsageError("--cells A:B needs A < B, got '" + range + "'");
    return std::make_pair(std::uint32_t(first), std::uint32_t(end));
}

// Handlers storing an option's value, checked against [least, most], in `target`.
template <typename T>
CommandLine::ValueHandler countInto(const char* option, T& target, std::uint64_t least, std::uint64_t most)
{
    return [option, &target, least, most](const std::string& text)
    { target = T(parseUnsigned(option, text, least, most)); };
}

template <typename T>
CommandLine::ValueHandler numberInto(const char* option, T& target, double least,
                                     double most = std::numeric_limits<double>::max())
{
    return [option, &target, least, most](const std::string& text) { target = parseNumber(option, text, least, most); };
}

core::Vec3 vec3(const std::array<double, 3>& xyz)
{
    return core::Vec3(xyz[0], xyz[1], xyz[2]);
}

// The add*Options functions below each declare one topic's options.

// What the tool says besides baking: help, version, progress bar, explanation.
void addGeneralOptions(CommandLine& line, PvsToolOptions& o)
{
    line.flag({"--help", "-h"}, o.help)
        .flag({"--version"}, o.version)
        .flag({"--progress"}, o.forceProgress)
        .flag({"--explain"}, o.explain);
}

void addOutputOptions(CommandLine& line, PvsToolOptions& o)
{
    line.value({"-o", "--output"}, o.pvsFile).value({"--json"}, o.jsonFile);
}

// The cell-portal bake's subdivision and search, and the threads of either method.
void addBakeOptions(CommandLine& line, core::BakeOptions& bake)
{
    line.value({"--cells-from"},
               [&bake](const std::string& from)
               {
                   if (from != "faces" && from != "solids")
                       throw UsageError("--cells-from is faces or solids, got '" + from + "'");
                   bake.subdivision.fromSolids = from == "solids";
               })
        .value({"--min-coverage"}, numberInto("--min-coverage", bake.subdivision.minCoverage, 0.0, 1.0))
        .value({"--min-face-area"}, numberInto("--min-face-area", bake.subdivision.minFaceArea, 0.0))
        .value({"--min-cell-size"}, numberInto("--min-cell-size", bake.subdivision.minCellSize, 0.0, 1.0))
        .value({"--max-cells"}, countInto("--max-cells", bake.subdivision.maxCells, 1, 100000000))
        .value({"--stab-budget"}, countInto("--stab-budget", bake.stabBudget, 1, 4000000000u))
        .value({"--threads"}, countInto("--threads", bake.threads, 0, 4096));
}

// The method, and the planes and near distance of the multifocal one.
void addMethodOptions(CommandLine& line, PvsToolOptions& o)
{
    line.value({"--method"},
               [&o](const std::string& method)
               {
                   if (method != "cellportal" && method != "multifocal")
                       throw UsageError("--method is cellportal or multifocal, got '" + method + "'");
                   o.method = method;
               })
        .value({"--plane-resolution"}, countInto("--plane-resolution", o.multifocal.planeResolution, 1, 4096))
        .value({"--planes"}, countInto("--planes", o.multifocal.planesPerDirection, 1, 64))
        .value({"--near"}, numberInto("--near", o.nearDistance, 0.0));
}

// Where the multifocal method's view cells are.
void addViewCellOptions(CommandLine& line, PvsToolOptions& o)
{
    line.value({"--grid"},
               [&o](const std::string& text)
               {
                   const std::vector<std::string> items = apps::splitList(text);
                   if (items.size() != 6)
                       throw UsageError("--grid expects 6 comma-separated numbers, got '" + text + "'");
                   std::vector<double> v;
                   for (const std::string& item : items)
                       v.push_back(parseNumber("--grid", item));
                   if (!(v[0] < v[3] && v[1] < v[4] && v[2] < v[5]))
                       throw UsageError("--grid needs X0 < X1, Y0 < Y1 and Z0 < Z1");
                   o.grid = core::Aabb(core::Vec3(v[0], v[1], v[2]), core::Vec3(v[3], v[4], v[5]));
               })
        .value({"--walk"}, o.walkFile)
        .value({"--cell-size"},
               [&o](const std::string& text)
               {
                   const std::array<double, 3> size = apps::parseTriple("--cell-size", text);
                   if (!(size[0] > 0.0 && size[1] > 0.0 && size[2] > 0.0))
                       throw UsageError("--cell-size must be positive along every axis");
                   o.cellSize = vec3(size);
               })
        .value({"--cell-origin"},
               [&o](const std::string& text) { o.cellOrigin = vec3(apps::parseTriple("--cell-origin", text)); });
}

// Splitting a bake into cell ranges and work units.
void addSplitOptions(CommandLine& line, PvsToolOptions& o, const char* (*environment)(const char*))
{
    line.value({"--cells"}, [&o](const std::string& text) { o.cellRange = parseCellRange(text); })
        .value({"--shard"}, [&o, environment](const std::string& text) { o.shard = parseShard(text, environment); })
        .value({"--unit-cells"}, countInto("--unit-cells", o.unitCells, 1, 100000000));
}

// A bake needs a model and an output, and options of one method only.
void checkComplete(const PvsToolOptions& o)
{
    if (o.modelFile.empty())
        throw UsageError("missing the model to bake (osgvispvs MODEL -o OUT.pvs)");
    if (o.pvsFile.empty())
        throw UsageError("missing output path (-o OUT.pvs)");
    const bool viewCellOptions = o.grid || !o.walkFile.empty() || o.cellSize.x > 0.0 || o.nearDistance;
    if (o.method != "multifocal" && viewCellOptions)
        throw UsageError("--grid, --walk, --cell-size and --near go with --method multifocal");
    if (o.method == "multifocal" && o.bake.subdivision.fromSolids)
        throw UsageError("--cells-from goes with --method cellportal");
    if (o.cellRange && o.shard)
        throw UsageError("give --cells or --shard, not both");
    if (o.grid && !o.walkFile.empty())
        throw UsageError("give --grid or --walk, not both");
}
} // namespace

PvsToolOptions parsePvsToolOptions(int argc, char** argv, const char* (*environment)(const char*))
{
    if (!environment)
        environment = [](const char* name) -> const char* { return std::getenv(name); };
    PvsToolOptions o;
    CommandLine line;
    addGeneralOptions(line, o);
    addOutputOptions(line, o);
    addBakeOptions(line, o.bake);
    addMethodOptions(line, o);
    addViewCellOptions(line, o);
    addSplitOptions(line, o, environment);
    line.positional(o.modelFile, "one model only: got");
    line.parse(argc, argv);
    if (o.help || o.version)
        return o;
    checkComplete(o);
    return o;
}
} // namespace osgVis::pvstool
