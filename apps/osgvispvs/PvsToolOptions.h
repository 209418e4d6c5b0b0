// SPDX-License-Identifier: MIT
#pragma once
// Command line of osgvispvs: the model to bake, where the .pvs goes, and the bake's knobs. Parsing
// only: nothing here reads a file.
#include <osgVis/core/cellportal/CellPortalBake.h>

#include <stdexcept>
#include <string>

namespace osgVis::pvstool
{
// Bad command line: main prints the message and a hint to --help, and exits with code 2.
struct UsageError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct PvsToolOptions
{
    std::string modelFile;      // the one positional argument (any format osgDB reads)
    std::string pvsFile;        // -o / --output
    std::string jsonFile;       // --json FILE: the statistics as JSON
    core::BakeOptions bake;     // --min-coverage, --min-face-area, --min-cell-size, --max-cells, --stab-budget, --threads
    bool forceProgress = false; // --progress: draw the bar even when stderr is no terminal
    bool help = false;          // --help
    bool version = false;       // --version
};

// Throws UsageError naming the offending argument.
PvsToolOptions parsePvsToolOptions(int argc, char** argv);
std::string pvsToolUsage();
} // namespace osgVis::pvstool
