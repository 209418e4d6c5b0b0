// SPDX-License-Identifier: MIT
#include "PvsToolOptions.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <vector>

namespace osgVis::pvstool
{
namespace
{
std::string shortNumber(double value);

// Whole decimal digits only: strtoull would accept "-1" (wrapping it) and " 7".
std::uint64_t parseCount(const std::string& flag, const std::string& text, std::uint64_t lo, std::uint64_t hi)
{
    if (text.empty() || text.size() > 19 || text.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(flag + " expects a non-negative integer, got '" + text + "'");
    const std::uint64_t value = std::strtoull(text.c_str(), nullptr, 10);
    if (value < lo || value > hi)
        throw UsageError(flag + " must lie between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got '" +
                         text + "'");
    return value;
}

// A finite decimal number in [lo, hi]; the whole text must be the number ("0.3x" is an error).
double parseNumber(const std::string& flag, const std::string& text, double lo, double hi)
{
    char* end = nullptr;
    const double value = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) ||
        text.find_first_of(" \t") != std::string::npos)
        throw UsageError(flag + " expects a number, got '" + text + "'");
    if (value < lo || value > hi)
        throw UsageError(flag + " must lie between " + shortNumber(lo) + " and " + shortNumber(hi) + ", got '" +
                         text + "'");
    return value;
}

// `count` comma-separated finite numbers ("4,4,2").
std::vector<double> parseNumbers(const std::string& flag, const std::string& text, std::size_t count)
{
    std::vector<double> values;
    std::size_t start = 0;
    for (std::size_t k = 0; k < count; ++k)
    {
        const std::size_t comma = text.find(',', start);
        const bool last = k + 1 == count;
        if (last != (comma == std::string::npos))
            throw UsageError(flag + " expects " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
        values.push_back(parseNumber(flag, text.substr(start, last ? std::string::npos : comma - start),
                                     -std::numeric_limits<double>::max(), std::numeric_limits<double>::max()));
        start = comma + 1;
    }
    return values;
}

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
        const std::uint64_t n = parseCount("SLURM_ARRAY_TASK_COUNT", count, 1, 1000000);
        const std::uint64_t first = min ? parseCount("SLURM_ARRAY_TASK_MIN", min, 0, 100000000) : 0;
        const std::uint64_t task = parseCount("SLURM_ARRAY_TASK_ID", id, first, first + n - 1);
        return {std::uint32_t(task - first + 1), std::uint32_t(n)};
    }
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos)
        throw UsageError("--shard expects K/N (the K-th of N cell ranges, 1 <= K <= N) or slurm, got '" + text + "'");
    const std::uint64_t n = parseCount("--shard", text.substr(slash + 1), 1, 1000000);
    const std::uint64_t k = parseCount("--shard", text.substr(0, slash), 1, n);
    return {std::uint32_t(k), std::uint32_t(n)};
}

// "A:B" with A < B: cells A to B-1.
std::pair<std::uint32_t, std::uint32_t> parseCellRange(const std::string& flag, const std::string& range)
{
    const std::size_t colon = range.find(':');
    if (colon == std::string::npos)
        throw UsageError("--cells expects A:B (cells A to B-1), got '" + range + "'");
    const std::uint64_t first = parseCount(flag, range.substr(0, colon), 0, 4000000000u);
    const std::uint64_t end = parseCount(flag, range.substr(colon + 1), 0, 4000000000u);
    if (first >= end)
        throw UsageError("--cells A:B needs A < B, got '" + range + "'");
    return std::make_pair(std::uint32_t(first), std::uint32_t(end));
}

// One argument of the command line; value() takes the next one as its value.
struct Argument
{
    std::string text;
    int& index; // of text in argv: value() moves it on to the value
    int argc;
    char** argv;

    std::string value() const
    {
        if (index + 1 >= argc)
            throw UsageError(text + " needs a value");
        return argv[++index];
    }
};

// The parse*Option functions below each handle one topic and return whether the argument was theirs.

// What the tool says besides baking: help, version, progress bar, explanation.
bool parseGeneralOption(const Argument& arg, PvsToolOptions& o)
{
    if (arg.text == "--help" || arg.text == "-h")
        o.help = true;
    else if (arg.text == "--version")
        o.version = true;
    else if (arg.text == "--progress")
        o.forceProgress = true;
    else if (arg.text == "--explain")
        o.explain = true;
    else
        return false;
    return true;
}

bool parseOutputOption(const Argument& arg, PvsToolOptions& o)
{
    if (arg.text == "-o" || arg.text == "--output")
        o.pvsFile = arg.value();
    else if (arg.text == "--json")
        o.jsonFile = arg.value();
    else
        return false;
    return true;
}

