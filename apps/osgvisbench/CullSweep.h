// SPDX-License-Identifier: MIT
#pragma once
// Cull-only sweeps (--speeds, --threads): each module-chain mode's core::ModuleChain driven
// directly on the extracted scene, with no rendering, so the time measured is the module's own
// query (occluder selection included) at several observer speeds and TBB thread counts. Also
// checks that every thread count gives the same visible set for every view.
#include "BenchMode.h"
#include "BenchReport.h"

#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/Walk.h>

#include <vector>

namespace osgVis::bench
{
struct SweepSettings
{
    std::vector<unsigned> speeds;  // empty: 1 (walking speed)
    std::vector<unsigned> threads; // empty: TBB's default concurrency
    bool cube = false;             // every frame is the six cube faces of its key
};

// `walk` is the scene's whole walk (never subsampled: its key spacing is the walking speed). Modes
// that are not module chains (osg, osg-oq, exact) are skipped. Progress goes to stderr.
SweepReport runCullSweeps(const core::Scene& scene, const core::Walk& walk, const std::vector<BenchMode>& modes,
                          const SweepSettings& settings);
} // namespace osgVis::bench
