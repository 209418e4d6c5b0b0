// SPDX-License-Identifier: MIT
// placeDrawable: a drawable's bounds from the vertices its primitives use, its triangles in the root
// frame, and whether it holds a sliver (docs/occluders.md).
#include "DrawableGeometry.h"
#include "Extraction.h"

#include <osg/Geometry>
#include <osg/PrimitiveSet>
#include <osg/TriangleFunctor>

#include <utility>

namespace osgVis
{
namespace
{
// The vertices a geometry's primitive sets draw. Real files often share one vertex array between
// many drawables (OSG's bsp plugin gives every face of a Quake 3 level the whole level's vertices):
// the bounds of what a drawable draws are those of the vertices its primitives use, not of its array.
class ReferencedVertices : public osg::PrimitiveIndexFunctor
{
public:
    std::vector<bool> used;
    bool any = false;

    void setVertexArray(unsigned int count, const osg::Vec2*) override { used.assign(count, false); }
    void setVertexArray(unsigned int count, const osg::Vec3*) override { used.assign(count, false); }
    void setVertexArray(unsigned int count, const osg::Vec4*) override { used.assign(count, false); }
    void setVertexArray(unsigned int count, const osg::Vec2d*) override { used.assign(count, false); }
    void setVertexArray(unsigned int count, const osg::Vec3d*) override { used.assign(count, false); }
    void setVertexArray(unsigned int count, const osg::Vec4d*) override { used.assign(count, false); }
    void drawArrays(GLenum, GLint first, GLsizei count) override
    {
        for (GLsizei i = 0; i < count; ++i)
            mark(unsigned(first + i));
    }
    void drawElements(GLenum, GLsizei count, const GLubyte* indices) override { markAll(count, indices); }
    void drawElements(GLenum, GLsizei count, const GLushort* indices) override { markAll(count, indices); }
    void drawElements(GLenum, GLsizei count, const GLuint* indices) override { markAll(count, indices); }

private:
    // note: an index past the array draws nothing we can bound (OSG would read out of range); the
    // caller falls back to the whole array when no index was usable.
    void mark(unsigned index)
    {
        if (index < used.size())
            used[index] = true, any = true;
    }
    template <class Index> void markAll(GLsizei count, const Index* indices)
    {
        for (GLsizei i = 0; i < count; ++i)
            mark(unsigned(indices[i]));
    }
};

// Feeds the vertices of a vertex array to a BoundsAccumulator (all of them, or those `used` marks);
// `handled` stays false for array types that hold no positions we understand.
struct VertexBoundsVisitor : public osg::ConstArrayVisitor
{
    VertexBoundsVisitor(BoundsAccumulator& out, const std::vector<bool>* used) : _out(out), _used(used) {}

    // note: float and double arrays share the position rules (add below), widened to double.
    void apply(const osg::Vec2Array& a) override { each(a); }
    void apply(const osg::Vec3Array& a) override { each(a); }
    void apply(const osg::Vec4Array& a) override { each(a); }
    void apply(const osg::Vec2dArray& a) override { each(a); }
    void apply(const osg::Vec3dArray& a) override { each(a); }
    void apply(const osg::Vec4dArray& a) override { each(a); }

    bool handled = false;

private:
    template <class ArrayT> void each(const ArrayT& array)
    {
        handled = true;
        for (std::size_t i = 0; i < array.size(); ++i)
            if (!_used || (i < _used->size() && (*_used)[i]))
                add(array[i]);
    }
    void add(const osg::Vec2d& v) { _out.add({v.x(), v.y(), 0.0}); }
    void add(const osg::Vec3d& v) { _out.add(v); }
    void add(const osg::Vec4d& v) { _out.addHomogeneous(v); }

    BoundsAccumulator& _out;
    const std::vector<bool>* _used;
};
// Finds a sliver: a triangle with three distinct corners that lie on one line up to float storage
// (its height below 10⁻⁶ of its longest edge plus eight float epsilons of its largest coordinate).
// Exactly degenerate ones (a repeated corner) stay degenerate once snapped and draw nothing; a
// sliver may snap to a sub-pixel triangle whose depth plane is ill-conditioned (docs/occluders.md).
struct SliverFinder
{
    bool found = false;

    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        found = found || core::isSliverTriangle({{a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}, {c.x(), c.y(), c.z()}});
    }
};

} // namespace

bool hasSlivers(osg::Drawable& drawable)
{
    osg::TriangleFunctor<SliverFinder> finder;
    drawable.accept(finder);
    return static_cast<const SliverFinder&>(finder).found;
}

DrawablePlacement placeDrawable(osg::Drawable& drawable, const osg::Matrixd& world, bool clockwiseFront,
                                std::vector<core::Triangle>* triangles)
{
    DrawablePlacement out;
    BoundsAccumulator bounds(world);
    const osg::Geometry* geometry = drawable.asGeometry();
    bool fromVertices = false;
    if (geometry && geometry->getVertexArray())
    {
        ReferencedVertices referenced;
        geometry->accept(referenced);
        VertexBoundsVisitor visitor(bounds, referenced.any ? &referenced.used : nullptr);
        geometry->getVertexArray()->accept(visitor);
        fromVertices = visitor.handled;
    }
    // note: an explicit bound or bound callback may be larger than the vertices (shader
    // displacement); the union keeps the object conservative.
    if (!fromVertices || drawable.getInitialBound().valid() || drawable.getComputeBoundingBoxCallback())
        bounds.addBox(drawable.getBoundingBox());
    out.bounds = bounds.bounds;
    out.nonFinite = bounds.nonFinite;

    TriangleCollector collector;
    collector.world = world;
    collector.out = triangles;
    const std::size_t first = triangles ? triangles->size() : 0;
    osg::TriangleFunctor<TriangleCollector> functor;
    static_cast<TriangleCollector&>(functor) = collector;
    drawable.accept(functor);
    out.counted = static_cast<const TriangleCollector&>(functor).count;
    if (!triangles)
        return out;
    out.stored = static_cast<std::uint32_t>(triangles->size() - first);
    // note: stored triangles are counter-clockwise seen from their drawn front, whatever
    // osg::FrontFace says (face culling and one-sided occluders rely on it)
    if (clockwiseFront)
        for (std::size_t t = first; t < triangles->size(); ++t)
            std::swap((*triangles)[t].b, (*triangles)[t].c);
    return out;
}
} // namespace osgVis