// The cell-portal bake's subdivision and search, and the threads of either method.
bool parseBakeOption(const Argument& arg, PvsToolOptions& o)
{
    if (arg.text == "--cells-from")
    {
        const std::string from = arg.value();
        if (from != "faces" && from != "solids")
            throw UsageError("--cells-from is faces or solids, got '" + from + "'");
        o.bake.subdivision.fromSolids = from == "solids";
    }
    else if (arg.text == "--min-coverage")
        o.bake.subdivision.minCoverage = parseNumber(arg.text, arg.value(), 0.0, 1.0);
    else if (arg.text == "--min-face-area")
        o.bake.subdivision.minFaceArea = parseNumber(arg.text, arg.value(), 0.0, std::numeric_limits<double>::max());
    else if (arg.text == "--min-cell-size")
        o.bake.subdivision.minCellSize = parseNumber(arg.text, arg.value(), 0.0, 1.0);
    else if (arg.text == "--max-cells")
        o.bake.subdivision.maxCells = std::uint32_t(parseCount(arg.text, arg.value(), 1, 100000000));
    else if (arg.text == "--stab-budget")
        o.bake.stabBudget = std::uint32_t(parseCount(arg.text, arg.value(), 1, 4000000000u));
    else if (arg.text == "--threads")
        o.bake.threads = unsigned(parseCount(arg.text, arg.value(), 0, 4096));
    else
        return false;
    return true;
}

// The method, and the planes and near distance of the multifocal one.
bool parseMethodOption(const Argument& arg, PvsToolOptions& o)
{
    if (arg.text == "--method")
    {
        o.method = arg.value();
        if (o.method != "cellportal" && o.method != "multifocal")
            throw UsageError("--method is cellportal or multifocal, got '" + o.method + "'");
    }
    else if (arg.text == "--plane-resolution")
        o.multifocal.planeResolution = int(parseCount(arg.text, arg.value(), 1, 4096));
    else if (arg.text == "--planes")
        o.multifocal.planesPerDirection = int(parseCount(arg.text, arg.value(), 1, 64));
    else if (arg.text == "--near")
        o.nearDistance = parseNumber(arg.text, arg.value(), 0.0, std::numeric_limits<double>::max());
    else
        return false;
    return true;
}

// Where the multifocal method's view cells are.
bool parseViewCellOption(const Argument& arg, PvsToolOptions& o)
{
    if (arg.text == "--grid")
    {
        const std::vector<double> v = parseNumbers(arg.text, arg.value(), 6);
        if (!(v[0] < v[3] && v[1] < v[4] && v[2] < v[5]))
            throw UsageError("--grid needs X0 < X1, Y0 < Y1 and Z0 < Z1");
        o.grid = core::Aabb(core::Vec3(v[0], v[1], v[2]), core::Vec3(v[3], v[4], v[5]));
    }
    else if (arg.text == "--walk")
        o.walkFile = arg.value();
    else if (arg.text == "--cell-size")
    {
        const std::vector<double> v = parseNumbers(arg.text, arg.value(), 3);
        if (!(v[0] > 0.0 && v[1] > 0.0 && v[2] > 0.0))
            throw UsageError("--cell-size must be positive along every axis");
        o.cellSize = core::Vec3(v[0], v[1], v[2]);
    }
    else if (arg.text == "--cell-origin")
    {
        const std::vector<double> v = parseNumbers(arg.text, arg.value(), 3);
        o.cellOrigin = core::Vec3(v[0], v[1], v[2]);
    }
    else
        return false;
    return true;
}

// Splitting a bake into cell ranges and work units.
bool parseSplitOption(const Argument& arg, PvsToolOptions& o, const char* (*environment)(const char*))
{
    if (arg.text == "--cells")
        o.cellRange = parseCellRange(arg.text, arg.value());
    else if (arg.text == "--shard")
        o.shard = parseShard(arg.value(), environment);
    else if (arg.text == "--unit-cells")
        o.unitCells = std::uint32_t(parseCount(arg.text, arg.value(), 1, 100000000));
    else
        return false;
    return true;
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
    for (int i = 1; i < argc; ++i)
    {
        const Argument arg{argv[i], i, argc, argv};
        if (parseGeneralOption(arg, o) || parseOutputOption(arg, o) || parseBakeOption(arg, o) ||
            parseMethodOption(arg, o) || parseViewCellOption(arg, o) || parseSplitOption(arg, o, environment))
            continue;
        if (!arg.text.empty() && arg.text[0] == '-')
            throw UsageError("unknown argument '" + arg.text + "'");
        if (!o.modelFile.empty())
            throw UsageError("one model only: got '" + o.modelFile + "' and '" + arg.text + "'");
        o.modelFile = arg.text;
    }
    if (o.help || o.version)
        return o;
    checkComplete(o);
    return o;
}
} // namespace osgVis::pvstool
