// SPDX-License-Identifier: MIT
#pragma once
// Command line of osgvispvs: the model to bake, where the .pvs goes, and the bake's knobs. Parsing
// only: nothing here reads a file.
#include <osgVis/core/cellportal/CellPortalBake.h>
#include <osgVis/core/multifocal/VolumeVisibility.h>

#include <CommandLine.h>

#include <optional>
#include <string>

namespace osgVis::pvstool
{
// Bad command line (the apps' shared one): main prints the message and a hint to --help, and exits
// with code 2.
using apps::UsageError;

struct PvsToolOptions
{
    std::string modelFile;      // the one positional argument (any format osgDB reads)
    std::string pvsFile;        // -o / --output
    std::string jsonFile;       // --json FILE: the statistics as JSON
    core::BakeOptions bake;     // --min-coverage, --min-face-area, --min-cell-size, --max-cells, --stab-budget, --threads,
                                // --cells-from
    std::string method = "cellportal"; // --method cellportal|multifocal
    // --method multifocal: the view cells and their planes.
    core::MultifocalOptions multifocal; // --plane-resolution, --planes
    std::optional<double> nearDistance; // --near D: the near-plane reach assumed
    std::optional<core::Aabb> grid;     // --grid X0,Y0,Z0,X1,Y1,Z1: cells over that box
    std::string walkFile;               // --walk FILE: the cells the walk passes through
    core::Vec3 cellSize{0.0};           // --cell-size X,Y,Z; 0: 1/50 of the model's diagonal
    core::Vec3 cellOrigin{0.0};         // --cell-origin X,Y,Z: a corner of the walk's grid
    std::optional<std::pair<std::uint32_t, std::uint32_t>> cellRange; // --cells A:B (B excluded)
    std::optional<std::pair<std::uint32_t, std::uint32_t>> shard;     // --shard K/N (1 <= K <= N), or from Slurm
    std::uint32_t unitCells = 0; // --unit-cells N: cells per work unit; 0: the method's default
    bool forceProgress = false; // --progress: draw the bar even when stderr is no terminal
    bool explain = false;       // --explain: say what the subdivision found and why
    bool help = false;          // --help
    bool version = false;       // --version
};

// Throws UsageError naming the offending argument. `environment` looks up variables
// (SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT for --shard slurm); std::getenv by default.
PvsToolOptions parsePvsToolOptions(int argc, char** argv, const char* (*environment)(const char*) = nullptr);
std::string pvsToolUsage();
} // namespace osgVis::pvstool
