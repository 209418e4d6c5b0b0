// SPDX-License-Identifier: MIT
#include "BoundaryLoop.h"

#include <osgVis/core/geometry/Aabb.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
constexpr double TwoPi = 6.28318530717958647692;
} // namespace

double storageSlack(const Vec3& p)
{
    const double magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return 4.0 * magnitude * 0x1p-24;
}

Turn turnAt(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal, double tolerance)
{
    const Vec3 in = b - a;
    const Vec3 out = c - b;
    const Vec3 cross = glm::cross(in, out);
    const double scale = glm::length(in) * glm::length(out);
    if (!(scale > 0.0))
        return Turn::Reflex; // repeated vertex: never part of a clean outline
    // |in × out| = distance of b from the line a–c × |c − a|.
    const double slack = std::max({storageSlack(a), storageSlack(b), storageSlack(c)});
    if (glm::length(cross) <= tolerance * scale + slack * glm::length(c - a))
        return glm::dot(in, out) > 0.0 ? Turn::Straight : Turn::Reflex;
    return glm::dot(cross, normal) > 0.0 ? Turn::Convex : Turn::Reflex;
}

std::vector<std::size_t> cornerIndices(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions,
                                       const Vec3& normal, double tolerance, const std::vector<bool>& keep)
{
    const std::size_t n = loop.size();
    std::vector<std::size_t> corners;
    if (n < 3)
    {
        for (std::size_t i = 0; i < n; ++i)
            corners.push_back(i);
        return corners;
    }
    auto at = [&](std::size_t i) -> const Vec3& { return positions[loop[i % n]]; };
    auto mustKeep = [&](std::size_t i) { return !keep.empty() && keep[i % n]; };

    // Start from a vertex that stays whatever is dropped around it.
    std::size_t start = n;
    for (std::size_t i = 0; i < n && start == n; ++i)
    {
        if (mustKeep(i) || turnAt(at(i + n - 1), at(i), at(i + 1), normal, tolerance) != Turn::Straight)
            start = i;
    }
    if (start == n)
        start = 0;

    corners.push_back(start);
    std::size_t last = start;
    for (std::size_t step = 1; step < n; ++step)
    {
        const std::size_t i = start + step;
        if (mustKeep(i) || turnAt(at(last), at(i), at(i + 1), normal, tolerance) != Turn::Straight)
        {
            corners.push_back(i % n);
            last = i;
        }
    }
    return corners;
}

Vec3 loopNormal(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions)
{
    Vec3 sum(0.0);
    if (loop.size() < 3)
        return sum;
    const Vec3& origin = positions[loop.front()];
    for (std::size_t i = 1; i + 1 < loop.size(); ++i)
        sum += glm::cross(positions[loop[i]] - origin, positions[loop[i + 1]] - origin);
    return sum;
}

bool isConvexLoop(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions, const Vec3& normal,
                  double turnTolerance, double planeTolerance, std::uint32_t maxCorners)
{
    if (loop.size() < 3)
        return false;
    std::vector<std::uint32_t> sorted(loop);
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        return false;

    const std::vector<std::size_t> corners = cornerIndices(loop, positions, normal, turnTolerance);
    const std::size_t n = corners.size();
    if (n < 3 || n > maxCorners)
        return false;
    double winding = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& a = positions[loop[corners[i]]];
        const Vec3& b = positions[loop[corners[(i + 1) % n]]];
        const Vec3& c = positions[loop[corners[(i + 2) % n]]];
        if (turnAt(a, b, c, normal, turnTolerance) == Turn::Reflex)
            return false;
        const Vec3 in = b - a;
        const Vec3 out = c - b;
        winding += std::atan2(glm::dot(glm::cross(in, out), normal), glm::dot(in, out));
    }
    // A convex outline turns once; 4π and more means it wraps around twice (a star or a spiral).
    if (std::abs(winding - TwoPi) > 1e-3)
        return false;

    const Vec3 newell = loopNormal(loop, positions);
    const double length = glm::length(newell);
    if (!(length > 0.0) || !std::isfinite(length))
        return false;
    const Vec3 unit = newell / length;
    Aabb box;
    Vec3 mean(0.0);
    for (std::uint32_t v : loop)
    {
        box.expand(positions[v]);
        mean += positions[v];
    }
    mean /= double(loop.size());
    const double limit = planeTolerance * glm::length(box.extent()) +
                         std::max(storageSlack(box.min), storageSlack(box.max)) + storageSlack(mean);
    for (std::uint32_t v : loop)
    {
        if (std::abs(glm::dot(unit, positions[v] - mean)) > limit)
            return false;
    }
    return true;
}
} // namespace osgVis::core
