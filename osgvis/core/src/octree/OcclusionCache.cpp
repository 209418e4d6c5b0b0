// SPDX-License-Identifier: MIT
#include "OcclusionCache.h"

namespace osgVis::core
{
const BoxOccluderPlanes& BoxOcclusionCache::planesFor(std::uint32_t occluder, const PreparedOccluder& polygon,
                                                      const Aabb& box, std::uint32_t frame, bool& computed)
{
    for (std::size_t i = 0; i < _occluders.size(); ++i)
        if (_occluders[i] == occluder)
        {
            OccluderRelation& relation = _relations[i];
            relation.lastFrame = frame;
            computed = false;
            return relation.planes;
        }

    if (_relations.capacity() < MaxRelations)
        _relations.reserve(MaxRelations); // never reallocates afterwards: earlier references stay valid
    std::size_t index = _relations.size();
    if (index < MaxRelations)
    {
        _relations.emplace_back();
        _occluders.push_back(occluder);
    }
    else
    {
        index = 0;
        for (std::size_t i = 1; i < _relations.size(); ++i)
            if (_relations[i].lastFrame < _relations[index].lastFrame)
                index = i;
        _occluders[index] = occluder;
    }
    OccluderRelation* slot = &_relations[index];
    slot->occluder = occluder;
    slot->lastFrame = frame;
    computePlanes(polygon, box, slot->planes);
    computed = true;
    return slot->planes;
}
} // namespace osgVis::core
