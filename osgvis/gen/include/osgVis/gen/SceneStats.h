// SPDX-License-Identifier: MIT
#pragma once
// What a scene graph draws, counted the way the culling metrics count it: one object per drawable
// instance (a drawable reached through two paths counts twice), and the triangles of each instance.
#include <osg/Node>

#include <cstddef>
#include <cstdint>

namespace osgVis::gen
{
struct SceneStats
{
    std::size_t objects = 0;
    std::uint64_t triangles = 0;
};

// Every child is counted, whatever its node mask.
SceneStats sceneStats(osg::Node& root);
} // namespace osgVis::gen
