// SPDX-License-Identifier: MIT
#pragma once
// Decides from a drawable's node path whether its triangles may stand in as automatic occluders
// and from which side they hide: a polygon only hides what lies behind it if it is drawn every
// frame, fills its pixels and writes depth where its triangles are.
#include <osg/Node>

#include <cstdint>

namespace osgVis
{
struct OccluderEligibility
{
    std::uint32_t flags = 0;     // core::OBJECT_NO_AUTO_OCCLUDER, OBJECT_CULL_BACK, OBJECT_CULL_FRONT
    bool clockwiseFront = false; // osg::FrontFace CLOCKWISE: stored triangles must be flipped
    const char* notOccluderBecause = nullptr; // with OBJECT_NO_AUTO_OCCLUDER: the first reason found
};

// `path` runs from the extraction root down to and including the drawable.
OccluderEligibility occluderEligibility(const osg::NodePath& path);

// A hash of everything in `ss` that occluderEligibility and the extractor's transparency flag read
// (modes, the attributes' values, the rendering hint): equal keys, same flags.
std::uint64_t drawnStateKey(const osg::StateSet& ss);
} // namespace osgVis
