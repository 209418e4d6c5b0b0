// SPDX-License-Identifier: MIT
#include "PagingPolicy.h"

#include <osg/PagedLOD>

#include <algorithm>
#include <cmath>

namespace osgVis
{
namespace
{
double distanceToBox(const osg::Vec3d& eye, const core::Aabb& box)
{
    if (box.empty())
        return 0.0;
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double below = box.min[axis] - eye[axis], above = eye[axis] - box.max[axis];
        const double gap = std::max({below, above, 0.0});
        squared += gap * gap;
    }
    return std::sqrt(squared);
}

// What PagedLOD::traverse would have stamped had the cull entered it.
void renewStamps(osg::PagedLOD& node, const osg::FrameStamp& frameStamp)
{
    node.setFrameNumberOfLastTraversal(frameStamp.getFrameNumber());
    for (unsigned child = 0; child < node.getNumChildren(); ++child)
    {
        node.setTimeStamp(child, frameStamp.getReferenceTime());
        node.setFrameNumber(child, frameStamp.getFrameNumber());
    }
}
} // namespace

PagingFigures applyPagingPolicy(const PagingOptions& options, const ExtractedScene& scene, core::VisibleSet& visible,
                                const osg::Vec3d& eye, const osg::FrameStamp* frameStamp, std::size_t residentBudget,
                                std::vector<unsigned>& lastVisible)
{
    PagingFigures figures;
    if (scene.pagedNodes.empty())
        return figures;
    const unsigned frame = frameStamp ? frameStamp->getFrameNumber() : 0u;
    if (lastVisible.size() < scene.scene.objects.size())
        lastVisible.resize(scene.scene.objects.size(), ~0u);

    std::vector<std::pair<double, core::ObjectId>> waiting; // visible, nothing loaded: would request
    std::vector<std::pair<unsigned, osg::PagedLOD*>> recent; // hidden, loaded, seen lately: frames since
    unsigned visibleLoaded = 0;
    for (const PagedNodeRecord& record : scene.pagedNodes)
    {
        const core::ObjectId id = record.placeholder;
        osg::Group& node = *scene.refs[id].paged;
        if (visible.test(id))
        {
            lastVisible[id] = frame;
            if (node.getNumChildren() == 0)
                waiting.emplace_back(distanceToBox(eye, scene.scene.objects[id].bounds), id);
            else
                ++visibleLoaded;
            continue;
        }
        auto* paged = dynamic_cast<osg::PagedLOD*>(&node);
        if (paged && frameStamp && paged->getNumChildren() > 0 && lastVisible[id] != ~0u &&
            frame - lastVisible[id] <= options.keepFrames)
            recent.emplace_back(frame - lastVisible[id], paged);
    }
    // The pager's own budget of loaded paged nodes holds: the most recently seen are kept first.
    const std::size_t room = residentBudget > visibleLoaded ? residentBudget - visibleLoaded : 0;
    if (recent.size() > room)
    {
        std::nth_element(recent.begin(), recent.begin() + room, recent.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        recent.resize(room);
    }
    for (const auto& kept : recent)
        renewStamps(*kept.second, *frameStamp);
    figures.keptFresh = unsigned(recent.size());
    // note: a node with no child loaded draws nothing, so leaving it out this frame hides nothing;
    // it only delays its request behind those of nearer tiles.
    if (options.requestsPerFrame != 0 && waiting.size() > options.requestsPerFrame)
    {
        std::nth_element(waiting.begin(), waiting.begin() + options.requestsPerFrame, waiting.end());
        for (auto it = waiting.begin() + options.requestsPerFrame; it != waiting.end(); ++it)
        {
            visible.clear(it->second);
            ++figures.deferred;
        }
    }
    return figures;
}
} // namespace osgVis
