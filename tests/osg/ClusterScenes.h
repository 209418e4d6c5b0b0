// SPDX-License-Identifier: MIT
#pragma once
// One large drawable made of tessellated rectangles ("patches"), each drawn by a primitive set of
// its own kind, for the cluster tests: every primitive type OSG draws in one Geometry.
#include <osg/Geometry>
#include <osg/Vec3>
#include <osg/Vec4>

#include <vector>

namespace osgVis::test
{
enum class PatchKind
{
    Triangles,      // DrawElementsUInt GL_TRIANGLES
    TrianglesShort, // DrawElementsUShort GL_TRIANGLES (the patch's own index range must fit)
    Strips,         // DrawElementsUInt GL_TRIANGLE_STRIP per row
    Quads,          // DrawArrays GL_QUADS (vertices repeated per cell)
    Fans,           // DrawArrayLengths GL_TRIANGLE_FAN, one fan per cell
    QuadStrips,     // DrawElementsUShort GL_QUAD_STRIP per row
    ArrayTriangles, // DrawArrays GL_TRIANGLES
};

struct Patch
{
    osg::Vec3 origin, u, v; // the rectangle origin + [0,1]·u + [0,1]·v
    int cells = 8;           // cells × cells quads, two triangles each
    osg::Vec4 colour{1, 1, 1, 1};
    PatchKind kind = PatchKind::Triangles;
};

// Vertex colours shade across each patch (so a misplaced triangle shows); lighting off.
osg::ref_ptr<osg::Geometry> makePatchedMesh(const std::vector<Patch>& patches);

// Triangles a patch adds (2 per cell whatever the kind).
inline unsigned patchTriangles(const Patch& p)
{
    return 2u * unsigned(p.cells * p.cells);
}
} // namespace osgVis::test
