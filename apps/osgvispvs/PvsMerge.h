// SPDX-License-Identifier: MIT
#pragma once
// `osgvispvs merge IN1.pvs IN2.pvs ... -o OUT.pvs`: joins the range files of one view-cell bake into
// one .pvs file (core::mergeViewCellPvs), its model named relative to OUT.pvs's folder.
#include <string>
#include <vector>

namespace osgVis::pvstool
{
struct PvsMergeOptions
{
    std::vector<std::string> inputs; // the positional arguments, in the order given
    std::string output;              // -o / --output
    bool complete = false;           // --complete: refuse unless the inputs hold every cell of the bake
    bool help = false;               // --help
};

// The words after "merge"; throws UsageError naming the offending argument.
PvsMergeOptions parsePvsMergeOptions(const std::vector<std::string>& arguments);
std::string pvsMergeUsage();
// What main runs for `osgvispvs merge ...`: exit status 0 merged, 1 an input that cannot be read or
// does not belong (with the reason on stderr) or an output that cannot be written, 2 a bad command line.
int runPvsMerge(const std::vector<std::string>& arguments);
} // namespace osgVis::pvstool
