// SPDX-License-Identifier: MIT
#include "MapGeometry.h"

#include <algorithm>

namespace osgVis::viewer
{
osg::ref_ptr<osg::Geometry> makeMapLayer(GLenum primitive, unsigned vertexCount, MapBin bin, const osg::Vec4& colour,
                                         bool perVertexColour)
{
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setDataVariance(osg::Object::DYNAMIC);
    geometry->setUseDisplayList(false);
    geometry->setUseVertexBufferObjects(true);
    geometry->setVertexArray(new osg::Vec3Array(vertexCount));
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array(perVertexColour ? vertexCount : 1);
    std::fill(colours->begin(), colours->end(), colour);
    geometry->setColorArray(colours.get(), perVertexColour ? osg::Array::BIND_PER_VERTEX : osg::Array::BIND_OVERALL);
    geometry->addPrimitiveSet(new osg::DrawArrays(primitive, 0, vertexCount));
    geometry->getOrCreateStateSet()->setRenderBinDetails(bin, "RenderBin");
    return geometry;
}

void resizeMapLayer(osg::Geometry& layer, unsigned vertexCount)
{
    auto& vertices = static_cast<osg::Vec3Array&>(*layer.getVertexArray());
    vertices.resize(vertexCount);
    vertices.dirty();
    auto& colours = static_cast<osg::Vec4Array&>(*layer.getColorArray());
    if (layer.getColorArray()->getBinding() == osg::Array::BIND_PER_VERTEX)
    {
        colours.resize(vertexCount);
        colours.dirty();
    }
    static_cast<osg::DrawArrays*>(layer.getPrimitiveSet(0))->setCount(int(vertexCount));
    layer.getPrimitiveSet(0)->dirty();
    layer.dirtyBound();
}

void setFootprintOutline(osg::Vec3Array& lines, unsigned i, const core::Aabb& box)
{
    const double xs[4] = {box.min.x, box.max.x, box.max.x, box.min.x};
    const double ys[4] = {box.min.y, box.min.y, box.max.y, box.max.y};
    for (unsigned corner = 0; corner < 4; ++corner)
    {
        setPlanarVertex(lines, 8 * i + 2 * corner, xs[corner], ys[corner]);
        setPlanarVertex(lines, 8 * i + 2 * corner + 1, xs[(corner + 1) % 4], ys[(corner + 1) % 4]);
    }
}

void setFootprint(osg::Vec3Array& quads, osg::Vec3Array& lines, unsigned i, const core::Aabb& box)
{
    setFootprintOutline(lines, i, box);
    for (unsigned corner = 0; corner < 4; ++corner)
        quads[4 * i + corner] = lines[8 * i + 2 * corner];
}
} // namespace osgVis::viewer
