// SPDX-License-Identifier: MIT
#pragma once

#include <osgVis/oracle/OracleObject.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::oracle
{
class TriangleBvh;

// Dense CPU ray casting, independent of GL: a second judge for the ID-buffer oracle on small scenes.
// One ray per sample through the near and far planes of the given projection (perspective or
// orthographic), nearest opaque hit by Möller–Trumbore over a BVH. Transparent objects hide nothing:
// every transparent object hit in front of the nearest opaque hit is visible. Honours the objects'
// effective cull face / front face; ignores everything else in their state (polygon mode, lines,
// points: triangles only, as osg::TriangleFunctor gives them).
class RayCaster
{
public:
    explicit RayCaster(const std::vector<OracleObject>& objects); // builds world triangles + BVH once
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    // Indices into objects, ascending. Samples the centres of a subgrid×subgrid grid inside every
    // pixel of a width×height image (subgrid 1: pixel centres, as GL rasterises).
    std::vector<std::uint32_t> visible(const osg::Matrixd& view, const osg::Matrixd& projection, unsigned width,
                                       unsigned height, unsigned subgrid = 1) const;

    std::size_t triangleCount() const;

private:
    std::size_t _objectCount;
    std::unique_ptr<TriangleBvh> _opaque;
    std::unique_ptr<TriangleBvh> _transparent;
};

// One-shot form: one ray per pixel centre of a width×height grid (subgrid×subgrid per pixel).
// objects: as from enumerateObjects(*root) or IdBufferOracle::objects(); when empty, enumerated from root.
std::vector<std::uint32_t> rayCastVisible(osg::Node* root, const std::vector<OracleObject>& objects,
                                          const osg::Matrixd& view, const osg::Matrixd& projection, unsigned width,
                                          unsigned height, unsigned subgrid = 1);
} // namespace osgVis::oracle
