#pragma once
// The views a bench run renders: the walk's keys subsampled evenly, each with the exact matrices
// every mode and the oracle use (one fixed projection, one fixed near/far for the whole walk).
#include <osgVis/core/Frustum.h>
#include <osgVis/core/Walk.h>

#include <osg/Matrixd>

#include <vector>

namespace osgVis::bench
{
struct BenchView
{
    core::WalkKey key;
    osg::Matrixd view;       // world → eye
    osg::Matrixd projection; // eye → clip, from walk.projection at the render size's aspect
    core::Frustum frustum;   // of projection × view, to tell occlusion from frustum culling
};

// `count` keys spread evenly from the first to the last key (both kept); 0 or more than the walk
// holds keeps every key. The walk's width/height give the aspect.
std::vector<BenchView> makeBenchViews(const core::Walk& walk, unsigned count);
} // namespace osgVis::bench
