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
    bool backFace = false; // the ray met the triangle's back (it runs along the counter-clockwise normal)
    bool hit() const { return distance < std::numeric_limits<double>::infinity(); }
};

class RayScene
{
public:
    // Every triangle of `scene` (kept by the extraction); degenerate ones never hit.
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

private:
    struct Embree;
    const core::Scene& _scene;
    std::unique_ptr<Embree> _embree;
};

// The definition of "inside solid geometry" the automatic walk and its tests use: of `rays` directions
// spread evenly over the sphere (a spherical Fibonacci set), more than half first meet a back face.
// Rays that meet nothing count as outside.
bool insideSolid(const RayScene& rays, const core::Vec3& eye, unsigned rayCount = 64);
// The directions that test uses, unit length.
std::vector<core::Vec3> sphereDirections(unsigned count);
} // namespace osgVis::apps
