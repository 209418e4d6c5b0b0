// SPDX-License-Identifier: MIT
#include "OccluderSources.h"

namespace osgVis::core
{
bool isEligible(const SceneObject& object, bool sceneGeometry)
{
    const std::uint32_t flags = object.flags;
    // Moving, see-through or unbounded geometry never hides anything reliably, stated or not.
    if (flags & (OBJECT_DYNAMIC | OBJECT_TRANSPARENT | OBJECT_ALWAYS_VISIBLE))
        return false;
    if ((flags & OBJECT_CULL_BACK) && (flags & OBJECT_CULL_FRONT))
        return false; // neither side is drawn
    // A stated occluder is the modeller's word, so it needs no automatic eligibility.
    if (flags & OBJECT_OCCLUDER)
        return true;
    return sceneGeometry && !(flags & OBJECT_NO_AUTO_OCCLUDER);
}
} // namespace osgVis::core
