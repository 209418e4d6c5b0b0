// SPDX-License-Identifier: MIT
#pragma once
// One mode's timed pass over the walk: every view rendered once, with what the cull traversal
// emitted (S(v)) and the cull time read back after each frame, outside the timed region.
#include "BenchViewer.h"
#include "EmittedObjects.h"

#include <osgVis/core/scene/VisibleSet.h>

#include <functional>
#include <string>
#include <vector>

namespace osgVis::bench
{
struct PassResult
{
    std::vector<core::VisibleSet> emitted; // S(v) per view
    std::vector<double> cullMs;            // per view
    std::vector<double> chainMs;           // per view: osgVis's visibility query (NaN: none ran)
    double renderSeconds = 0.0;            // sum of the frames' wall times
    std::size_t unmatchedLeaves = 0;       // see EmittedObjects::unmatchedLeaves
};

// `beforeView(v)` runs before view v is rendered (the exact mode points its replay at v). One
// untimed priming frame at the first view comes first and is not counted: it builds what modes
// build lazily on their first cull (scene extraction, spatial hierarchy, query objects), which is
// set-up, not per-frame cost.
// `afterView(v)` runs once view v is culled, outside the timed region.
PassResult renderModePass(const std::string& label, BenchViewer& viewer, const std::vector<BenchView>& views,
                          EmittedObjects& emittedObjects, std::size_t objectCount,
                          const std::function<void(std::size_t)>& beforeView,
                          const std::function<void(std::size_t)>& afterView = {});
} // namespace osgVis::bench
