// SPDX-License-Identifier: MIT
#pragma once
// The views a bench run renders: every key of the (already subsampled or cube-expanded) walk, each
// with the exact matrices every mode and the oracle use (one fixed projection, one fixed near/far
// for the whole walk).
#include <osgVis/core/geometry/Frustum.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/scene/Walk.h>

#include <osg/Matrixd>

#include <vector>

namespace osgVis::bench
{
struct BenchView
{
    core::WalkKey key;
    osg::Matrixd view;       // world → eye
    osg::Matrixd projection; // eye → clip, from walk.projection at the walk size's aspect
    core::Frustum frustum;   // of projection × view, to tell occlusion from frustum culling
};

// One view per key; the walk's width/height give the aspect.
std::vector<BenchView> makeBenchViews(const core::Walk& walk);

// The same views as the core modules take them (time and viewport included): what the cull-only
// sweeps feed a module chain, with no OSG matrices in between.
std::vector<core::View> makeCoreViews(const core::Walk& walk);
} // namespace osgVis::bench
