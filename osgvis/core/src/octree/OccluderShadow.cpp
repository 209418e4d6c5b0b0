// SPDX-License-Identifier: MIT
#include "OccluderShadow.h"

#include <cmath>

namespace osgVis::core
{
void OccluderShadows::begin(std::size_t polygonCount)
{
    for (std::uint32_t index : _added)
        _slots[index] = Slot();
    _added.clear();
    _slots.resize(polygonCount);
    _planes.clear();
    _normalLengths.clear();
}

void OccluderShadows::add(std::uint32_t index, const OccluderPolygon& polygon, const Vec3& eye, double margin)
{
    if (index >= _slots.size())
        return;
    Slot& slot = _slots[index];
    slot = Slot();
    slot.added = true;
    _added.push_back(index);
    const double eyeDistance = polygon.plane.distance(eye);
    if (!(std::abs(eyeDistance) > margin) || (polygon.oneSided && eyeDistance < 0.0))
        return; // hides nothing from here
    slot.empty = false;
    slot.first = std::uint32_t(_planes.size());
    // Behind the occluder: the half-space away from the eye.
    _planes.push_back(eyeDistance > 0.0 ? Plane(-polygon.plane.normal, -polygon.plane.d) : polygon.plane);
    const std::size_t n = polygon.vertices.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        Plane edge = Plane::fromPointNormal(eye, glm::cross(polygon.vertices[i] - eye, polygon.vertices[(i + 1) % n] - eye));
        // Inside is the polygon's side; the centroid tells which way the cross product came out.
        if (edge.distance(polygon.centroid) < 0.0)
            edge = Plane(-edge.normal, -edge.d);
        if (std::isfinite(edge.d) && edge.normal != Vec3(0.0))
            _planes.push_back(edge);
    }
    for (std::size_t p = slot.first; p < _planes.size(); ++p)
        _normalLengths.push_back(glm::length(_planes[p].normal));
    slot.count = std::uint32_t(_planes.size()) - slot.first;
}

bool OccluderShadows::misses(std::uint32_t index, const Aabb& box) const
{
    if (index >= _slots.size())
        return false;
    const Slot& slot = _slots[index];
    if (!slot.added)
        return false;
    if (slot.empty)
        return true;
    const Vec3 center = box.center(), half = 0.5 * box.extent();
    const double centerLength = glm::length(center);
    for (std::uint32_t p = slot.first; p < slot.first + slot.count; ++p)
    {
        const Plane& plane = _planes[p];
        const double reach = std::abs(plane.normal.x) * half.x + std::abs(plane.normal.y) * half.y +
                             std::abs(plane.normal.z) * half.z;
        // Strictly outside, by more than the rounding of the distance itself.
        if (plane.distance(center) + reach < -1e-12 * (std::abs(plane.d) + _normalLengths[p] * centerLength))
            return true;
    }
    return false;
}
} // namespace osgVis::core
