// SPDX-License-Identifier: MIT
#include "PvsMerge.h"

#include "PvsToolOptions.h"

#include <osgVis/core/pvs/CellPortalMerge.h>
#include <osgVis/core/pvs/ViewCellMerge.h>

#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace osgVis::pvstool
{
namespace
{
// The model `pvsFile` names by `modelPath` (relative to its folder), as `output` must name it.
std::string modelPathFrom(const std::string& pvsFile, const std::string& modelPath, const std::string& output)
{
    const fs::path stored(modelPath);
    const fs::path model = stored.is_absolute() ? stored : fs::absolute(pvsFile).parent_path() / stored;
    const fs::path relative = model.lexically_normal().lexically_relative(fs::absolute(output).parent_path());
    return relative.empty() ? model.lexically_normal().generic_string() : relative.generic_string();
}
} // namespace

std::string pvsMergeUsage()
{
    return "usage: osgvispvs merge IN1.pvs IN2.pvs ... -o OUT.pvs [--complete]\n"
           "\n"
           "Joins .pvs files that each hold a range of the cells of one bake (osgvispvs --cells or\n"
           "--shard; the same model, method, options and near distance) into OUT.pvs, cells in ascending\n"
           "index: multifocal view cells, or the source cells of one cell-portal subdivision. OUT.pvs\n"
           "names the model of IN1.pvs relative to its own folder. Refuses files of another model or\n"
           "bake, view-cell and cell-portal files together, and cells that come twice.\n"
           "\n"
           "  -o, --output OUT.pvs   the merged file (required; may be one of the inputs)\n"
           "  --complete             also refuse when a cell of the bake is in no input\n"
           "  --help                 this text\n"
           "\n"
           "Exit status: 0 merged, 1 an input cannot be read or does not belong, or OUT.pvs cannot be\n"
           "written, 2 bad command line.\n";
}

PvsMergeOptions parsePvsMergeOptions(const std::vector<std::string>& arguments)
{
    PvsMergeOptions o;
    apps::CommandLine line;
    line.flag({"--help", "-h"}, o.help)
        .value({"-o", "--output"}, o.output)
        .flag({"--complete"}, o.complete)
        .positional([&o](const std::string& input) { o.inputs.push_back(input); });
    try
    {
        line.parse(arguments);
    }
    catch (const UsageError& e)
    {
        // The shared parser's message, said of the subcommand as merge's own errors are.
        throw UsageError(std::string("merge: ") + e.what());
    }
    if (o.help)
        return o;
    if (o.inputs.empty())
        throw UsageError("merge: missing the .pvs files to merge (osgvispvs merge IN1.pvs IN2.pvs ... -o OUT.pvs)");
    if (o.output.empty())
        throw UsageError("merge: missing output path (-o OUT.pvs)");
    return o;
}

int runPvsMerge(const std::vector<std::string>& arguments)
{
    PvsMergeOptions o;
    if (const std::optional<int> status = apps::readCommandLine(
            [&]
            {
                o = parsePvsMergeOptions(arguments);
                return o.help;
            },
            "osgvispvs", "(osgvispvs merge --help for usage)\n", pvsMergeUsage()))
        return *status;
    try
    {
        std::vector<core::PvsFile> ranges;
        for (const std::string& input : o.inputs)
            ranges.push_back(core::readPvsFile(input));
        core::ViewCellMergeOptions options;
        options.requireAllCells = o.complete;
        options.inputNames = o.inputs;
        const bool cellPortal = ranges.front().hasCellPortal;
        core::PvsFile merged =
            cellPortal ? core::mergeCellPortalPvs(ranges, options) : core::mergeViewCellPvs(ranges, options);
        merged.modelPath = modelPathFrom(o.inputs.front(), ranges.front().modelPath, o.output);
        core::writePvsFile(o.output, merged);
        std::size_t held = merged.viewCells.cellIndices.size(), total = merged.viewCells.totalCells;
        if (cellPortal)
        {
            total = merged.data.sources.size();
            held = merged.sourceRange ? merged.sourceRange->second - merged.sourceRange->first : total;
        }
        std::cout << "merged " << o.inputs.size() << " files into " << o.output << ": " << held << " of the " << total
                  << (cellPortal ? " source cells" : " cells") << " of the bake, model '" << merged.modelPath << "'\n";
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvispvs merge: " << e.what() << '\n';
        return 1;
    }
}
} // namespace osgVis::pvstool
