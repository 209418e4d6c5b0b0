// SPDX-License-Identifier: MIT
#include <osgVis/oracle/RayCast.h>

#include "EffectiveState.h"
#include "TriangleBvh.h"

#include <osg/TriangleFunctor>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace osgVis::oracle
{
namespace
{
struct TriangleCollector
{
    std::vector<WorldTriangle>* triangles = nullptr;
    WorldTriangle prototype;
    osg::Matrixd world;

    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        WorldTriangle triangle = prototype;
        triangle.a = osg::Vec3d(a) * world;
        triangle.b = osg::Vec3d(b) * world;
        triangle.c = osg::Vec3d(c) * world;
        triangles->push_back(triangle);
    }
};

void collectTriangles(const OracleObject& object, std::uint32_t index, std::vector<WorldTriangle>& out)
{
    osg::TriangleFunctor<TriangleCollector> collector;
    collector.triangles = &out;
    collector.world = osg::computeLocalToWorld(object.path);
    collector.prototype.object = index;
    const FaceCulling culling = effectiveFaceCulling(object.path);
    collector.prototype.cullsCounterClockwise = culling.cullsCounterClockwise;
    collector.prototype.cullsClockwise = culling.cullsClockwise;
    object.drawable->accept(collector);
}

// The segment through NDC (x, y) from the near plane (z = -1) to the far plane (z = +1); works for
// perspective and orthographic projections alike.
Ray rayThrough(const osg::Matrixd& ndcToWorld, double x, double y)
{
    Ray ray;
    ray.origin = osg::Vec3d(x, y, -1.0) * ndcToWorld;
    ray.direction = osg::Vec3d(x, y, 1.0) * ndcToWorld - ray.origin;
    for (int axis = 0; axis < 3; ++axis)
        ray.inverseDirection[axis] = 1.0 / ray.direction[axis];
    return ray;
}
} // namespace

RayCaster::RayCaster(const std::vector<OracleObject>& objects)
    : _objectCount(objects.size())
{
    std::vector<WorldTriangle> opaque, transparent;
    for (std::uint32_t i = 0; i < objects.size(); ++i)
        if (objects[i].drawable)
            collectTriangles(objects[i], i, objects[i].transparent ? transparent : opaque);
    _opaque = std::make_unique<TriangleBvh>(std::move(opaque));
    _transparent = std::make_unique<TriangleBvh>(std::move(transparent));
}

RayCaster::~RayCaster() = default;

std::size_t RayCaster::triangleCount() const
{
    return _opaque->size() + _transparent->size();
}

std::vector<std::uint32_t> RayCaster::visible(const osg::Matrixd& view, const osg::Matrixd& projection,
                                              unsigned width, unsigned height, unsigned subgrid) const
{
    subgrid = std::max(subgrid, 1u);
    const osg::Matrixd ndcToWorld = osg::Matrixd::inverse(view * projection);
    const unsigned samplesX = width * subgrid, samplesY = height * subgrid;

    tbb::combinable<std::vector<std::uint8_t>> seenPerThread(
        [this] { return std::vector<std::uint8_t>(_objectCount, 0); });
    tbb::parallel_for(tbb::blocked_range<unsigned>(0, samplesY), [&](const tbb::blocked_range<unsigned>& rows) {
        std::vector<std::uint8_t>& seen = seenPerThread.local();
        for (unsigned sy = rows.begin(); sy != rows.end(); ++sy)
        {
            const double y = (sy + 0.5) / samplesY * 2.0 - 1.0;
            for (unsigned sx = 0; sx < samplesX; ++sx)
            {
                const double x = (sx + 0.5) / samplesX * 2.0 - 1.0;
                const Ray ray = rayThrough(ndcToWorld, x, y);
                double tOpaque = 1.0; // the far plane
                std::uint32_t object = 0;
                if (_opaque->nearest(ray, 1.0, tOpaque, object))
                    seen[object] = 1;
                _transparent->forEachHit(ray, tOpaque, [&](std::uint32_t hit) { seen[hit] = 1; });
            }
        }
    });

    std::vector<std::uint8_t> seen(_objectCount, 0);
    seenPerThread.combine_each([&](const std::vector<std::uint8_t>& local) {
        for (std::size_t i = 0; i < _objectCount; ++i)
            seen[i] |= local[i];
    });
    std::vector<std::uint32_t> visible;
    for (std::uint32_t i = 0; i < _objectCount; ++i)
        if (seen[i])
            visible.push_back(i);
    return visible;
}

std::vector<std::uint32_t> rayCastVisible(osg::Node* root, const std::vector<OracleObject>& objects,
                                          const osg::Matrixd& view, const osg::Matrixd& projection, unsigned width,
                                          unsigned height, unsigned subgrid)
{
    if (objects.empty() && root)
        return RayCaster(enumerateObjects(*root)).visible(view, projection, width, height, subgrid);
    return RayCaster(objects).visible(view, projection, width, height, subgrid);
}
} // namespace osgVis::oracle
