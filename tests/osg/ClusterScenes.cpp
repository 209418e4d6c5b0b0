// SPDX-License-Identifier: MIT
#include "ClusterScenes.h"

#include <osg/PrimitiveSet>
#include <osg/StateSet>

namespace osgVis::test
{
osg::ref_ptr<osg::Geometry> makePatchedMesh(const std::vector<Patch>& patches)
{
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    for (const Patch& p : patches)
    {
        const int n = p.cells;
        const auto at = [&](int i, int j) { return p.origin + p.u * (float(i) / n) + p.v * (float(j) / n); };
        const auto shade = [&](int i, int j)
        { return osg::Vec4(p.colour.r() * (0.5f + 0.5f * i / n), p.colour.g() * (0.5f + 0.5f * j / n), p.colour.b(), 1); };
        const auto add = [&](int i, int j)
        {
            vertices->push_back(at(i, j));
            colours->push_back(shade(i, j));
            return GLuint(vertices->size() - 1);
        };
        const GLuint base = GLuint(vertices->size());
        const auto grid = [&](int i, int j) { return base + GLuint(j * (n + 1) + i); };
        switch (p.kind)
        {
        case PatchKind::Triangles:
        case PatchKind::TrianglesShort:
        case PatchKind::Strips:
        case PatchKind::QuadStrips:
        {
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i)
                    add(i, j);
            if (p.kind == PatchKind::Triangles || p.kind == PatchKind::TrianglesShort)
            {
                osg::ref_ptr<osg::DrawElements> e;
                if (p.kind == PatchKind::Triangles)
                    e = new osg::DrawElementsUInt(GL_TRIANGLES);
                else
                    e = new osg::DrawElementsUShort(GL_TRIANGLES);
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i)
                        for (GLuint index : {grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j), grid(i + 1, j + 1),
                                             grid(i, j + 1)})
                            e->addElement(index);
                geometry->addPrimitiveSet(e.get());
            }
            else
            {
                for (int j = 0; j < n; ++j)
                {
                    osg::ref_ptr<osg::DrawElements> e;
                    if (p.kind == PatchKind::Strips)
                        e = new osg::DrawElementsUInt(GL_TRIANGLE_STRIP);
                    else
                        e = new osg::DrawElementsUShort(GL_QUAD_STRIP);
                    for (int i = 0; i <= n; ++i)
                    {
                        e->addElement(grid(i, j));
                        e->addElement(grid(i, j + 1));
                    }
                    geometry->addPrimitiveSet(e.get());
                }
            }
            break;
        }
        case PatchKind::Quads:
        case PatchKind::ArrayTriangles:
        case PatchKind::Fans:
        {
            osg::ref_ptr<osg::DrawArrayLengths> fans = new osg::DrawArrayLengths(GL_TRIANGLE_FAN, GLint(base));
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                {
                    if (p.kind == PatchKind::ArrayTriangles)
                        for (auto [a, b] : {std::pair{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}})
                            add(a, b);
                    else
                    {
                        add(i, j), add(i + 1, j), add(i + 1, j + 1), add(i, j + 1);
                        fans->push_back(4);
                    }
                }
            const GLsizei count = GLsizei(vertices->size() - base);
            if (p.kind == PatchKind::Fans)
                geometry->addPrimitiveSet(fans.get());
            else
                geometry->addPrimitiveSet(
                    new osg::DrawArrays(p.kind == PatchKind::Quads ? GL_QUADS : GL_TRIANGLES, GLint(base), count));
            break;
        }
        }
    }
    geometry->setVertexArray(vertices.get());
    geometry->setColorArray(colours.get(), osg::Array::BIND_PER_VERTEX);
    geometry->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    return geometry;
}
} // namespace osgVis::test
