// SPDX-License-Identifier: MIT
#pragma once
// Why culling does or does not work on a model (--explain): which objects may stand in as
// occluders and why the others may not (transparent, alpha test, polygon mode, no depth write,
// under LOD/Switch, dynamic, degenerate, too small), how many occluder polygons the object-space
// methods get, objects whose bounds are far larger than what they draw, and the objects a mode never
// culled although the oracle found them hidden, with the likeliest reason, largest first. For a
// user who wants to know what to change in a model.
#include "BenchMode.h"

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
    std::size_t objects = 0;
    std::uint64_t triangles = 0;
    std::vector<std::pair<std::string, std::size_t>> notOccluders; // reason, objects
    std::size_t occluderObjects = 0;  // objects that yield at least one occluder polygon
    std::size_t occluderPolygons = 0; // what the object-space occluder builder makes of the scene
    std::size_t hugeBounds = 0;       // objects whose bounds span more than half the model's diagonal
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
