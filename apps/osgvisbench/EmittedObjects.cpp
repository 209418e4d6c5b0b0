// SPDX-License-Identifier: MIT
#include "EmittedObjects.h"

#include <osgVis/ClusterDraw>

#include <osgUtil/StateGraph>

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::bench
{
namespace
{
double largestDifference(const osg::Matrixd& a, const osg::Matrixd& b)
{
    double largest = 0.0;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            largest = std::max(largest, std::abs(a(row, column) - b(row, column)));
    return largest;
}

double largestMagnitude(const osg::Matrixd& m)
{
    double largest = 0.0;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            largest = std::max(largest, std::abs(m(row, column)));
    return largest;
}

void forEachLeafOfBin(const osgUtil::RenderBin& bin, const std::function<void(const osgUtil::RenderLeaf&)>& visit)
{
    // note: sorting moves the leaves of depth-sorted bins from the state graphs into the leaf list,
    // so both have to be read.
    for (const osgUtil::RenderLeaf* leaf : bin.getRenderLeafList())
        visit(*leaf);
    for (const osgUtil::StateGraph* graph : bin.getStateGraphList())
        for (const auto& leaf : graph->_leaves)
            visit(*leaf);
    for (const auto& nested : bin.getRenderBinList())
        forEachLeafOfBin(*nested.second, visit);
}
} // namespace

void forEachRenderLeaf(const osgUtil::RenderStage& stage, const std::function<void(const osgUtil::RenderLeaf&)>& visit)
{
    for (const auto& pre : stage.getPreRenderList())
        forEachRenderLeaf(*pre.second, visit);
    forEachLeafOfBin(stage, visit);
    for (const auto& post : stage.getPostRenderList())
        forEachRenderLeaf(*post.second, visit);
}

EmittedObjects::EmittedObjects(const ExtractedScene& scene) : _scene(scene) {}

void EmittedObjects::collect(const osgUtil::RenderStage& stage, const osg::Matrixd& view, core::VisibleSet& emitted)
{
    _inverseView = osg::Matrixd::inverse(view);
    forEachRenderLeaf(stage, [&](const osgUtil::RenderLeaf& leaf) { collectLeaf(leaf, emitted); });
}

void EmittedObjects::collectLeaf(const osgUtil::RenderLeaf& leaf, core::VisibleSet& emitted)
{
    // A ClusterDraw stands for the clusters it issues to GL; a clustered drawable drawn as it is
    // stands for all of them (docs/clusters.md).
    const osg::Drawable* drawable = leaf.getDrawable();
    const auto* part = dynamic_cast<const ClusterDraw*>(drawable);
    if (part)
        drawable = part->original();
    const std::vector<core::ObjectId>& candidates = _scene.idsOf(drawable);
    if (candidates.empty())
        return;
    const auto emit = [&](core::ObjectId id)
    {
        const ObjectRef& ref = _scene.refs[id];
        if (!ref.clusters)
        {
            emitted.set(id);
            return;
        }
        const core::ObjectId first = id - ref.cluster;
        if (part)
            for (std::uint32_t c : part->drawnClusters())
                emitted.set(first + c);
        else
            for (std::size_t c = 0; c < ref.clusters->size(); ++c)
                emitted.set(first + core::ObjectId(c));
    };
    const bool oneInstance = candidates.size() == 1 || (_scene.refs[candidates.front()].clusters &&
                                                        candidates.size() == _scene.refs[candidates.front()].clusters->size());
    if (oneInstance || !leaf._modelview.valid())
    {
        emit(candidates.front());
        return;
    }
    const osg::Matrixd model = *leaf._modelview * _inverseView;
    const double tolerance = 1e-6 * (1.0 + largestMagnitude(model));
    core::ObjectId nearest = core::InvalidObject;
    double nearestDifference = std::numeric_limits<double>::max();
    for (core::ObjectId id : candidates)
    {
        if (_scene.refs[id].cluster != 0)
            continue; // one instance's clusters share its matrix
        const double difference = largestDifference(model, _scene.refs[id].world);
        if (difference < nearestDifference)
        {
            nearest = id;
            nearestDifference = difference;
        }
    }
    if (nearestDifference <= tolerance)
        emit(nearest);
    else
        ++_unmatchedLeaves;
}
} // namespace osgVis::bench
