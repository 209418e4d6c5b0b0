// SPDX-License-Identifier: MIT
// Sliver triangles: distinct corners on one line up to float storage, whose pixels the rasterizer
// may give any depth (docs/occluders.md, "Sliver triangles"). Both front doors flag their objects
// by it: the OSG adapter's extraction and the C interface's osgvis_scene_add_object / _move_object.
#include <osgVis/core/scene/Scene.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::core
{
bool isSliverTriangle(const Triangle& triangle)
{
    if (triangle.a == triangle.b || triangle.b == triangle.c || triangle.c == triangle.a)
        return false; // snaps to zero area: draws nothing
    const Vec3 a(triangle.a), b(triangle.b), c(triangle.c);
    const Vec3 ab = b - a, ac = c - a, bc = c - b;
    const double longest = std::sqrt(std::max({glm::dot(ab, ab), glm::dot(ac, ac), glm::dot(bc, bc)}));
    double largest = 0.0;
    for (const Vec3& v : {a, b, c})
        largest = std::max({largest, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    const double height = glm::length(glm::cross(ab, ac)) / longest;
    // note: 1e-6 of the edge leaves thin triangles modelled on purpose alone (their depth plane is
    // well conditioned); eight float epsilons of the coordinates catch corners meant to be collinear,
    // each rounded to float
    return std::isfinite(longest) &&
           height < 1e-6 * longest + 8.0 * double(std::numeric_limits<float>::epsilon()) * largest;
}

bool hasSliverTriangle(const Triangle* triangles, std::size_t count)
{
    return count > 0 && std::any_of(triangles, triangles + count, isSliverTriangle);
}
} // namespace osgVis::core
