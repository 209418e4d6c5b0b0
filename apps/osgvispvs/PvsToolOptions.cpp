// SPDX-License-Identifier: MIT
#include "PvsToolOptions.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

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
           "  --threads N            worker threads, 0 = all cores (default 0); results do not depend on it\n"
           "  --json FILE            also write the statistics as JSON to FILE\n"
           "  --progress             draw the progress bar even when stderr is not a terminal\n"
           "  --help                 this text\n"
           "  --version              the osgVis version\n"
           "\n"
           "A progress bar with percentage and ETA goes to stderr when it is a terminal; one closing line\n"
           "always. Exit status: 0 done, 1 the model or an output could not be read or written (or the\n"
           "scene is empty), 2 bad command line.\n";
}

PvsToolOptions parsePvsToolOptions(int argc, char** argv)
{
    PvsToolOptions o;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string
        {
            if (i + 1 >= argc)
                throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--help" || arg == "-h")
            o.help = true;
        else if (arg == "--version")
            o.version = true;
        else if (arg == "-o" || arg == "--output")
            o.pvsFile = value();
        else if (arg == "--json")
            o.jsonFile = value();
        else if (arg == "--progress")
            o.forceProgress = true;
        else if (arg == "--min-coverage")
            o.bake.subdivision.minCoverage = parseNumber(arg, value(), 0.0, 1.0);
        else if (arg == "--min-face-area")
            o.bake.subdivision.minFaceArea = parseNumber(arg, value(), 0.0, std::numeric_limits<double>::max());
        else if (arg == "--min-cell-size")
            o.bake.subdivision.minCellSize = parseNumber(arg, value(), 0.0, 1.0);
        else if (arg == "--max-cells")
            o.bake.subdivision.maxCells = std::uint32_t(parseCount(arg, value(), 1, 100000000));
        else if (arg == "--stab-budget")
            o.bake.stabBudget = std::uint32_t(parseCount(arg, value(), 1, 4000000000u));
        else if (arg == "--threads")
            o.bake.threads = unsigned(parseCount(arg, value(), 0, 4096));
        else if (!arg.empty() && arg[0] == '-')
            throw UsageError("unknown argument '" + arg + "'");
        else if (!o.modelFile.empty())
            throw UsageError("one model only: got '" + o.modelFile + "' and '" + arg + "'");
        else
            o.modelFile = arg;
    }
    if (o.help || o.version)
        return o;
    if (o.modelFile.empty())
        throw UsageError("missing the model to bake (osgvispvs MODEL -o OUT.pvs)");
    if (o.pvsFile.empty())
        throw UsageError("missing output path (-o OUT.pvs)");
    return o;
}
} // namespace osgVis::pvstool
