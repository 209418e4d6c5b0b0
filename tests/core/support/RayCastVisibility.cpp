// SPDX-License-Identifier: MIT
#include "RayCastVisibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis::test
{
using core::Mat4;
using core::ObjectId;
using core::Vec3;
using core::Vec4;

namespace
{
// Barycentric slack: shared edges of a watertight mesh must not leak rays through float rounding.
constexpr double EdgeSlack = 1e-9;
constexpr std::uint32_t LeafTriangles = 4;

// Deterministic jitter in [0, 1) from a sample's integer coordinates.
double hashUnit(std::uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ULL;
    x ^= x >> 33;
    return double(x >> 11) * (1.0 / 9007199254740992.0);
}

bool slabHit(const Vec3& lo, const Vec3& hi, const Vec3& origin, const Vec3& inverseDirection, double tMax)
{
    double t0 = 0.0, t1 = tMax;
    for (int k = 0; k < 3; ++k)
    {
        double a = (lo[k] - origin[k]) * inverseDirection[k];
        double b = (hi[k] - origin[k]) * inverseDirection[k];
        if (std::isnan(a) || std::isnan(b)) // origin on the slab face, direction parallel to it
            continue;
        if (a > b)
            std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1)
            return false;
    }
    return true;
}

Vec3 unproject(const Mat4& inverseViewProjection, double x, double y, double z)
{
    const Vec4 p = inverseViewProjection * Vec4(x, y, z, 1.0);
    return Vec3(p) / p.w;
}
} // namespace

std::size_t RayCastResult::count() const
{
    return std::size_t(std::count(visible.begin(), visible.end(), true));
}

std::vector<ObjectId> RayCastResult::ids() const
{
    std::vector<ObjectId> out;
    for (std::size_t i = 0; i < visible.size(); ++i)
        if (visible[i])
            out.push_back(ObjectId(i));
    return out;
}

RayCastVisibility::RayCastVisibility(const core::Scene& scene, const std::vector<bool>& removed)
    : _objectCount(scene.objects.size())
{
    for (const core::SceneObject& object : scene.objects)
    {
        if (object.id < removed.size() && removed[object.id])
            continue;
        const std::uint8_t cull = (object.flags & core::OBJECT_CULL_BACK)    ? 1
                                  : (object.flags & core::OBJECT_CULL_FRONT) ? 2
                                                                             : 0;
        for (std::uint32_t k = 0; k < object.triangleCount; ++k)
        {
            const core::Triangle& t = scene.triangles[object.firstTriangle + k];
            const Vec3 a(t.a), b(t.b), c(t.c);
            _tris.push_back({a, b - a, c - a, object.id, cull, (object.flags & core::OBJECT_TRANSPARENT) != 0});
        }
    }
    if (!_tris.empty())
        build(0, std::uint32_t(_tris.size()));
}

