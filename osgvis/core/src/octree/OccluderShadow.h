// SPDX-License-Identifier: MIT
#pragma once
// Shadow frustum of an occluder from a point eye (Hudson et al., "Accelerated occlusion culling
// using shadow frusta", SoCG 1997, §3): the planes through the eye and each edge, and the
// occluder's own plane. A box wholly outside one of them has no point the occluder hides, so the
// octree skips Coorg & Teller's eye-independent planes for it (computing them costs a silhouette
// search per edge against the box's corners; this is one dot product per plane). The pre-test only
// ever answers "hides none of it": the Invisible decision stays with classify() and its margins.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/occluders/OccluderPolygon.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
class OccluderShadows
{
public:
    /// Forgets the previous frame's shadows; `polygonCount` sizes the per-polygon slots. Costs
    /// what the last frame added, not the polygon count.
    void begin(std::size_t polygonCount);
    /// Shadow of `polygons[index]` seen from `eye`. An eye on the plane (within `margin`), or on
    /// the culled side of a one-sided polygon, gets an empty shadow: classify() calls that Visible.
    void add(std::uint32_t index, const OccluderPolygon& polygon, const Vec3& eye, double margin);
    /// True when no point of `box` lies in the shadow of polygon `index` (added this frame).
    bool misses(std::uint32_t index, const Aabb& box) const;

private:
    struct Slot
    {
        std::uint32_t first = 0, count = 0; ///< its planes in _planes
        bool added = false;                 ///< false: not an occluder this frame (never misses)
        bool empty = true;                  ///< hides nothing from this eye
    };
    std::vector<Slot> _slots;
    std::vector<std::uint32_t> _added;
    std::vector<Plane> _planes;
    std::vector<double> _normalLengths; ///< per plane: |normal|, for the rounding bound in misses()
};
} // namespace osgVis::core
