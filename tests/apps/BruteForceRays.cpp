// SPDX-License-Identifier: MIT
#include "BruteForceRays.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace osgVis::test
{
int firstHitIsBack(const core::Scene& scene, const core::Vec3& origin, const core::Vec3& direction)
{
    // Every hit distance and facing, then the facings within a hair of the nearest.
    std::vector<std::pair<double, bool>> hits;
    for (const core::Triangle& t : scene.triangles)
    {
        const core::Vec3 a(t.a), e1 = core::Vec3(t.b) - a, e2 = core::Vec3(t.c) - a;
        const core::Vec3 p = glm::cross(direction, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-12)
            continue;
        const core::Vec3 s = origin - a;
        const double u = glm::dot(s, p) / det;
        const core::Vec3 q = glm::cross(s, e1);
        const double v = glm::dot(direction, q) / det;
        const double d = glm::dot(e2, q) / det;
        if (u < 0 || v < 0 || u + v > 1 || d <= 0)
            continue;
        hits.emplace_back(d, glm::dot(glm::cross(e1, e2), direction) > 0);
    }
    if (hits.empty())
        return -1;
    const double nearest = std::min_element(hits.begin(), hits.end())->first;
    const double hair = 1e-5 * std::max(1.0, nearest);
    bool front = false;
    for (const auto& [d, back] : hits)
        front = front || (d <= nearest + hair && !back);
    return front ? 0 : 1;
}

bool insideByBruteForce(const core::Scene& scene, const core::Vec3& eye, std::mt19937& random)
{
    std::normal_distribution<double> gauss;
    int back = 0;
    for (int i = 0; i < 64; ++i)
    {
        const core::Vec3 direction = glm::normalize(core::Vec3(gauss(random), gauss(random), gauss(random)));
        back += firstHitIsBack(scene, eye, direction) == 1;
    }
    return back > 32;
}
} // namespace osgVis::test
