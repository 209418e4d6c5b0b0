#pragma once
// Small hand-built geometry for the adapter tests.
#include <osg/Geometry>
#include <osg/Vec3>
#include <osg/Vec4>

namespace osgVis::test
{
// Axis-aligned box as 12 indexed triangles, one flat colour, lighting off.
osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& min, const osg::Vec3& max,
                                    const osg::Vec4& colour = osg::Vec4(1, 1, 1, 1));
} // namespace osgVis::test
