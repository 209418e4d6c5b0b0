// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Dynamic occluder choice (Coorg & Teller): a polygon is worth testing when its area-angle
/// A·(N·D̂)/|D|² (N its unit normal, D the vector from the eye to its centroid, D̂ = D/|D|) is
/// large. Space is divided into leaf cells; each leaf lists its potential occluders, the polygons
/// whose metric can exceed the threshold from some point of the leaf; per frame the k best of the
/// eye leaf's list, at the eye's exact position, are the actual occluders.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/occluders/OccluderPolygon.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
/// |A·(N·D̂)/|D|²|; 0 when the eye sees the polygon edge-on, from its culled side (one-sided) or
/// stands on it.
double areaAngle(const OccluderPolygon& polygon, const Vec3& eye);

struct OccluderSelectorOptions
{
    double threshold = 0.01;            ///< area-angle a polygon must be able to reach from a leaf
    std::uint32_t maxLeafPolygons = 64; ///< split a leaf while it lists more than this…
    std::uint32_t maxDepth = 8;         ///< …down to this depth
};

class OccluderSelector
{
public:
    /// `region` is the part of space with leaves (the scene bounds, enlarged a little); an eye
    /// outside it uses the root's list, which holds every polygon. A leaf lists each polygon whose
    /// areaAngle can reach the threshold from some point of the leaf's closed box (an upper bound
    /// over the box decides, so lists may hold a few more). Splitting also stops at fixed caps on
    /// cells and list entries, so dense scenes keep a bounded tree. `polygons` must outlive the
    /// selector's use.
    void build(const std::vector<OccluderPolygon>& polygons, const Aabb& region, const OccluderSelectorOptions& options = {});

    /// Leaf holding `eye` (root index 0 when outside the region).
    std::uint32_t leafOf(const Vec3& eye) const;
    /// A leaf's list is ordered by an upper bound of each polygon's areaAngle over the leaf's box,
    /// largest first (ties by index); the root's (eyes outside the region) is in index order.
    const std::vector<std::uint32_t>& potentialOccluders(std::uint32_t leaf) const;
    /// Those bounds, one per entry of potentialOccluders(leaf), so that a search for the best
    /// can stop early; empty where no bound holds (the root).
    const std::vector<double>& potentialOccluderBounds(std::uint32_t leaf) const;
    const Aabb& leafBounds(std::uint32_t leaf) const;

    /// The k polygons of the eye leaf's list with the largest areaAngle at `eye` (at least the
    /// threshold), best first; ties broken by index so the choice is deterministic. No allocation
    /// once `out` has capacity k.
    void select(const Vec3& eye, std::uint32_t k, std::vector<std::uint32_t>& out) const;

private:
    struct Cell
    {
        Aabb bounds;
        std::uint32_t firstChild = 0; ///< 8 children from here; 0 for a leaf
        std::vector<std::uint32_t> polygons;
        std::vector<double> metricBounds; ///< leaves but the root: per polygon its areaAngle bound, descending
    };
    void sortLeafLists();
    const std::vector<OccluderPolygon>* _polygons = nullptr;
    std::vector<Cell> _cells;
    double _threshold = 0.0;
};
} // namespace osgVis::core
