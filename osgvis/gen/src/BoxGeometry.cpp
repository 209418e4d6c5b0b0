// SPDX-License-Identifier: MIT
#include <osgVis/gen/BoxGeometry.h>

namespace osgVis::gen
{
osg::ref_ptr<osg::Geometry> boxGeometry(const osg::Vec3& lo, const osg::Vec3& hi, const osg::Vec4& colour,
                                        const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (int i = 0; i < 8; ++i)
        corners->push_back(osg::Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
    // Corner i has bit 0 = x, bit 1 = y, bit 2 = z at the maximum.
    static const GLushort faces[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                     2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(name);
    geometry->setVertexArray(corners);
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    colours->push_back(colour);
    geometry->setColorArray(colours, osg::Array::BIND_OVERALL);
    geometry->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 36, faces));
    return geometry;
}
} // namespace osgVis::gen
