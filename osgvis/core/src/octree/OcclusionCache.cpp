// SPDX-License-Identifier: MIT
#include "OcclusionCache.h"

namespace osgVis::core
{
const BoxOccluderPlanes& BoxOcclusionCache::planesFor(std::uint32_t occluder, const OccluderPolygon& polygon,
                                                      const Aabb& box, std::uint32_t frame, bool& computed)
{
    for (OccluderRelation& relation : _relations)
        if (relation.occluder == occluder)
        {
            relation.lastFrame = frame;
            computed = false;
            return relation.planes;
        }

    if (_relations.capacity() < MaxRelations)
        _relations.reserve(MaxRelations); // never reallocates afterwards: earlier references stay valid
    OccluderRelation* slot = nullptr;
    if (_relations.size() < MaxRelations)
        slot = &_relations.emplace_back();
    else
    {
        slot = &_relations.front();
        for (OccluderRelation& relation : _relations)
            if (relation.lastFrame < slot->lastFrame)
                slot = &relation;
    }
    slot->occluder = occluder;
    slot->lastFrame = frame;
    computePlanes(polygon, box, slot->planes);
    computed = true;
    return slot->planes;
}
} // namespace osgVis::core
