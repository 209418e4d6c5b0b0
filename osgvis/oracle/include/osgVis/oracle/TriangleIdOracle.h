// SPDX-License-Identifier: MIT
#pragma once

#include <osgVis/oracle/OracleObject.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::oracle
{
// Exact visibility of single triangles by an item-buffer render: every triangle of every object draws
// its own 32-bit ID colour (so more than 16 M triangles are fine), depth-tested against all opaque
// geometry, under the object's own state (cull face, front face, polygon mode and offset, clip planes,
// colour mask, as IdBufferOracle keeps them) and its world matrix. A triangle is visible when it owns
// a pixel of the width × height image; transparent objects' triangles hide nothing.
//
// Triangles are numbered as the adapter's extraction stores them in core::Scene::triangles: object by
// object in enumeration order, each object's in osg::TriangleFunctor order, leaving out any triangle
// with a non-finite world corner (the extraction keeps none). The oracle gathers them itself from the
// drawables and draws the same vertices under the same matrices as the real drawable, so a triangle
// covers the pixels it covers in the real render. Quads and polygons are split as
// osg::TriangleFunctor splits them; for planar convex ones the pieces together cover the pixels the
// real primitive covers. Lines and points are no triangles: IdBufferOracle still sees their objects.
//
// Owns one offscreen viewer, current only inside visible()/markVisible(). Needs a display (Xvfb).
// Not thread-safe.
class TriangleIdOracle
{
public:
    // Throws std::runtime_error without a display or with more than 2^32 - 2 triangles.
    TriangleIdOracle(const std::vector<OracleObject>& objects, unsigned width, unsigned height);
    ~TriangleIdOracle();
    TriangleIdOracle(const TriangleIdOracle&) = delete;
    TriangleIdOracle& operator=(const TriangleIdOracle&) = delete;

    std::size_t triangleCount() const;
    // Object i owns triangles [firstTriangle(i), firstTriangle(i + 1)); i may be objects.size().
    std::uint32_t firstTriangle(std::uint32_t object) const;

    // Indices of the triangles with a pixel in this view, ascending. view and projection are used as
    // given (no near/far recomputation, no small-feature culling).
    std::vector<std::uint32_t> visible(const osg::Matrixd& view, const osg::Matrixd& projection);
    // The same, accumulated: seen[t] = 1 for every triangle t with a pixel; seen has triangleCount()
    // entries. Returns how many entries it set that were 0.
    std::size_t markVisible(const osg::Matrixd& view, const osg::Matrixd& projection, std::vector<std::uint8_t>& seen);

private:
    struct Passes;
    std::unique_ptr<Passes> _passes;
};
} // namespace osgVis::oracle
