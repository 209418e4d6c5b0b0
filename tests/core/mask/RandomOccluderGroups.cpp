// SPDX-License-Identifier: MIT
// Random occluder groups for the mask rasterizer tests (RandomOccluderGroups.h).
#include "RandomOccluderGroups.h"

#include <osgVis/core/geometry/ConvexHull2.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

using osgVis::core::DepthPlane;
using osgVis::core::ScreenPolygon;

namespace maskTest
{
namespace
{
struct Piece
{
    std::vector<glm::dvec2> vertices;
    std::vector<bool> shared;
};

// Cuts a piece along a chord between points on two of its edges; the chord is shared by both halves.
void cut(std::mt19937& random, std::vector<Piece>& pieces)
{
    Piece& piece = pieces[random() % pieces.size()];
    const std::size_t n = piece.vertices.size();
    const std::size_t i = random() % n, j = (i + 1 + random() % (n - 1)) % n; // two different edges
    std::uniform_real_distribution<double> along(0.1, 0.9);
    auto pointOn = [&](std::size_t e)
    { return glm::mix(piece.vertices[e], piece.vertices[(e + 1) % n], along(random)); };
    const glm::dvec2 p = pointOn(i), q = pointOn(j);
    // One half walks p → v[i+1] … v[j] → q → p, the other q → v[j+1] … v[i] → p → q.
    auto half = [&](glm::dvec2 start, std::size_t from, std::size_t to, glm::dvec2 end)
    {
        Piece result;
        result.vertices.push_back(start);
        result.shared.push_back(piece.shared[from]);
        for (std::size_t k = (from + 1) % n;; k = (k + 1) % n)
        {
            result.vertices.push_back(piece.vertices[k]);
            result.shared.push_back(k == to ? piece.shared[to] : piece.shared[k]);
            if (k == to)
                break;
        }
        result.vertices.push_back(end);
        result.shared.push_back(true); // the chord
        return result;
    };
    Piece a = half(p, i, j, q), b = half(q, j, i, p);
    piece = std::move(a);
    pieces.push_back(std::move(b));
}

} // namespace

// Convex hull (counter-clockwise, no collinear points) of random points.
std::vector<glm::dvec2> randomConvexPolygon(std::mt19937& random, double size)
{
    std::uniform_real_distribution<double> centre(-10.0, size + 10.0), unit(0.0, 1.0);
    const glm::dvec2 middle{centre(random), centre(random)};
    const double radius = 3.0 + unit(random) * size * 0.6;
    std::vector<glm::dvec2> points(3 + random() % 10);
    for (glm::dvec2& p : points)
    {
        const double angle = unit(random) * 2.0 * M_PI, r = radius * std::sqrt(unit(random));
        p = middle + glm::dvec2{r * std::cos(angle), r * std::sin(angle) * (0.3 + unit(random))};
    }
    std::vector<glm::dvec2> scratch;
    osgVis::core::convexHullInPlace(points, scratch,
                                    [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
                                    { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); });
    return points;
}

DepthPlane randomPlane(std::mt19937& random, glm::dvec2 around)
{
    std::uniform_real_distribution<double> slope(-0.01, 0.01), level(0.02, 0.5);
    DepthPlane plane;
    plane.inverse = random() % 4 != 0;
    plane.a = slope(random);
    plane.b = slope(random);
    plane.c = level(random) - plane.a * around.x - plane.b * around.y;
    if (!plane.inverse)
    {
        plane.a *= 100.0;
        plane.b *= 100.0;
        plane.c = 50.0 + plane.c * 100.0;
    }
    return plane;
}

std::vector<ScreenPolygon> randomCutGroup(std::mt19937& random, const std::vector<glm::dvec2>& hull, int cuts,
                                          const DepthPlane& plane)
{
    std::vector<Piece> pieces = {{hull, std::vector<bool>(hull.size(), false)}};
    for (int c = 0; c < cuts; ++c)
        cut(random, pieces);
    std::vector<ScreenPolygon> group;
    for (Piece& piece : pieces)
    {
        if (random() % 2 == 0) // clockwise: edge k of the reversed polygon is edge n-2-k
        {
            const std::size_t n = piece.vertices.size();
            std::reverse(piece.vertices.begin(), piece.vertices.end());
            std::vector<bool> shared(n);
            for (std::size_t k = 0; k < n; ++k)
                shared[k] = piece.shared[(2 * n - 2 - k) % n];
            piece.shared = shared;
        }
        ScreenPolygon polygon;
        polygon.vertices = piece.vertices;
        polygon.sharedEdge = piece.shared;
        polygon.depth = plane;
        group.push_back(std::move(polygon));
    }
    return group;
}
} // namespace maskTest
