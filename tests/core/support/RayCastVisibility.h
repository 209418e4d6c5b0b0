// SPDX-License-Identifier: MIT
#pragma once
// Exact-visibility reference for core tests (no GL, shares no code with any culler): casts rays
// through a dense, deterministic jittered grid of samples over the viewport and reports every
// object that is the nearest hit of at least one ray.
//
// Rays run from the near plane to the far plane of the view's projection (unprojected through
// inverse(projection * view)), so what the near plane clips is never seen and perspective,
// off-centre and orthographic views are handled alike. Triangles are tested in double precision
// (Möller–Trumbore), both faces, except for objects with OBJECT_CULL_BACK / OBJECT_CULL_FRONT
// whose culled faces neither show nor hide anything; OBJECT_TRANSPARENT objects are seen but do
// not hide. A BVH over the triangles keeps a few-thousand-triangle scene at a few hundred
// thousand rays per view in a fraction of a second.
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/View.h>

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace osgVis::test
{
struct RayCastOptions
{
    std::uint32_t samplesPerAxis = 4; // per pixel: samplesPerAxis² jittered samples
    std::uint32_t seed = 1;           // jitter pattern (same seed, same samples)
    // Only pixels [x0, x1) × [y0, y1) (window pixels, origin bottom left, clamped to the viewport);
    // the default covers the whole viewport. For tests that only ask about one region.
    std::uint32_t x0 = 0, y0 = 0, x1 = ~0u, y1 = ~0u;
};

struct RayCastResult
{
    std::vector<bool> visible;         // per object id
    std::vector<glm::dvec2> seenAt;    // per visible object: the first sample (window pixels, origin bottom left)
    std::vector<double> seenAtDepth;   // per visible object: view depth (-z in eye space) of the nearest
                                       // opaque hit of that sample
    std::size_t count() const;
    std::vector<core::ObjectId> ids() const;
};

class RayCastVisibility
{
public:
    // Copies the triangles of every object not marked in `removed` (per object id; missing = present).
    explicit RayCastVisibility(const core::Scene& scene, const std::vector<bool>& removed = {});

    RayCastResult cast(const core::View& view, const RayCastOptions& options = {}) const;
    // Nearest object seen through window position (x, y) (pixels, origin bottom left), or
    // InvalidObject; `depth` receives its view depth.
    core::ObjectId objectAt(const core::View& view, double x, double y, double* depth = nullptr) const;

private:
    struct Tri
    {
        core::Vec3 a, e1, e2;
        core::ObjectId object;
        std::uint8_t cull;   // 0 none, 1 back faces, 2 front faces
        bool transparent;
    };
    struct Node
    {
        core::Vec3 lo, hi;
        std::uint32_t first = 0, count = 0; // leaf: triangles [first, first+count)
        std::uint32_t right = 0;            // inner: right child (left child is the next node)
    };
    struct Hit
    {
        double t;
        core::ObjectId object;
    };

    std::uint32_t build(std::uint32_t first, std::uint32_t count);
    // Nearest opaque hit in [0, 1] of origin + t·direction; transparent hits go to `seeThrough`.
    Hit trace(const core::Vec3& origin, const core::Vec3& direction, std::vector<Hit>& seeThrough) const;
    core::ObjectId sample(const core::Mat4& inverseViewProjection, const core::Mat4& viewMatrix, double ndcX,
                          double ndcY, std::vector<Hit>& seeThrough, std::vector<core::ObjectId>& seen,
                          double& depth) const;

    std::size_t _objectCount = 0;
    std::vector<Tri> _tris;
    std::vector<Node> _nodes;
};
} // namespace osgVis::test
