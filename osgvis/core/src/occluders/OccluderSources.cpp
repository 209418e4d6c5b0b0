// SPDX-License-Identifier: MIT
#include "OccluderSources.h"

#include <algorithm>

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

std::pair<std::size_t, std::size_t> triangleRange(const Scene& scene, const SceneObject& object)
{
    const std::size_t first = std::min<std::size_t>(object.firstTriangle, scene.triangles.size());
    const std::size_t end =
        std::min<std::size_t>(std::size_t(object.firstTriangle) + object.triangleCount, scene.triangles.size());
    return {first, std::max(first, end)};
}
} // namespace osgVis::core
