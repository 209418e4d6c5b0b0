// SPDX-License-Identifier: MIT
#pragma once
// Building blocks of the debug map's drawing: flat layers in the z = 0 plane of the map's
// orthographic camera, and the render bins that stack them (depth testing is off, so only the bin
// order keeps one layer above another).
#include <osgVis/core/geometry/Aabb.h>

#include <osg/Array>
#include <osg/Geometry>
#include <osg/Vec4>

namespace osgVis::viewer
{
enum MapBin : int
{
    BackgroundBin = 1,
    NodeFillBin, // a module's tree nodes, under the objects
    ObjectFillBin,
    ObjectOutlineBin,
    NodeOutlineBin, // node borders stay readable over the objects
    OccluderBin,
    EyeCellBin,
    FrustumBin,
    EyeBin,
    LabelBin
};

// One geometry of the map with its own vertex and colour arrays (one colour for all vertices unless
// `perVertexColour`), rewritten every frame while the map shows.
osg::ref_ptr<osg::Geometry> makeMapLayer(GLenum primitive, unsigned vertexCount, MapBin bin, const osg::Vec4& colour,
                                         bool perVertexColour);
// Makes a layer built by makeMapLayer draw `vertexCount` vertices (growing or shrinking its arrays).
void resizeMapLayer(osg::Geometry& layer, unsigned vertexCount);

inline void setPlanarVertex(osg::Vec3Array& vertices, unsigned i, double x, double y)
{
    vertices[i].set(float(x), float(y), 0.0f);
}

// The box's footprint (its x/y rectangle) as the four edges of a GL_LINES layer, vertices 8·i to 8·i + 7.
void setFootprintOutline(osg::Vec3Array& lines, unsigned i, const core::Aabb& box);
// The same rectangle also as the quad 4·i to 4·i + 3 of a GL_QUADS layer.
void setFootprint(osg::Vec3Array& quads, osg::Vec3Array& lines, unsigned i, const core::Aabb& box);
} // namespace osgVis::viewer
