// SPDX-License-Identifier: MIT
#include "MaskOccluderSelection.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace osgVis::core
{
namespace
{
// Fraction of the frame that the box's projection covers, seen from `eye` with the view's
// orientation; corners nearer than the near plane are pushed out to it along the view axis.
double coverage(const MaskProjection& projection, const Aabb& box, const Vec3& shift)
{
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int i = 0; i < 8; ++i)
    {
        Vec3 eyeSpace = projection.toEye(box.corner(i) - shift);
        eyeSpace.z = std::min(eyeSpace.z, -projection.nearPlane());
        const glm::dvec2 m = projection.toMask(eyeSpace);
        x0 = std::min(x0, m.x), y0 = std::min(y0, m.y);
        x1 = std::max(x1, m.x), y1 = std::max(y1, m.y);
    }
    const double b = projection.border();
    const double w = projection.frameWidth(), h = projection.frameHeight();
    const double cw = std::max(0.0, std::min(x1, b + w) - std::max(x0, b));
    const double ch = std::max(0.0, std::min(y1, b + h) - std::max(y0, b));
    return cw * ch / (w * h);
}

double importance(const MaskSelectionInput& in, const Aabb& box)
{
    if (in.measure == OccluderMeasure::Distance)
        return -box.distance(in.eye);
    const double r = in.sampleRadius;
    const Vec3 samples[7] = {Vec3(0.0), {r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
    const int sampleCount = r > 0.0 ? 7 : 1;
    double phi = std::numeric_limits<double>::max();
    for (int s = 0; s < sampleCount; ++s)
        phi = std::min(phi, coverage(*in.projection, box, samples[s]) * box.distance(in.eye + samples[s]));
    return phi;
}
} // namespace

std::vector<ObjectId> selectMaskOccluders(const MaskSelectionInput& in)
{
    const MaskKdTree& tree = *in.tree;
    std::vector<ObjectId> chosen;
    if (tree.empty() || in.count == 0)
        return chosen;
    // Enough candidates to choose from, without walking the whole city.
    const std::size_t wanted = std::size_t(in.count) * 4;
    struct Entry
    {
        double distance;
        std::uint32_t node;
        bool operator<(const Entry& o) const { return distance > o.distance || (distance == o.distance && node > o.node); }
    };
    std::priority_queue<Entry> queue;
    queue.push({tree.node(tree.root()).bounds.distance(in.eye), tree.root()});
    std::vector<std::pair<double, ObjectId>> candidates;
    while (!queue.empty() && candidates.size() < wanted)
    {
        const Entry top = queue.top();
        queue.pop();
        const MaskKdTree::Node& node = tree.node(top.node);
        if (node.objectCount == 0 || in.view->frustum.classify(node.bounds) == Containment::Outside)
            continue;
        if (!node.leaf())
        {
            queue.push({tree.node(node.left).bounds.distance(in.eye), node.left});
            queue.push({tree.node(node.right).bounds.distance(in.eye), node.right});
            continue;
        }
        for (ObjectId id : node.objects)
        {
            const Aabb& box = (*in.objects)[id].bounds;
            if (!(*in.usable)[id] || box.distance(in.eye) < in.minDistance ||
                in.view->frustum.classify(box) == Containment::Outside)
                continue;
            candidates.push_back({importance(in, box), id});
        }
    }
    const auto better = [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); };
    const std::size_t keep = std::min<std::size_t>(in.count, candidates.size());
    std::partial_sort(candidates.begin(), candidates.begin() + keep, candidates.end(), better);
    for (std::size_t i = 0; i < keep; ++i)
        chosen.push_back(candidates[i].second);
    return chosen;
}
} // namespace osgVis::core