std::uint32_t RayCastVisibility::build(std::uint32_t first, std::uint32_t count)
{
    const std::uint32_t index = std::uint32_t(_nodes.size());
    _nodes.emplace_back();
    Vec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    Vec3 centreLo = lo, centreHi = hi;
    for (std::uint32_t i = first; i < first + count; ++i)
    {
        const Tri& t = _tris[i];
        for (const Vec3& p : {t.a, t.a + t.e1, t.a + t.e2})
        {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const Vec3 centre = t.a + (t.e1 + t.e2) / 3.0;
        centreLo = glm::min(centreLo, centre);
        centreHi = glm::max(centreHi, centre);
    }
    _nodes[index].lo = lo;
    _nodes[index].hi = hi;
    const Vec3 spread = centreHi - centreLo;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
    if (count <= LeafTriangles || spread[axis] <= 0.0)
    {
        _nodes[index].first = first;
        _nodes[index].count = count;
        return index;
    }
    const std::uint32_t half = count / 2;
    std::nth_element(_tris.begin() + first, _tris.begin() + first + half, _tris.begin() + first + count,
                     [axis](const Tri& p, const Tri& q)
                     { return (p.a + (p.e1 + p.e2) / 3.0)[axis] < (q.a + (q.e1 + q.e2) / 3.0)[axis]; });
    build(first, half);
    const std::uint32_t right = build(first + half, count - half);
    _nodes[index].right = right;
    return index;
}

RayCastVisibility::Hit RayCastVisibility::trace(const Vec3& origin, const Vec3& direction,
                                                std::vector<Hit>& seeThrough) const
{
    Hit nearest{std::numeric_limits<double>::infinity(), core::InvalidObject};
    if (_nodes.empty())
        return nearest;
    const Vec3 inverseDirection = 1.0 / direction;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
        const Node& node = _nodes[stack[--top]];
        if (!slabHit(node.lo, node.hi, origin, inverseDirection, std::min(1.0, nearest.t)))
            continue;
        if (node.count == 0)
        {
            stack[top++] = node.right;
            stack[top++] = std::uint32_t(&node - _nodes.data()) + 1;
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        {
            const Tri& tri = _tris[i];
            const Vec3 p = glm::cross(direction, tri.e2);
            const double det = glm::dot(tri.e1, p);
            // det > 0: the ray meets the counter-clockwise (front) side.
            if (det == 0.0 || (tri.cull == 1 && det < 0.0) || (tri.cull == 2 && det > 0.0))
                continue;
            const double inverseDet = 1.0 / det;
            const Vec3 s = origin - tri.a;
            const double u = glm::dot(s, p) * inverseDet;
            if (u < -EdgeSlack || u > 1.0 + EdgeSlack)
                continue;
            const Vec3 q = glm::cross(s, tri.e1);
            const double v = glm::dot(direction, q) * inverseDet;
            if (v < -EdgeSlack || u + v > 1.0 + EdgeSlack)
                continue;
            const double t = glm::dot(tri.e2, q) * inverseDet;
            if (t < 0.0 || t > 1.0 || t >= nearest.t)
                continue;
            if (tri.transparent)
                seeThrough.push_back({t, tri.object});
            else
                nearest = {t, tri.object};
        }
    }
    return nearest;
}

ObjectId RayCastVisibility::sample(const Mat4& inverseViewProjection, const Mat4& viewMatrix, double ndcX,
                                   double ndcY, std::vector<Hit>& seeThrough, std::vector<ObjectId>& seen,
                                   double& depth) const
{
    const Vec3 nearPoint = unproject(inverseViewProjection, ndcX, ndcY, -1.0);
    const Vec3 farPoint = unproject(inverseViewProjection, ndcX, ndcY, 1.0);
    const Vec3 direction = farPoint - nearPoint;
    seeThrough.clear();
    seen.clear();
    const Hit hit = trace(nearPoint, direction, seeThrough);
    for (const Hit& h : seeThrough)
        if (h.t < hit.t)
            seen.push_back(h.object);
    depth = std::numeric_limits<double>::infinity();
    if (hit.object != core::InvalidObject)
    {
        seen.push_back(hit.object);
        depth = -(viewMatrix * Vec4(nearPoint + hit.t * direction, 1.0)).z;
    }
    return hit.object;
}

ObjectId RayCastVisibility::objectAt(const core::View& view, double x, double y, double* depth) const
{
    const Mat4 inverseViewProjection = glm::inverse(view.projectionMatrix * view.viewMatrix);
    std::vector<Hit> seeThrough;
    std::vector<ObjectId> seen;
    double d = 0.0;
    const ObjectId id = sample(inverseViewProjection, view.viewMatrix, 2.0 * x / view.viewportWidth - 1.0,
                               2.0 * y / view.viewportHeight - 1.0, seeThrough, seen, d);
    if (depth)
        *depth = d;
    return id;
}

RayCastResult RayCastVisibility::cast(const core::View& view, const RayCastOptions& options) const
{
    const Mat4 inverseViewProjection = glm::inverse(view.projectionMatrix * view.viewMatrix);
    const std::uint32_t width = view.viewportWidth, height = view.viewportHeight;
    const std::uint32_t n = std::max<std::uint32_t>(1, options.samplesPerAxis);

    // Per row: the objects first seen in it, with where; merged in row order so the answer does not
    // depend on scheduling.
    struct FirstSight
    {
        ObjectId object;
        glm::dvec2 at;
        double depth;
    };
    const std::uint32_t x0 = std::min(options.x0, width), x1 = std::min(options.x1, width);
    const std::uint32_t y0 = std::min(options.y0, height), y1 = std::min(options.y1, height);
    std::vector<std::vector<FirstSight>> rows(height);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(y0, std::max(y0, y1)),
                      [&](const tbb::blocked_range<std::uint32_t>& range)
                      {
                          std::vector<bool> known(_objectCount, false);
                          std::vector<Hit> seeThrough;
                          std::vector<ObjectId> seen;
                          for (std::uint32_t py = range.begin(); py != range.end(); ++py)
                          {
                              std::fill(known.begin(), known.end(), false);
                              for (std::uint32_t sy = 0; sy < n; ++sy)
                                  for (std::uint32_t px = x0; px < x1; ++px)
                                      for (std::uint32_t sx = 0; sx < n; ++sx)
                                      {
                                          const std::uint64_t key = ((std::uint64_t(py) * n + sy) << 32) ^
                                                                    (std::uint64_t(px) * n + sx) ^
                                                                    (std::uint64_t(options.seed) << 58);
                                          const double x = px + (sx + hashUnit(key * 2 + 1)) / n;
                                          const double y = py + (sy + hashUnit(key * 2 + 2)) / n;
                                          double depth = 0.0;
                                          sample(inverseViewProjection, view.viewMatrix, 2.0 * x / width - 1.0,
                                                 2.0 * y / height - 1.0, seeThrough, seen, depth);
                                          for (ObjectId id : seen)
                                              if (!known[id])
                                              {
                                                  known[id] = true;
                                                  rows[py].push_back({id, {x, y}, depth});
                                              }
                                      }
                          }
                      });

    RayCastResult result;
    result.visible.assign(_objectCount, false);
    result.seenAt.assign(_objectCount, glm::dvec2(0.0));
    result.seenAtDepth.assign(_objectCount, 0.0);
    for (const std::vector<FirstSight>& row : rows)
        for (const FirstSight& s : row)
            if (!result.visible[s.object])
            {
                result.visible[s.object] = true;
                result.seenAt[s.object] = s.at;
                result.seenAtDepth[s.object] = s.depth;
            }
    return result;
}
} // namespace osgVis::test
