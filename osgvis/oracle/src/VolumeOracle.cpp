// SPDX-License-Identifier: MIT
#include <osgVis/oracle/VolumeOracle.h>

#include <osgVis/oracle/CubeFaceViews.h>
#include <osgVis/oracle/IdBufferOracle.h>
#include <osgVis/oracle/TriangleIdOracle.h>
#include <osgVis/oracle/VolumeEyes.h>

#include <algorithm>
#include <stdexcept>

namespace osgVis::oracle
{
namespace
{
std::vector<std::uint32_t> setEntries(const std::vector<std::uint8_t>& flags)
{
    std::vector<std::uint32_t> indices;
    for (std::uint32_t i = 0; i < flags.size(); ++i)
        if (flags[i])
            indices.push_back(i);
    return indices;
}

double longestEdge(const osg::BoundingBoxd& box)
{
    return std::max({box.xMax() - box.xMin(), box.yMax() - box.yMin(), box.zMax() - box.zMin()});
}
} // namespace

VolumeOracle::VolumeOracle(osg::Node* root, const VolumeOracleSettings& settings) : _settings(settings)
{
    if (!root)
        throw std::invalid_argument("osgVis volume oracle: null root");
    if (settings.faceSize == 0)
        throw std::invalid_argument("osgVis volume oracle: empty face size");
    _sceneBound = root->getBound();
    OracleSettings faces;
    faces.width = faces.height = settings.faceSize;
    faces.supersample = settings.supersample;
    _objects = std::make_unique<IdBufferOracle>(root, faces);
    if (settings.triangles)
        _triangles = std::make_unique<TriangleIdOracle>(_objects->objects(), settings.faceSize, settings.faceSize);
}

VolumeOracle::~VolumeOracle() = default;

const std::vector<OracleObject>& VolumeOracle::objects() const
{
    return _objects->objects();
}

std::size_t VolumeOracle::triangleCount() const
{
    return _triangles ? _triangles->triangleCount() : 0;
}

std::uint32_t VolumeOracle::firstTriangle(std::uint32_t object) const
{
    return _triangles ? _triangles->firstTriangle(object) : 0;
}

VolumeVisibility VolumeOracle::visibleFrom(const osg::BoundingBoxd& box)
{
    VolumeVisibility result;
    const std::vector<osg::Vec3d> eyes = volumeEyes(box, _settings.interiorEyes, _settings.seed);

    const double diameter = _sceneBound.valid() ? 2.0 * _sceneBound.radius() : 0.0;
    result.zNear = _settings.zNear;
    if (result.zNear <= 0.0)
    {
        result.zNear = diameter > 0.0 ? 1e-3 * diameter : 1e-3;
        if (longestEdge(box) > 0.0)
            result.zNear = std::min(result.zNear, 0.25 * longestEdge(box));
    }
    result.zFar = _settings.zFar;
    if (result.zFar <= 0.0)
    {
        // The farthest scene point from any eye: box centre to sphere centre, plus both radii.
        const double reach = _sceneBound.valid()
                                 ? (box.center() - osg::Vec3d(_sceneBound.center())).length() + _sceneBound.radius()
                                 : 0.0;
        result.zFar = 1.01 * (reach + 0.5 * (box._max - box._min).length()) + 2.0 * result.zNear;
    }
    const osg::Matrixd projection = cubeFaceProjection(result.zNear, result.zFar);

    std::vector<std::uint8_t> objectsSeen(objects().size(), 0), trianglesSeen(triangleCount(), 0);
    std::vector<std::uint8_t> eyeObjects(objects().size()), eyeTriangles;
    for (const osg::Vec3d& eye : eyes)
    {
        VolumeVisibility::Eye seen;
        seen.position = eye;
        std::fill(eyeObjects.begin(), eyeObjects.end(), 0);
        if (_settings.perEyeTriangles)
            eyeTriangles.assign(triangleCount(), 0);
        for (const osg::Matrixd& view : cubeFaceViews(eye))
        {
            for (std::uint32_t object : _objects->visible(view, projection).visible)
                eyeObjects[object] = objectsSeen[object] = 1;
            if (_triangles)
                _triangles->markVisible(view, projection, _settings.perEyeTriangles ? eyeTriangles : trianglesSeen);
        }
        seen.objects = setEntries(eyeObjects);
        if (_settings.perEyeTriangles)
        {
            seen.triangles = setEntries(eyeTriangles);
            for (std::uint32_t t : seen.triangles)
                trianglesSeen[t] = 1;
        }
        result.eyes.push_back(std::move(seen));
    }
    result.objects = setEntries(objectsSeen);
    result.triangles = setEntries(trianglesSeen);
    return result;
}
} // namespace osgVis::oracle
