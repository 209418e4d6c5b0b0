// SPDX-License-Identifier: MIT
#include "RayScene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <stdexcept>

namespace osgVis::apps
{
namespace
{
// Hits near one distance, gathered by a filter that rejects every hit so traversal goes on.
struct GatherContext
{
    RTCIntersectContext context; // note: first member, so Embree's context pointer is ours
    const core::Scene* scene = nullptr;
    core::Vec3 direction;
    bool front = false, back = false;
};

void gatherFacings(const RTCFilterFunctionNArguments* args)
{
    auto* gather = reinterpret_cast<GatherContext*>(args->context);
    const core::Triangle& t = gather->scene->triangles[RTCHitN_primID(args->hit, args->N, 0)];
    const core::Vec3 normal = glm::cross(core::Vec3(t.b - t.a), core::Vec3(t.c - t.a));
    (glm::dot(normal, gather->direction) > 0.0 ? gather->back : gather->front) = true;
    args->valid[0] = 0;
}
} // namespace

struct RayScene::Embree
{
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Embree()
    {
        if (scene)
            rtcReleaseScene(scene);
        if (device)
            rtcReleaseDevice(device);
    }
};

RayScene::RayScene(const core::Scene& scene) : _scene(scene), _embree(std::make_unique<Embree>())
{
    if (scene.triangles.empty())
        throw std::runtime_error("ray casting needs the scene's triangles, and it has none");
    _embree->device = rtcNewDevice(nullptr);
    if (!_embree->device)
        throw std::runtime_error("Embree could not create a device");
    _embree->scene = rtcNewScene(_embree->device);
    RTCGeometry geometry = rtcNewGeometry(_embree->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t count = scene.triangles.size();
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    if (!vertices || !indices)
    {
        rtcReleaseGeometry(geometry);
        throw std::runtime_error("Embree could not allocate the triangle buffers");
    }
    _usable.assign(count, false);
    for (std::size_t i = 0; i < count; ++i)
    {
        const core::Triangle& t = scene.triangles[i];
        const core::Vec3f corners[3] = {t.a, t.b, t.c};
        bool sane = true;
        for (int k = 0; k < 3; ++k)
            for (int axis = 0; axis < 3; ++axis)
                sane = sane && std::isfinite(corners[k][axis]) && std::abs(corners[k][axis]) <= 1e12f;
        _usable[i] = sane;
        for (int k = 0; k < 3; ++k)
        {
            for (int axis = 0; axis < 3; ++axis)
                vertices[9 * i + 3 * k + axis] = sane ? corners[k][axis] : 0.0f; // a point: never hit
            if (sane)
                _bounds.expand(core::Vec3(corners[k]));
        }
        for (int k = 0; k < 3; ++k)
            indices[3 * i + k] = unsigned(3 * i + k);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(_embree->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcSetSceneFlags(_embree->scene, RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
    rtcCommitScene(_embree->scene);
}

RayScene::~RayScene() = default;

RayHit RayScene::nearest(const core::Vec3& origin, const core::Vec3& direction, double maxDistance) const
{
    const double length = glm::length(direction);
    RayHit result;
    if (!(length > 0.0))
        return result;
    const core::Vec3 unit = direction / length;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray.org_x = float(origin.x), query.ray.org_y = float(origin.y), query.ray.org_z = float(origin.z);
    query.ray.dir_x = float(unit.x), query.ray.dir_y = float(unit.y), query.ray.dir_z = float(unit.z);
    query.ray.tnear = 0.0f;
    query.ray.tfar = std::isfinite(maxDistance) ? float(maxDistance) : std::numeric_limits<float>::infinity();
    query.ray.mask = ~0u;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(_embree->scene, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return result;
    result.distance = query.ray.tfar;
    result.triangle = query.hit.primID;
    // Every triangle within a hair of the nearest distance, facing judged by our own counter-clockwise
    // normal (not Embree's Ng, whose sign follows its own convention).
    GatherContext gather;
    rtcInitIntersectContext(&gather.context);
    gather.context.filter = gatherFacings;
    gather.scene = &_scene;
    gather.direction = unit;
    const float hair = 1e-5f * std::max(1.0f, query.ray.tfar);
    RTCRayHit window = query;
    window.ray.tnear = std::max(0.0f, query.ray.tfar - hair);
    window.ray.tfar = query.ray.tfar + hair;
    window.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(_embree->scene, &gather.context, &window);
    const core::Triangle& t = _scene.triangles[result.triangle];
    const core::Vec3 normal = glm::cross(core::Vec3(t.b - t.a), core::Vec3(t.c - t.a));
    (glm::dot(normal, unit) > 0.0 ? gather.back : gather.front) = true; // the nearest one, whatever the window found
    result.backFace = gather.back && !gather.front;
    return result;
}

std::vector<core::Vec3> sphereDirections(unsigned count)
{
    // Spherical Fibonacci points: z evenly spaced, longitude advancing by the golden angle.
    std::vector<core::Vec3> directions;
    directions.reserve(count);
    const double goldenAngle = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (unsigned i = 0; i < count; ++i)
    {
        const double z = 1.0 - (2.0 * i + 1.0) / double(count);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        directions.emplace_back(r * std::cos(goldenAngle * i), r * std::sin(goldenAngle * i), z);
    }
    return directions;
}

double backFaceFraction(const RayScene& rays, const core::Vec3& eye, unsigned rayCount)
{
    unsigned back = 0;
    for (const core::Vec3& direction : sphereDirections(rayCount))
    {
        const RayHit hit = rays.nearest(eye, direction);
        back += hit.hit() && hit.backFace;
    }
    return rayCount ? double(back) / double(rayCount) : 0.0;
}

bool insideSolid(const RayScene& rays, const core::Vec3& eye, unsigned rayCount)
{
    return backFaceFraction(rays, eye, rayCount) > 0.5;
}
} // namespace osgVis::apps
