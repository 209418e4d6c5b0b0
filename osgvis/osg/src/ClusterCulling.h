// SPDX-License-Identifier: MIT
#pragma once
// Internal: the cull-time decision for a clustered drawable, shared by VisibilityGroup's drawable
// callback and osgVis::CullVisitor.
#include <osgVis/ClusterDraw>
#include <osgVis/SceneExtractor>

#include <osgVis/core/scene/VisibleSet.h>

#include <osgUtil/CullVisitor>

namespace osgVis
{
enum class ClusterCull
{
    Hidden, ///< no cluster of the instance is visible
    Whole,  ///< every cluster is visible: let the user's drawable draw as it is
    Drawn,  ///< a ClusterDraw for the visible clusters went into the render graph in its place
};

/// Index runs of the visible clusters of the instance whose first cluster is `first`.
ClusterDraw::Runs visibleRuns(const ClusterLayout& layout, core::ObjectId first, const core::VisibleSet& visible,
                              std::size_t& visibleClusters);

/// For the drawable `drawable` at the cull visitor's current node path, an instance of `layout`
/// with first cluster `first`: decides, and for some-visible adds a ClusterDraw to the render graph
/// the way osgUtil::CullVisitor::apply(osg::Drawable&) adds a drawable (its own frustum test, near
/// and far, state set, depth). Never culls a visible cluster.
ClusterCull cullClusters(osgUtil::CullVisitor& cv, osg::Drawable& drawable, const ClusterLayout& layout,
                         core::ObjectId first, const core::VisibleSet& visible);

/// Runs `callback` (the drawable's own cull callback, or one it chains) as
/// osgUtil::CullVisitor::apply(osg::Drawable&) does; true when it culls the drawable.
bool culledByCallback(osg::NodeVisitor& nv, osg::Drawable& drawable, const osg::Callback* callback);

/// The whole decision for a clustered instance, the drawable at the top of the visitor's path: true
/// when OSG should draw the drawable whole (every cluster visible, or cullClusters says so); false when
/// none is visible, its own cull callback culls it, or a ClusterDraw of the visible ones went in.
bool drawClusteredWhole(osgUtil::CullVisitor& cv, osg::Drawable& drawable, const ClusterLayout& layout,
                        core::ObjectId first, const core::VisibleSet& visible);
} // namespace osgVis
