// SPDX-License-Identifier: MIT
// Automatic cell subdivision after Teller & Séquin, "Visibility Preprocessing for Interactive
// Walkthroughs" (SIGGRAPH '91): a kd-tree over the scene box split along the planes that opaque
// axial faces cover most (union of the faces in the node's cross-section over its area), breadth
// first so a cell budget spreads evenly; leaves are the cells, then the portals between them.
#include <osgVis/core/cellportal/CellSubdivision.h>

#include "PortalEnumeration.h"
#include "SubdivisionRectSet.h"
#include "SubdivisionStatedCells.h"
#include "SubdivisionTolerance.h"

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
        const int axis = r.axis, u = AxialRect::uAxis(axis), v = AxialRect::vAxis(axis);
        if (!(r.coordinate > box.min[axis] + minSize) || !(r.coordinate < box.max[axis] - minSize))
            continue;
        AxialRect clipped = r;
        clipped.uMin = std::max(r.uMin, box.min[u]);
        clipped.uMax = std::min(r.uMax, box.max[u]);
        clipped.vMin = std::max(r.vMin, box.min[v]);
        clipped.vMax = std::min(r.vMax, box.max[v]);
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

// Root box: the scene's finite bounds grown so an eye at the model's very edge is inside a cell.
Aabb rootBox(const Scene& scene)
{
    Aabb box = scene.bounds();
    if (box.empty())
        return box;
    const Vec3 magnitude = glm::max(glm::abs(box.min), glm::abs(box.max));
    const double margin =
        1e-3 * glm::length(box.extent()) + 1e-6 * (1.0 + std::max({magnitude.x, magnitude.y, magnitude.z}));
    return {box.min - Vec3(margin), box.max + Vec3(margin)};
}

// Leaves get cell numbers in depth-first order, low child first, so that nearby cells have nearby
// numbers and kd queries report cells in ascending order.
void numberCells(CellGraph& graph, const std::vector<Aabb>& nodeBoxes)
{
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty())
    {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        CellGraph::KdNode& node = graph.nodes[n];
        if (node.axis > 2)
        {
            node.children[0] = std::uint32_t(graph.cells.size());
            graph.cells.push_back(nodeBoxes[n]);
            continue;
        }
        stack.push_back(node.children[1]);
        stack.push_back(node.children[0]);
    }
}

CellGraph automaticCellGraph(const Scene& scene, const SubdivisionOptions& options)
{
    CellGraph graph;
    graph.bounds = rootBox(scene);
    if (graph.bounds.empty())
        return graph; // nothing with finite bounds: no cell to stand in
    const double tolerance = subdivisionTolerance(graph.bounds);
    const double minSize = std::max(options.minCellSize * glm::length(graph.bounds.extent()), tolerance);
    const std::vector<OpaqueFace> faces = findOpaqueAxialFaces(scene);

    std::vector<Aabb> nodeBoxes{graph.bounds};
    graph.nodes.emplace_back();
    std::deque<PendingNode> pending;
    {
        PendingNode root{0, graph.bounds, 0, {}};
        for (std::uint32_t i = 0; i < faces.size(); ++i)
            root.faces.push_back(i);
        pending.push_back(std::move(root));
    }
    std::uint32_t leaves = 1;
    const std::uint32_t maxCells = std::max<std::uint32_t>(options.maxCells, 1);
    while (!pending.empty())
    {
        PendingNode work = std::move(pending.front());
        pending.pop_front();
        if (work.depth >= options.maxDepth || leaves >= maxCells)
            continue;
        const SplitChoice split = chooseSplit(work.box, work.faces, faces, options, minSize, tolerance);
        if (split.axis < 0)
            continue;

        const int axis = split.axis;
        PendingNode low{std::uint32_t(graph.nodes.size()), work.box, work.depth + 1, {}};
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
        CellGraph::KdNode& node = graph.nodes[work.node];
        node.axis = std::uint8_t(axis);
        node.split = split.coordinate;
        node.children[0] = low.node;
        node.children[1] = high.node;
        graph.nodes.emplace_back();
        graph.nodes.emplace_back();
        nodeBoxes.push_back(low.box);
        nodeBoxes.push_back(high.box);
        ++leaves;
        pending.push_back(std::move(low));
        pending.push_back(std::move(high));
    }

    numberCells(graph, nodeBoxes);
    enumeratePortals(graph, faces, tolerance);
    return graph;
}
} // namespace

CellGraph subdivideCells(const Scene& scene, const SubdivisionOptions& options)
{
    if (!scene.cells.empty())
    {
        Aabb statedBounds;
        for (const Cell& cell : scene.cells)
            statedBounds.expand(cell.bounds);
        return statedCellGraph(scene, subdivisionTolerance(statedBounds));
    }
    return automaticCellGraph(scene, options);
}
} // namespace osgVis::core
