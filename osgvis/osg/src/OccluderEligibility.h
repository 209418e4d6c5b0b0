// SPDX-License-Identifier: MIT
#pragma once
// Decides from a drawable's node path whether its triangles may stand in as automatic occluders
// and from which side they hide: a polygon only hides what lies behind it if it is drawn every
// frame, fills its pixels and writes depth where its triangles are.
#include <osg/Node>

#include <cstdint>
#include <vector>

namespace osgVis
{
struct OccluderEligibility
{
    std::uint32_t flags = 0; // core::OBJECT_NO_AUTO_OCCLUDER, OBJECT_UNOCCLUDABLE, OBJECT_CULL_BACK, OBJECT_CULL_FRONT
    bool clockwiseFront = false; // osg::FrontFace CLOCKWISE: stored triangles must be flipped
    const char* notOccluderBecause = nullptr; // with OBJECT_NO_AUTO_OCCLUDER: the first reason found
};

// `path` runs from the extraction root down to and including the drawable.
OccluderEligibility occluderEligibility(const osg::NodePath& path);

// What the state a cull traversal brings to the extraction root (the camera's own state set and every
// one above the root, outermost first) allows below it, by the same rules.
struct InheritedStateRules
{
    const char* hidesNothingBecause = nullptr; // nothing drawn with it may occlude (wire-frame, no depth write, ...)
    bool occludable = true;                    // its depth test can fail behind nearer geometry
};
InheritedStateRules inheritedStateRules(const std::vector<const osg::StateSet*>& stateSets);

// A hash of everything in `ss` that occluderEligibility and the extractor's transparency flag read
// (modes, the attributes' values, the rendering hint): equal keys, same flags.
std::uint64_t drawnStateKey(const osg::StateSet& ss);
} // namespace osgVis
