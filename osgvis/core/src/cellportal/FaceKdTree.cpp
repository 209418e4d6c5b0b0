// SPDX-License-Identifier: MIT
// The kd-tree both automatic subdivisions build (Teller & Séquin's, on the model's opaque axial
// faces; the solid-space one, on the faces of solid boxes): split breadth first at the plane whose
// faces cover most of a node's cross-section, so a cell budget spreads evenly.
#include "FaceKdTree.h"

#include "SubdivisionRectSet.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace osgVis::core
{
namespace
{
struct PendingNode
{
    std::uint32_t node;
    Aabb box;
    std::uint32_t depth;
    std::vector<std::uint32_t> faces; // indices of the opaque faces overlapping the box
};

struct SplitChoice
{
    int axis = -1;
    double coordinate = 0.0;
    double coverage = 0.0;
    double area = 0.0;
};

// A face clipped to a node's cross-section, for scoring the plane it lies in.
struct PlaneFace
{
    int axis;
    double coordinate;
    AxialRect clipped;
};

// The best split plane of `box` among the planes of `faces`, or axis -1. Faces whose coordinates
// are within `tolerance` of the first one of a run count as one plane (float storage noise).
SplitChoice chooseSplit(const Aabb& box, const std::vector<std::uint32_t>& faceIds,
                        const std::vector<OpaqueFace>& faces, const SubdivisionOptions& options, double minSize,
                        double tolerance)
{
    std::vector<PlaneFace> candidates;
    for (std::uint32_t id : faceIds)
    {
        const AxialRect& r = faces[id].rect;
        const int axis = r.axis;
        if (!(r.coordinate > box.min[axis] + minSize) || !(r.coordinate < box.max[axis] - minSize))
            continue;
        const AxialRect clipped = r.clippedTo(box);
        if (!clipped.empty())
            candidates.push_back({axis, r.coordinate, clipped});
    }
    std::sort(candidates.begin(), candidates.end(), [](const PlaneFace& a, const PlaneFace& b)
              { return a.axis != b.axis ? a.axis < b.axis : a.coordinate < b.coordinate; });

    SplitChoice best;
    std::vector<AxialRect> plane;
    for (std::size_t i = 0; i < candidates.size();)
    {
        const int axis = candidates[i].axis;
        const double coordinate = candidates[i].coordinate;
        plane.clear();
        std::size_t end = i;
        for (; end < candidates.size() && candidates[end].axis == axis &&
               candidates[end].coordinate - coordinate <= tolerance;
             ++end)
            plane.push_back(candidates[end].clipped);
        i = end;

        const int u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
        const double crossSection = (box.max[u] - box.min[u]) * (box.max[v] - box.min[v]);
        const double area = unionArea(plane);
        const double coverage = crossSection > 0.0 ? area / crossSection : 0.0;
        const bool qualifies = coverage >= options.minCoverage || (options.minFaceArea > 0.0 && area >= options.minFaceArea);
        // Ties go to the larger area, then the smaller axis and coordinate (the visiting order).
        if (qualifies && (best.axis < 0 || coverage > best.coverage || (coverage == best.coverage && area > best.area)))
            best = {axis, coordinate, coverage, area};
    }
    return best;
}
} // namespace

Aabb subdivisionRootBox(const Scene& scene)
{
    Aabb box = scene.bounds();
    if (box.empty())
        return box;
    const Vec3 magnitude = glm::max(glm::abs(box.min), glm::abs(box.max));
    const double margin =
        1e-3 * glm::length(box.extent()) + 1e-6 * (1.0 + std::max({magnitude.x, magnitude.y, magnitude.z}));
    return {box.min - Vec3(margin), box.max + Vec3(margin)};
}

void numberCells(CellGraph& graph, const std::vector<Aabb>& nodeBoxes, const std::vector<bool>* leafIsCell)
{
    std::uint32_t leaf = 0;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty())
    {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        CellGraph::KdNode& node = graph.nodes[n];
        if (node.axis > 2)
        {
            const bool cell = !leafIsCell || (*leafIsCell)[leaf];
            ++leaf;
            node.children[0] = cell ? std::uint32_t(graph.cells.size()) : NoCell;
            if (cell)
                graph.cells.push_back(nodeBoxes[n]);
            continue;
        }
        stack.push_back(node.children[1]);
        stack.push_back(node.children[0]);
    }
}

FaceKdTree buildFaceKdTree(const Aabb& root, const std::vector<OpaqueFace>& faces, const SubdivisionOptions& options,
                           double tolerance, const std::function<bool(const Aabb&)>& settled)
{
    FaceKdTree tree;
    const double minSize = std::max(options.minCellSize * glm::length(root.extent()), tolerance);
    tree.nodeBoxes.push_back(root);
    tree.nodes.emplace_back();
    std::deque<PendingNode> pending;
    {
        PendingNode first{0, root, 0, {}};
        for (std::uint32_t i = 0; i < faces.size(); ++i)
            first.faces.push_back(i);
        pending.push_back(std::move(first));
    }
    std::uint32_t leaves = 1;
    const std::uint32_t maxCells = std::max<std::uint32_t>(options.maxCells, 1);
    while (!pending.empty())
    {
        PendingNode work = std::move(pending.front());
        pending.pop_front();
        if (work.depth >= options.maxDepth || leaves >= maxCells || work.faces.empty() || (settled && settled(work.box)))
            continue;
        const SplitChoice split = chooseSplit(work.box, work.faces, faces, options, minSize, tolerance);
        if (split.axis < 0)
            continue;

        const int axis = split.axis;
        PendingNode low{std::uint32_t(tree.nodes.size()), work.box, work.depth + 1, {}};
        PendingNode high{low.node + 1, work.box, work.depth + 1, {}};
        low.box.max[axis] = split.coordinate;
        high.box.min[axis] = split.coordinate;
        for (std::uint32_t id : work.faces)
        {
            const AxialRect& r = faces[id].rect;
            double lo = r.coordinate, hi = r.coordinate; // extent along the split axis
            if (r.axis != axis)
            {
                const bool alongU = AxialRect::uAxis(r.axis) == axis;
                lo = alongU ? r.uMin : r.vMin;
                hi = alongU ? r.uMax : r.vMax;
            }
            // A face in the split plane goes to both sides: it now lies on both boundaries.
            const bool inPlane = r.axis == axis;
            if (inPlane ? lo <= split.coordinate + tolerance : lo < split.coordinate - tolerance)
                low.faces.push_back(id);
            if (inPlane ? hi >= split.coordinate - tolerance : hi > split.coordinate + tolerance)
                high.faces.push_back(id);
        }
        CellGraph::KdNode& node = tree.nodes[work.node];
        node.axis = std::uint8_t(axis);
        node.split = split.coordinate;
        node.children[0] = low.node;
        node.children[1] = high.node;
        tree.nodes.emplace_back();
        tree.nodes.emplace_back();
        tree.nodeBoxes.push_back(low.box);
        tree.nodeBoxes.push_back(high.box);
        ++leaves;
        pending.push_back(std::move(low));
        pending.push_back(std::move(high));
    }
    return tree;
}
} // namespace osgVis::core
