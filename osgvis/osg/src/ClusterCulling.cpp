// SPDX-License-Identifier: MIT
// Which clusters of an instance a cull lets through, and the ClusterDraw that draws them.
#include "ClusterCulling.h"

#include <cmath>

namespace osgVis
{
ClusterDraw::Runs visibleRuns(const ClusterLayout& layout, core::ObjectId first, const core::VisibleSet& visible,
                              std::size_t& visibleClusters)
{
    ClusterDraw::Runs runs;
    visibleClusters = 0;
    const std::vector<ClusterLayout::Cluster>& clusters = layout.clusters();
    for (std::size_t c = 0; c < clusters.size(); ++c)
    {
        if (!visible.test(first + core::ObjectId(c)))
            continue;
        ++visibleClusters;
        const auto start = GLint(clusters[c].firstIndex);
        const auto count = GLsizei(clusters[c].indexCount);
        if (!runs.empty() && runs.back().first + runs.back().second == start)
            runs.back().second += count;
        else
            runs.push_back({start, count});
    }
    return runs;
}

ClusterCull cullClusters(osgUtil::CullVisitor& cv, osg::Drawable& drawable, const ClusterLayout& layout,
                         core::ObjectId first, const core::VisibleSet& visible)
{
    std::size_t visibleClusters = 0;
    ClusterDraw::Runs runs = visibleRuns(layout, first, visible, visibleClusters);
    if (visibleClusters == 0)
        return ClusterCull::Hidden;
    // note: state frusta (osg::CullingSet::getStateFrustumList, from ClipNodes' state) attach state
    // per drawable bound; the whole drawable keeps them exactly as OSG would.
    if (visibleClusters == layout.size() || !cv.getCurrentCullingSet().getStateFrustumList().empty())
        return ClusterCull::Whole;

    // Mirrors osgUtil::CullVisitor::apply(osg::Drawable&) after the cull callbacks.
    osg::RefMatrix& matrix = *cv.getModelViewMatrix();
    const osg::BoundingBox& bb = drawable.getBoundingBox();
    if (drawable.isCullingActive() && cv.isCulled(bb))
        return ClusterCull::Hidden;
    if (cv.getComputeNearFarMode() != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR && bb.valid() &&
        !cv.updateCalculatedNearFar(matrix, drawable, false))
        return ClusterCull::Hidden;
    const osg::Vec3 c = bb.center();
    const float depth =
        bb.valid() ? -float(c.x() * matrix(0, 2) + c.y() * matrix(1, 2) + c.z() * matrix(2, 2) + matrix(3, 2)) : 0.0f;
    if (std::isnan(depth))
        return ClusterCull::Whole; // let OSG report it as it does
    osg::ref_ptr<ClusterDraw> draw = new ClusterDraw(drawable, layout, std::move(runs));
    const osg::StateSet* stateset = drawable.getStateSet();
    if (stateset)
        cv.pushStateSet(stateset);
    cv.addDrawableAndDepth(draw.get(), &matrix, depth);
    if (stateset)
        cv.popStateSet();
    return ClusterCull::Drawn;
}

bool culledByCallback(osg::NodeVisitor& nv, osg::Drawable& drawable, const osg::Callback* callback)
{
    if (!callback)
        return false;
    osgUtil::CullVisitor* cv = nv.asCullVisitor();
    if (const osg::DrawableCullCallback* dcb = callback->asDrawableCullCallback())
        return dcb->cull(&nv, &drawable, cv ? &cv->getRenderInfo() : nullptr);
    const_cast<osg::Callback*>(callback)->run(&drawable, &nv);
    return false;
}

bool drawClusteredWhole(osgUtil::CullVisitor& cv, osg::Drawable& drawable, const ClusterLayout& layout,
                        core::ObjectId first, const core::VisibleSet& visible)
{
    std::size_t visibleClusters = 0;
    visibleRuns(layout, first, visible, visibleClusters);
    if (visibleClusters == layout.size())
        return true; // drawn whole by OSG, callbacks and all
    if (visibleClusters == 0 || culledByCallback(cv, drawable, drawable.getCullCallback()))
        return false;
    return cullClusters(cv, drawable, layout, first, visible) == ClusterCull::Whole;
}
} // namespace osgVis
