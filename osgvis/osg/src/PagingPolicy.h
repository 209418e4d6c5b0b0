// SPDX-License-Identifier: MIT
#pragma once
// Internal: what a view's visible set does to the pager, after the chain culled (docs/paging.md).
// Requests go nearest first: a tile that a nearer tile still loading covers on screen waits (a few
// are let through per frame), so that the tiles loaded first can hide the ones behind them before
// those are asked for; a loaded tile hidden only for a moment keeps its time
// stamps fresh, so the pager does not expire it and load it again when it shows.
#include <osgVis/SceneExtractor>
#include <osgVis/ViewCuller>

#include <osgVis/core/scene/VisibleSet.h>

#include <osg/FrameStamp>
#include <osg/NodeVisitor>

#include <vector>

namespace osgVis
{
struct PagingFigures
{
    unsigned deferred = 0; ///< visible paged nodes with nothing loaded, not entered this frame (over the budget)
    unsigned keptFresh = 0; ///< hidden loaded paged nodes whose time stamps were renewed
    unsigned prefetched = 0; ///< paged nodes requested ahead of the eye (prefetchAhead)
};

// `rootToEye`, `projection`: the view's matrices (OSG's row-vector convention). `lastVisible`: per
// object id, the frame a placeholder was last visible in this view (grown as needed). Clears the
// visible bit of deferred placeholders; renews the stamps of kept ones, at most
// so many that the loaded paged nodes visible or kept stay within `residentBudget` (the pager's
// target number of PagedLODs, OSG_MAX_PAGEDLOD).
PagingFigures applyPagingPolicy(const PagingOptions& options, const ExtractedScene& scene, core::VisibleSet& visible,
                                const osg::Matrixd& rootToEye, const osg::Matrixd& projection,
                                const osg::FrameStamp* frameStamp, std::size_t residentBudget,
                                std::vector<unsigned>& lastVisible);
// Prefetch: asks `pager` (at priority -1, below any visible tile) for each PagedLOD with nothing
// loaded that this frame's traversal will not enter (`visible` says it is hidden) and whose
// placeholder box the segment from `eye` to eye + frames·step crosses, or which `seenAhead` (may be
// null: what the chain's region query finds visible from some eye near that segment) holds;
// returns how many.
unsigned prefetchAhead(const ExtractedScene& scene, const core::VisibleSet& visible, const osg::Vec3d& eye,
                       const osg::Vec3d& step, unsigned frames, const core::VisibleSet* seenAhead,
                       osg::NodeVisitor::DatabaseRequestHandler& pager, const osg::FrameStamp* frameStamp);
} // namespace osgVis
