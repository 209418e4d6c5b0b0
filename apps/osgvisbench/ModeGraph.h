// SPDX-License-Identifier: MIT
#pragma once
// The scene data each mode renders. Every mode draws the same drawables with the same state; only
// what decides which of them reach the draw differs.
#include "BenchMode.h"

#include <osgVis/SceneExtractor>

#include <osgVis/core/async/AsyncVisibility.h>

#include <osg/Node>

namespace osgVis::bench
{
// osg: the model itself. osg-oq: the per-object occlusion-query graph. exact and module chains:
// the model under an osgVis::VisibilityGroup (exact runs the bench's oracle-replay module, which
// must be registered first: see ExactReplay).
// `async` turns on asynchronous visibility for module chains (with `asyncOptions`: the frames of path
// a region covers, its least size), `backOff` do no harm (core::BackOff).
osg::ref_ptr<osg::Node> buildModeGraph(const BenchMode& mode, osg::Node& model, const ExtractedScene& scene,
                                       bool async = false, const core::AsyncOptions& asyncOptions = {},
                                       bool backOff = false);
} // namespace osgVis::bench
