// SPDX-License-Identifier: MIT
#pragma once
// Nearest-hit ray casting over a scene's triangles (Embree 3), for the apps' automatic walk: where
// one can stand, how much room is above and around an eye, and whether an eye is inside solid
// geometry. Not the oracle: the exact-visibility oracle renders the real graph and has its own
// ray caster, sharing nothing with this.
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <limits>
#include <memory>

namespace osgVis::apps
{
struct RayHit
{
    double distance = std::numeric_limits<double>::infinity(); // infinity: nothing hit
    std::uint32_t triangle = 0;                                 // index into Scene::triangles
    // The ray met the surface from behind: every triangle at the nearest distance is seen from its back
    // (the ray runs along its counter-clockwise normal). A surface covered by triangles facing both
    // ways there (two-sided, or doubled as real files often have it) is met from the front.
    bool backFace = false;
    bool hit() const { return distance < std::numeric_limits<double>::infinity(); }
};

class RayScene
{
public:
    // Every triangle of `scene` (kept by the extraction); degenerate ones never hit, and neither do
    // triangles with a coordinate that is not finite or beyond ±1e12 (junk vertices real files have).
    // Throws std::runtime_error when the scene holds no triangles or Embree fails.
    explicit RayScene(const core::Scene& scene);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // The nearest triangle along origin + t·direction (direction need not be unit), 0 < t < maxDistance
    // in units of |direction|·t, i.e. world distance. Thread-safe.
    RayHit nearest(const core::Vec3& origin, const core::Vec3& direction,
                   double maxDistance = std::numeric_limits<double>::infinity()) const;

    const core::Scene& scene() const { return _scene; }
    // Bounds of the triangles that can be hit.
    const core::Aabb& bounds() const { return _bounds; }
    // Whether triangle i can be hit (its coordinates are sane).
    bool usable(std::uint32_t triangle) const { return _usable[triangle]; }

private:
    struct Embree;
    const core::Scene& _scene;
    core::Aabb _bounds;
    std::vector<bool> _usable;
    std::unique_ptr<Embree> _embree;
};

// The definition of "inside solid geometry" the automatic walk and its tests use: of `rays` directions
// spread evenly over the sphere (a spherical Fibonacci set), more than half first meet a back face
// (RayHit::backFace: only back faces at the nearest hit).
// Rays that meet nothing count as outside.
bool insideSolid(const RayScene& rays, const core::Vec3& eye, unsigned rayCount = 64);
// The fraction of those rays that first meet a back face.
double backFaceFraction(const RayScene& rays, const core::Vec3& eye, unsigned rayCount = 64);
// The directions that test uses, unit length.
std::vector<core::Vec3> sphereDirections(unsigned count);
} // namespace osgVis::apps
