// SPDX-License-Identifier: MIT
// Plane placement for the multifocal z-buffer (Marsden & Guibas, §4.5, §5.3). The rule is ours
// (the paper leaves it open) and is written down in docs/multifocal.md, "Planes".
#include "PlanePlacement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
std::vector<double> planeDepths(std::vector<DepthSample> samples, int count, double minDepth)
{
    std::vector<double> depths;
    if (samples.empty() || count <= 0)
        return depths;
    std::sort(samples.begin(), samples.end(), [](const DepthSample& a, const DepthSample& b)
              { return a.depth < b.depth || (a.depth == b.depth && a.weight > b.weight); });
    double total = 0.0;
    for (const DepthSample& s : samples)
        total += s.weight;
    if (!(total > 0.0))
        return depths;
    // Dyadic fractions 1/2, 1/4, 3/4, 1/8, 3/8, ...: the planes of K are among those of K + 1, so
    // more planes never cull less.
    std::vector<double> fractions;
    for (int denominator = 2; int(fractions.size()) < count; denominator *= 2)
        for (int numerator = 1; numerator < denominator && int(fractions.size()) < count; numerator += 2)
            fractions.push_back(double(numerator) / double(denominator));
    std::sort(fractions.begin(), fractions.end());
    double running = 0.0;
    std::size_t next = 0;
    for (double fraction : fractions)
    {
        const double target = total * fraction;
        while (next + 1 < samples.size() && running + samples[next].weight < target)
            running += samples[next++].weight;
        const double depth = std::max(samples[next].depth, minDepth);
        if (depths.empty() || depth > depths.back())
            depths.push_back(depth);
    }
    return depths;
}

CorrespondencePlane placePlane(const VolumeFace& face, const Aabb& volume, double depth,
                               const std::vector<Aabb>& occludees, double maxAngle, int resolution)
{
    CorrespondencePlane plane;
    plane.axis = face.axis;
    plane.direction = face.direction;
    plane.position = face.coordinate + face.direction * depth;
    plane.u = face.axis == 0 ? 1 : 0;
    plane.v = face.axis == 2 ? 1 : 2;
    plane.width = plane.height = 0;
    // Rays leaving V at up to maxAngle from the face's normal cross P within V's cross-section
    // grown by (depth + V's thickness)·tan(maxAngle).
    const double thickness = volume.max[face.axis] - volume.min[face.axis];
    const double reach = (depth + thickness) * std::tan(maxAngle);
    const Vec2 limitLo = Vec2(volume.min[plane.u], volume.min[plane.v]) - Vec2(reach);
    const Vec2 limitHi = Vec2(volume.max[plane.u], volume.max[plane.v]) + Vec2(reach);
    const auto corners = boxCorners(volume);
    Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const Aabb& box : occludees)
        for (const Vec3& c : corners)
            for (const Vec3& x : boxCorners(box))
            {
                const Vec2 q = plane.project(c, x);
                lo = glm::min(lo, q);
                hi = glm::max(hi, q);
            }
    lo = glm::max(lo, limitLo);
    hi = glm::min(hi, limitHi);
    if (!(lo.x < hi.x && lo.y < hi.y) || resolution <= 0)
        return plane;
    const Vec2 span = hi - lo;
    plane.pixel = std::max(span.x, span.y) / double(resolution);
    // One pixel of margin on each side, so footprints touching the window's edge stay testable.
    plane.origin = lo - Vec2(plane.pixel);
    plane.width = int(std::ceil(span.x / plane.pixel)) + 2;
    plane.height = int(std::ceil(span.y / plane.pixel)) + 2;
    return plane;
}
} // namespace osgVis::core
