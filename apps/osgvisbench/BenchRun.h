// SPDX-License-Identifier: MIT
#pragma once
// One bench run from a parsed command line to a report: load the scene and walk, run the oracle,
// render every mode's pass in one viewer, measure.
#include "BenchMode.h"
#include "BenchOptions.h"
#include "BenchReport.h"

#include <SceneSource.h>

#include <vector>

namespace osgVis::bench
{
// The scene and walk the command line names (a file or a generated kind), at the bench's size.
apps::LoadedScene loadBenchScene(const BenchOptions& options);
// The walk a run views: --views keys of the scene's walk, each made six cube faces with --cube.
core::Walk benchWalk(const core::Walk& sceneWalk, const BenchOptions& options);

// Throws (apps::SceneError, ViewerError, std::exception) with a message fit for the user.
BenchReport runBench(const BenchOptions& options, const std::vector<BenchMode>& modes);
} // namespace osgVis::bench
