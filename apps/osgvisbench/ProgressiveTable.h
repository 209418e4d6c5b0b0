// SPDX-License-Identifier: MIT
#pragma once
// Teller & Séquin's progressive table (their Table 2): how much of the model each stage of
// cell-and-portal culling still draws, from the entire model through cell-to-cell, cell-to-object
// and eye-to-cell to eye-to-object. A cull-only pass (no rendering) of the four CellPortalModule
// stages over the bench's views, sharing one set of baked data.
#include "BenchMode.h"
#include "BenchReport.h"

#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/Walk.h>

#include <vector>

namespace osgVis::bench
{
// True when some mode's chain has a cellportal stage: then the bench adds the table.
bool wantsProgressiveTable(const std::vector<BenchMode>& modes);

// One row per stage, in the paper's order, each the mean over `walk`'s keys of the fraction of
// the scene's triangles (and objects) the stage keeps. The modules use the baked data registered
// for the scene (a .pvs file) or bake on the spot. Progress goes to stderr.
std::vector<ProgressiveRow> runProgressiveTable(const core::Scene& scene, const core::Walk& walk);
} // namespace osgVis::bench
