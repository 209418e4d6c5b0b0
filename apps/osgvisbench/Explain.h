// SPDX-License-Identifier: MIT
#pragma once
// Why culling does or does not work on a model (--explain): the model's occluders and why the
// others are none (apps::OccluderReport), and the objects a mode never culled although the oracle
// found them hidden, with the likeliest reason, largest first. For a user who wants to know what to
// change in a model.
#include "BenchMode.h"

#include <OccluderReport.h>

#include <osgVis/SceneExtractor>
#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::bench
{
struct NeverCulledObject
{
    core::ObjectId id = core::InvalidObject;
    std::string name;
    std::uint32_t triangles = 0;
    std::uint32_t hiddenViews = 0; // views where the oracle found it hidden and in the frustum
    std::string why;
};

struct Explanation
{
    apps::OccluderReport occluders;
    std::string mode; // the mode the never-culled list is about: the highest occlusion efficacy; empty if none culls any
    std::size_t neverCulledCount = 0;
    std::uint64_t neverCulledTriangles = 0;
    std::vector<NeverCulledObject> neverCulled; // the largest, at most 12
};

// `scene` must keep its triangles. `drawn` and `hidden`: per view, what `mode` drew and the objects
// the oracle found hidden inside the view frustum.
Explanation explainScene(const ExtractedScene& scene, const std::string& mode, const std::vector<core::VisibleSet>& drawn,
                         const std::vector<core::VisibleSet>& hidden);
void writeExplanation(std::ostream& out, const Explanation& explanation);
} // namespace osgVis::bench
