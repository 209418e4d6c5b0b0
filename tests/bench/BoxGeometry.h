// SPDX-License-Identifier: MIT
#pragma once
// The 12-triangle box the adapter micro-benchmarks build their graphs from.
#include <osg/Geometry>

namespace osgVis::bench
{
inline osg::ref_ptr<osg::Geometry> boxGeometry(const osg::Vec3& lo, const osg::Vec3& hi)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (int i = 0; i < 8; ++i)
        v->push_back(osg::Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
    const GLushort faces[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                              2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setVertexArray(v);
    geometry->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 36, faces));
    return geometry;
}
} // namespace osgVis::bench
