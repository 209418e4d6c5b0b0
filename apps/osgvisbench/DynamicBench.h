// SPDX-License-Identifier: MIT
#pragma once
// osgvisbench --dynamic: the bench run over a dynamic walk (DynamicWalk). Per frame the scene
// changes the same way for the oracle and every mode; the oracle renders each frame's scene, whose
// objects keep their ids across frames (reextractScene), so false-invisible is measured per frame
// as for a static walk. Nobody calls dirtyScene(): the VisibilityGroups find each change themselves
// (docs/changes.md). osg-oq and exact are not supported here.
#include "BenchMode.h"
#include "BenchOptions.h"
#include "BenchReport.h"

#include <vector>

namespace osgVis::bench
{
// Prints "dynamic changes: N (...)" on stdout. Throws std::invalid_argument for an unsupported mode
// and what runBench throws otherwise.
BenchReport runDynamicBench(const BenchOptions& options, const std::vector<BenchMode>& modes);
} // namespace osgVis::bench
