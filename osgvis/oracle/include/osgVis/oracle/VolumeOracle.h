// SPDX-License-Identifier: MIT
#pragma once

#include <osgVis/oracle/OracleObject.h>

#include <osg/BoundingBox>
#include <osg/Node>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::oracle
{
class IdBufferOracle;
class TriangleIdOracle;

struct VolumeOracleSettings
{
    unsigned faceSize = 512;    // pixels along each side of a cube-face image, >= 1
    unsigned supersample = 1;   // objects only: IdBufferOracle's second render at this factor; <= 1: none
    unsigned interiorEyes = 48; // random eyes inside the box, besides its 8 corners and 6 face centres
    std::uint32_t seed = 1;     // of the interior eyes
    // Clip planes in metres (scene units). zNear 0: the smaller of 1e-3 × the scene's bounding diameter
    // and 1/4 of the box's longest edge. Geometry nearer an eye than zNear is clipped away, so the
    // eyes see through it: keep zNear below the distance from the box to the nearest geometry.
    // zFar 0: beyond every point of the scene from every eye in the box.
    double zNear = 0.0, zFar = 0.0;
    bool triangles = true;        // also the triangles seen (TriangleIdOracle), at about twice the cost
    bool perEyeTriangles = false; // keep each eye's triangles, not only their union
};

// What a box of eyes sees: every list ascending, object indices into VolumeOracle::objects() (the
// adapter's object ids), triangle indices in core::Scene::triangles order (see TriangleIdOracle).
struct VolumeVisibility
{
    struct Eye
    {
        osg::Vec3d position;
        std::vector<std::uint32_t> objects;
        std::vector<std::uint32_t> triangles; // with VolumeOracleSettings::perEyeTriangles only
    };
    std::vector<std::uint32_t> objects;   // seen by at least one eye
    std::vector<std::uint32_t> triangles; // seen by at least one eye; empty without settings.triangles
    std::vector<Eye> eyes;                // the sampled eyes in volumeEyes order
    double zNear = 0.0, zFar = 0.0;       // the clip planes used
};

// Sampled visibility from a volume of viewpoints (the reference for a conservative from-region PVS,
// such as the multifocal z-buffer's): the union of what each eye of volumeEyes(box) sees in its six
// 90° cube-face views, rendered by IdBufferOracle (objects) and TriangleIdOracle (triangles) at
// faceSize². It is a lower bound on what the volume sees: an object visible only from points
// between the samples, or through gaps narrower than a pixel, can be missing; whatever it reports is
// truly visible from a sampled eye at that resolution, and a conservative PVS must contain it.
// Needs a display (Xvfb). Not thread-safe.
class VolumeOracle
{
public:
    VolumeOracle(osg::Node* root, const VolumeOracleSettings& settings = {}); // throws std::runtime_error
    ~VolumeOracle();
    VolumeOracle(const VolumeOracle&) = delete;
    VolumeOracle& operator=(const VolumeOracle&) = delete;

    const std::vector<OracleObject>& objects() const;
    std::size_t triangleCount() const; // 0 without settings.triangles
    // Object i owns triangles [firstTriangle(i), firstTriangle(i + 1)); 0 without settings.triangles.
    std::uint32_t firstTriangle(std::uint32_t object) const;
    const VolumeOracleSettings& settings() const { return _settings; }

    // Throws std::invalid_argument for an invalid box.
    VolumeVisibility visibleFrom(const osg::BoundingBoxd& box);

private:
    VolumeOracleSettings _settings;
    osg::BoundingSphere _sceneBound;
    std::unique_ptr<IdBufferOracle> _objects;
    std::unique_ptr<TriangleIdOracle> _triangles;
};
} // namespace osgVis::oracle
