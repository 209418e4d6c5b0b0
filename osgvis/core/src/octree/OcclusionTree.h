// SPDX-License-Identifier: MIT
#pragma once
// Occluder fusion for occluders that share no edge: an occlusion tree (after Bittner, Havran &
// Slavík, "Hierarchical visibility culling with occlusion trees"), a BSP tree over the directions
// in front of one eye, kept as lines in the image plane (direction d ↦ (d·right, d·up) / d·forward),
// whose "in" leaves say which occluders cover every direction of the leaf. Occluders are inserted
// front to back; a convex hull is hidden when every leaf its image reaches (clipped by the lines
// on the way down) is "in" and the hull lies behind one of that leaf's occluders. Many small
// occluders (a field of rocks, a forest) then hide together what none hides alone.
//
// Conservative by construction: an "in" leaf lies inside each of its occluders' images shrunk by
// the occluder's margin (every edge line moves into the polygon by at least the margin's angle,
// unless the caller says the edge is shared with a neighbour inserted alongside, where
// rasterization leaves no crack). A leaf gets only the edge lines its fragment touches; a vertex
// the clipping put on a line stays within rounding of it (clipping interpolates along edges, and
// the distance to the cutting line is affine there), far inside the touch tolerance, and clipping
// keeps vertices near a line on both sides, so a needed line is never left out.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/geometry/Plane.h>

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
class OcclusionTree
{
public:
    using Point = glm::dvec2;

    /// Forgets every occluder. `forward`: the view direction (unit); only what lies in front of
    /// the eye along it takes part. `sceneSize` scales the numerical tolerances.
    void reset(const Vec3& eye, const Vec3& forward, double sceneSize);

    /// Adds a convex polygon seen from its front (the eye on the positive side of `plane`), every
    /// vertex in front of the eye. Edge i (vertices[i] → vertices[i+1]) is pulled into the
    /// polygon by `edgeMargins[i]` (world units at the edge's nearer end; 0 for an edge shared
    /// exactly with a neighbour inserted alongside). Returns false (and adds nothing) for a
    /// polygon the eye does not see from the front, one reaching behind the eye, one with fewer
    /// than three vertices, or one its margins shrink to nothing.
    bool insert(const std::vector<Vec3>& vertices, const Plane& plane, const std::vector<double>& edgeMargins);

    /// True when every ray from the eye to the convex hull of `points` (which lies in `bounds`)
    /// meets an inserted occluder before the hull, with `depthTolerance` to spare (z-fighting).
    bool hidden(const Vec3* points, std::size_t count, const Aabb& bounds, double depthTolerance) const;
    /// The same for a box (its eight corners).
    bool hidden(const Aabb& box, double depthTolerance) const;

    std::size_t nodeCount() const { return _nodes.size(); }
    /// Steps taken since reset (fragments and query regions moved down a node, points projected):
    /// a deterministic measure of the time inserting and querying took, for work budgets.
    std::uint64_t work() const { return _work; }
    std::size_t occluderCount() const { return _occluders.size(); }

    /// Leaves hold at most this many occluders; a fragment that finds a full leaf is dropped.
    static constexpr std::size_t MaxLeafOccluders = 4;

private:
    // A child reference: a node index (>= 0), Out, or an "in" leaf as InLeaf - leafIndex.
    using Ref = std::int32_t;
    static constexpr Ref Out = -1;
    static constexpr Ref InLeaf = -2;

    struct Line // inside where dot(normal, p) + offset >= 0; normal of unit length
    {
        Point normal;
        double offset;
        double at(const Point& p) const { return normal.x * p.x + normal.y * p.y + offset; }
    };
    struct Node
    {
        Line line;
        Ref positive = Out, negative = Out;
    };
    struct Occluder
    {
        Plane plane;        // eye on the positive side
        double maxDistance; // farthest vertex from the eye
    };
    struct Leaf
    {
        std::uint32_t count = 0;
        std::uint32_t occluders[MaxLeafOccluders] = {};
    };
    // Where a child reference lives: a node's positive or negative child, or the root (node -1).
    // Held as indices because inserting grows _nodes.
    struct Slot
    {
        Ref node;
        bool positive;
    };

    struct Fragment // of the image being inserted, on its way to `slot`
    {
        Slot slot;
        std::uint32_t begin, count; // its points in _arena
    };
    struct QueryRegion // of a query's image, on its way down from `ref`
    {
        Ref ref;
        std::uint32_t begin, count; // its points in _queryArena
    };

    bool project(const Vec3& p, Point& image) const;
    Ref& at(Slot slot);
    void insertShrunkImage(const std::vector<Vec3>& polygon, std::uint32_t occluder);
    void pushClipped(const Line& line, bool positive, Slot slot);
    void addToLeaf(Slot slot, Ref ref, const Point* fragment, std::size_t count, const std::vector<Vec3>& polygon,
                   std::uint32_t occluder);
    bool coversBehind(const Leaf& leaf, const std::vector<Vec3>& polygon) const;
    bool hiddenInLeaf(const Leaf& leaf, const Vec3* points, std::size_t count, double nearest,
                      double depthTolerance) const;

    Vec3 _eye{0.0}, _forward{0.0, 1.0, 0.0}, _right{1.0, 0.0, 0.0}, _up{0.0, 0.0, 1.0};
    double _sceneSize = 1.0;
    std::vector<Node> _nodes;
    std::vector<Leaf> _leaves;
    std::vector<Occluder> _occluders;
    Ref _root = Out;
    mutable std::uint64_t _work = 0;
    // Scratch, kept between calls so that inserting and querying allocate nothing once grown.
    std::vector<Line> _edgeLines; // of the occluder being inserted
    std::vector<Point> _image, _clipped, _arena, _region;
    std::vector<Fragment> _fragments;
    mutable std::vector<Point> _queryImage, _queryArena, _queryRegion;
    mutable std::vector<QueryRegion> _queryStack;
};
} // namespace osgVis::core
