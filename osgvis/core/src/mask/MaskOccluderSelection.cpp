// SPDX-License-Identifier: MIT
#include "MaskOccluderSelection.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
// Fraction of the frame that the box's projection covers, seen from an eye moved by `shift` (in eye
// space) with the view's orientation; `corners` are the box's corners in eye space. Corners nearer
// than the near plane are pushed out to it along the view axis.
double coverage(const MaskProjection& projection, const Vec3 (&corners)[8], const Vec3& shift)
{
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec3& corner : corners)
    {
        Vec3 eyeSpace = corner - shift;
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

// The sampled eyes of the δ-ball (the eye, and δ away along each axis) as offsets in world and in
// eye space (an eye moved by s sees every point moved by -R·s, R the view's rotation).
struct EyeSamples
{
    int count = 1;
    Vec3 world[7], eyeSpace[7];
    explicit EyeSamples(const MaskSelectionInput& in)
    {
        const double r = in.sampleRadius;
        const Vec3 offsets[7] = {Vec3(0.0), {r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
        count = r > 0.0 ? 7 : 1;
        const Vec3 origin = in.projection->toEye(Vec3(0.0));
        for (int s = 0; s < count; ++s)
        {
            world[s] = offsets[s];
            eyeSpace[s] = s == 0 ? Vec3(0.0) : in.projection->toEye(offsets[s]) - origin;
        }
    }
};

double importance(const MaskSelectionInput& in, const EyeSamples& samples, const Aabb& box)
{
    if (in.measure == OccluderMeasure::Distance)
        return -box.distance(in.eye);
    Vec3 corners[8]; // in eye space, once for every sample
    for (int i = 0; i < 8; ++i)
        corners[i] = in.projection->toEye(box.corner(i));
    double phi = std::numeric_limits<double>::max();
    for (int s = 0; s < samples.count; ++s)
        phi = std::min(phi, coverage(*in.projection, corners, samples.eyeSpace[s]) *
                                box.distance(in.eye + samples.world[s]));
    return phi;
}
// Nearest nodes first (ties by node id), gathering the candidate objects each holds until there are
// enough; `Tree` says how a node's box, objects and children are read.
template <class Tree> void gatherCandidates(const MaskSelectionInput& in, const Tree& tree, MaskSelectionScratch& scratch)
{
    // Enough candidates to choose from, without walking the whole city.
    const std::size_t wanted = std::size_t(in.count) * 4;
    using Entry = MaskSelectionScratch::Entry;
    std::vector<Entry>& queue = scratch.queue;
    std::vector<std::pair<double, ObjectId>>& candidates = scratch.candidates;
    queue.clear();
    candidates.clear();
    const EyeSamples samples(in);
    const auto push = [&](std::uint32_t node)
    {
        queue.push_back({tree.bounds(node).distance(in.eye), node});
        std::push_heap(queue.begin(), queue.end());
    };
    tree.forEachRoot(push);
    while (!queue.empty() && candidates.size() < wanted)
    {
        std::pop_heap(queue.begin(), queue.end());
        const Entry top = queue.back();
        queue.pop_back();
        if (tree.objectCount(top.node) == 0 || in.view->frustum.classify(tree.bounds(top.node)) == Containment::Outside)
            continue;
        tree.forEachHeld(top.node, [&](ObjectId id)
                         {
                             const Aabb& box = (*in.objects)[id].bounds;
                             if (!(*in.usable)[id] || box.distance(in.eye) < in.minDistance ||
                                 in.view->frustum.classify(box) == Containment::Outside)
                                 return;
                             candidates.push_back({importance(in, samples, box), id});
                         });
        tree.forEachChild(top.node, push);
    }
}

struct KdTreeNodes
{
    const MaskKdTree& tree;
    template <class F> void forEachRoot(F&& f) const { f(tree.root()); }
    const Aabb& bounds(std::uint32_t n) const { return tree.node(n).bounds; }
    std::uint32_t objectCount(std::uint32_t n) const { return tree.node(n).objectCount; }
    template <class F> void forEachHeld(std::uint32_t n, F&& f) const
    {
        for (ObjectId id : tree.node(n).objects)
            f(id);
    }
    template <class F> void forEachChild(std::uint32_t n, F&& f) const
    {
        if (!tree.node(n).leaf())
            f(tree.node(n).left), f(tree.node(n).right);
    }
};

// The renderer's hierarchy as recorded at setScene (its tight contents boxes).
struct RecordedNodes
{
    const HierarchyIndex& index;
    template <class F> void forEachRoot(F&& f) const
    {
        for (std::uint32_t root : index.roots())
            f(root);
    }
    const Aabb& bounds(std::uint32_t n) const { return index.node(n).contents; }
    std::uint32_t objectCount(std::uint32_t n) const { return index.node(n).subtreeEnd - index.node(n).firstObject; }
    template <class F> void forEachHeld(std::uint32_t n, F&& f) const
    {
        const HierarchyIndex::Node& node = index.node(n);
        for (std::uint32_t i = node.firstObject; i < node.firstObject + node.heldCount; ++i)
            f(index.objects()[i]);
    }
    template <class F> void forEachChild(std::uint32_t n, F&& f) const
    {
        const HierarchyIndex::Node& node = index.node(n);
        for (std::uint32_t i = node.firstChild; i < node.firstChild + node.childCount; ++i)
            f(index.childIds()[i]);
    }
};
} // namespace

void selectMaskOccluders(const MaskSelectionInput& in, MaskSelectionScratch& scratch, std::vector<ObjectId>& chosen)
{
    chosen.clear();
    if (in.count == 0 || (in.hierarchy ? in.hierarchy->objects().empty() : (!in.tree || in.tree->empty())))
        return;
    if (in.hierarchy)
        gatherCandidates(in, RecordedNodes{*in.hierarchy}, scratch);
    else
        gatherCandidates(in, KdTreeNodes{*in.tree}, scratch);
    std::vector<std::pair<double, ObjectId>>& candidates = scratch.candidates;
    const auto better = [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); };
    const std::size_t keep = std::min<std::size_t>(in.count, candidates.size());
    std::partial_sort(candidates.begin(), candidates.begin() + keep, candidates.end(), better);
    for (std::size_t i = 0; i < keep; ++i)
        chosen.push_back(candidates[i].second);
}
} // namespace osgVis::core
