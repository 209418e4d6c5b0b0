// SPDX-License-Identifier: MIT
#pragma once
// Temporal coherence of the octree module: each box (tree node or object) keeps the planes of the
// occluders it met in recent frames, which do not depend on the eye, and the occluder that
// decided it last. The next frame re-checks the eye against those planes instead of rebuilding
// them, and tries the last deciding occluder first.
#include <osgVis/core/octree/BoxOcclusion.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
constexpr std::uint32_t NoDecider = ~std::uint32_t(0);
constexpr std::uint32_t FusedDecider = NoDecider - 1;

struct OccluderRelation
{
    std::uint32_t occluder = NoDecider;
    std::uint32_t lastFrame = 0;
    BoxOccluderPlanes planes;
};

class BoxOcclusionCache
{
public:
    // Planes of `occluder` against `box`, computed only when not cached. `computed` tells which.
    const BoxOccluderPlanes& planesFor(std::uint32_t occluder, const PreparedOccluder& polygon, const Aabb& box,
                                       std::uint32_t frame, bool& computed);

    // Forgets everything (a module without temporal coherence calls it every frame).
    void clear()
    {
        _relations.clear();
        _occluders.clear();
        decidedBy = NoDecider;
    }

    std::uint32_t decidedBy = NoDecider; // occluder (or FusedDecider) that hid the box last time

    // Bounded so memory stays proportional to the tree, not to the frames walked. A frame may use
    // at most this many occluders (references returned in one frame stay valid).
    static constexpr std::size_t MaxRelations = 64;

private:
    std::vector<OccluderRelation> _relations;
    std::vector<std::uint32_t> _occluders; // _relations[i].occluder, packed: the lookup scans only these

};
} // namespace osgVis::core
