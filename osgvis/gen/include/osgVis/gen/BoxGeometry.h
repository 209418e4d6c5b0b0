// SPDX-License-Identifier: MIT
#pragma once
// A closed axis-aligned box as one drawable: what the dynamic bench walk and the viewer's building
// tool drop into a scene (cars, new buildings) during a walk.
#include <osg/Geometry>

#include <string>

namespace osgVis::gen
{
// 12 triangles, counter-clockwise seen from outside, one colour, named `name`.
osg::ref_ptr<osg::Geometry> boxGeometry(const osg::Vec3& lo, const osg::Vec3& hi, const osg::Vec4& colour,
                                        const std::string& name);
} // namespace osgVis::gen
