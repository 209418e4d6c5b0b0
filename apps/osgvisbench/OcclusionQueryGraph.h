// SPDX-License-Identifier: MIT
#pragma once
// The graph of the `osg-oq` mode: OSG's built-in hardware occlusion queries applied to every object.
// OSG only queries whole nodes, so each object (drawable instance) gets its own
//   MatrixTransform(world) → OcclusionQueryNode → Geode(state merged along its path) → drawable
// sharing the original drawables. The queries keep OSG's defaults (visibility threshold, query
// frame count): this is what an OSG user gets, staleness and thresholds included, and its
// false-invisible count is measured, not assumed.
#include <osgVis/SceneExtractor>

#include <osg/Group>

namespace osgVis::bench
{
osg::ref_ptr<osg::Group> buildOcclusionQueryGraph(const ExtractedScene& scene);
} // namespace osgVis::bench
