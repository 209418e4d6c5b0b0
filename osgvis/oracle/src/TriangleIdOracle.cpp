// SPDX-License-Identifier: MIT
#include <osgVis/oracle/TriangleIdOracle.h>

#include "IdColour.h"
#include "IdPassState.h"
#include "IdViewer.h"
#include "ObjectChain.h"

#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <osg/TriangleFunctor>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace osgVis::oracle
{
namespace
{
constexpr std::uint32_t NoPart = std::numeric_limits<std::uint32_t>::max();

bool finite(const osg::Vec3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// A drawable's triangles in its own coordinates, three vertices each, as osg::TriangleFunctor gives
// them; one with a non-finite world corner is left out, as the extraction leaves it out.
struct LocalTriangles
{
    osg::Matrixd world;
    osg::Vec3Array* corners = nullptr;

    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        if (!finite(osg::Vec3d(a) * world) || !finite(osg::Vec3d(b) * world) || !finite(osg::Vec3d(c) * world))
            return;
        corners->push_back(a);
        corners->push_back(b);
        corners->push_back(c);
    }
};

osg::ref_ptr<osg::Vec3Array> trianglesOf(const OracleObject& object)
{
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    osg::TriangleFunctor<LocalTriangles> functor;
    functor.world = object.world;
    functor.corners = corners.get();
    object.drawable->accept(functor);
    return corners;
}
} // namespace

struct TriangleIdOracle::Passes
{
    // A transparent object's triangles still drawn in this view: found ones leave, so the next pass
    // shows what was behind them.
    struct TransparentPart
    {
        std::uint32_t object = 0;
        osg::ref_ptr<osg::DrawElementsUInt> remaining;
        bool trimmed = false;
    };

    std::vector<std::uint32_t> first;  // per object, and one past the last
    std::vector<std::uint32_t> partOf; // object → index into transparent, or NoPart
    std::vector<TransparentPart> transparent;
    IdPassGraph graph;
    std::unique_ptr<IdViewer> viewer; // last: released first, while the graph is alive

    std::uint32_t objectOf(std::uint32_t triangle) const
    {
        return std::uint32_t(std::upper_bound(first.begin(), first.end(), triangle) - first.begin()) - 1;
    }

    void restoreTransparent()
    {
        for (TransparentPart& part : transparent)
            if (part.trimmed)
            {
                part.remaining->clear();
                for (std::uint32_t v = 0; v < 3 * (first[part.object + 1] - first[part.object]); ++v)
                    part.remaining->push_back(v);
                part.remaining->dirty();
                part.trimmed = false;
            }
    }

    // Marks every triangle in the image; with `found`, also lists the distinct ones, ascending.
    std::size_t collect(std::vector<std::uint8_t>& seen, std::vector<std::uint32_t>* found) const
    {
        const osg::Image& image = viewer->image();
        const std::size_t pixels = std::size_t(image.s()) * std::size_t(image.t());
        const unsigned char* data = image.data();
        const std::uint32_t count = first.back();
        std::size_t added = 0;
        std::uint32_t previous = 0;
        for (std::size_t p = 0; p < pixels; ++p)
        {
            const std::uint32_t idPlusOne = triangleIdPlusOneOfPixel(data + 4 * p);
            if (idPlusOne == previous)
                continue; // runs of one id are the common case
            previous = idPlusOne;
            if (idPlusOne == 0 || idPlusOne > count)
                continue;
            if (found)
                found->push_back(idPlusOne - 1);
            if (!seen[idPlusOne - 1])
            {
                seen[idPlusOne - 1] = 1;
                ++added;
            }
        }
        if (found)
        {
            std::sort(found->begin(), found->end());
            found->erase(std::unique(found->begin(), found->end()), found->end());
        }
        return added;
    }

    // Takes the found triangles out of their objects' element lists.
    void removeTransparent(const std::vector<std::uint32_t>& found)
    {
        for (std::size_t i = 0; i < found.size();)
        {
            const std::uint32_t object = objectOf(found[i]);
            std::size_t end = i;
            while (end < found.size() && found[end] < first[object + 1])
                ++end;
            if (partOf[object] != NoPart)
            {
                TransparentPart& part = transparent[partOf[object]];
                osg::DrawElementsUInt& elements = *part.remaining;
                std::size_t kept = 0;
                for (std::size_t e = 0; e + 2 < elements.size(); e += 3)
                {
                    const std::uint32_t triangle = first[object] + elements[e] / 3;
                    if (std::binary_search(found.begin() + i, found.begin() + end, triangle))
                        continue;
                    for (std::size_t k = 0; k < 3; ++k)
                        elements[kept++] = elements[e + k];
                }
                elements.resize(kept);
                elements.dirty();
                part.trimmed = true;
            }
            i = end;
        }
    }
};

TriangleIdOracle::TriangleIdOracle(const std::vector<OracleObject>& objects, unsigned width, unsigned height)
    : _passes(std::make_unique<Passes>())
{
    if (width == 0 || height == 0)
        throw std::invalid_argument("osgVis triangle oracle: empty image size");
    Passes& passes = *_passes;
    passes.graph = createIdPassGraph(createIdPassState(IdSource::VertexColour));
    passes.partOf.assign(objects.size(), NoPart);
    std::uint64_t total = 0;
    for (std::uint32_t i = 0; i < objects.size(); ++i)
    {
        const OracleObject& object = objects[i];
        passes.first.push_back(std::uint32_t(total));
        osg::ref_ptr<osg::Vec3Array> corners = trianglesOf(object);
        const std::uint64_t count = corners->size() / 3;
        if (total + count > MaxIdTriangles)
            throw std::runtime_error("osgVis triangle oracle: more triangles than 32-bit ids");
        if (count == 0)
            continue;

        osg::ref_ptr<osg::Vec4ubArray> colours = new osg::Vec4ubArray;
        colours->reserve(corners->size());
        for (std::uint64_t t = 0; t < count; ++t)
            colours->insert(colours->end(), 3, triangleIdColour(std::uint32_t(total + t)));
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setUseDisplayList(false);
        geometry->setUseVertexBufferObjects(true);
        geometry->setVertexArray(corners.get());
        geometry->setColorArray(colours.get(), osg::Array::BIND_PER_VERTEX);
        if (object.transparent)
        {
            Passes::TransparentPart part;
            part.object = i;
            part.remaining = new osg::DrawElementsUInt(GL_TRIANGLES);
            part.trimmed = true; // filled by restoreTransparent
            geometry->addPrimitiveSet(part.remaining.get());
            passes.partOf[i] = std::uint32_t(passes.transparent.size());
            passes.transparent.push_back(part);
        }
        else
            geometry->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(corners->size())));
        // The drawable's own state, innermost as in the real graph.
        osg::ref_ptr<osg::Group> drawn = new osg::Group;
        drawn->setStateSet(object.drawable->getStateSet());
        drawn->addChild(geometry.get());
        osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(object.world);
        placed->addChild(drawn.get());
        const osg::ref_ptr<osg::Node> chain = underPathState(object, placed.get());
        if (object.transparent)
            passes.graph.transparentIds->addChild(chain.get());
        else
            passes.graph.addOpaque(chain.get());
        total += count;
    }
    passes.first.push_back(std::uint32_t(total));
    passes.restoreTransparent();
    passes.viewer = std::make_unique<IdViewer>(width, height, passes.graph.root.get());
}

TriangleIdOracle::~TriangleIdOracle() = default;

std::size_t TriangleIdOracle::triangleCount() const
{
    return _passes->first.back();
}

std::uint32_t TriangleIdOracle::firstTriangle(std::uint32_t object) const
{
    return _passes->first.at(object);
}

std::size_t TriangleIdOracle::markVisible(const osg::Matrixd& view, const osg::Matrixd& projection,
                                          std::vector<std::uint8_t>& seen)
{
    Passes& passes = *_passes;
    if (seen.size() != triangleCount())
        throw std::invalid_argument("osgVis triangle oracle: seen must have one entry per triangle");
    passes.graph.showOpaqueIds(true);
    passes.viewer->drawFrame(view, projection);
    std::size_t added = passes.collect(seen, nullptr);
    if (passes.transparent.empty())
        return added;

    // Transparent triangles hide nothing, so each pass shows only the last one drawn at a pixel: repeat
    // without the ones found (in this view, whatever `seen` held before) until a pass shows none.
    passes.restoreTransparent();
    passes.graph.showOpaqueIds(false);
    std::vector<std::uint32_t> found;
    for (;;)
    {
        found.clear();
        passes.viewer->drawFrame(view, projection);
        added += passes.collect(seen, &found);
        if (found.empty())
            return added;
        passes.removeTransparent(found);
    }
}

std::vector<std::uint32_t> TriangleIdOracle::visible(const osg::Matrixd& view, const osg::Matrixd& projection)
{
    std::vector<std::uint8_t> seen(triangleCount(), 0);
    markVisible(view, projection, seen);
    std::vector<std::uint32_t> indices;
    for (std::uint32_t t = 0; t < seen.size(); ++t)
        if (seen[t])
            indices.push_back(t);
    return indices;
}
} // namespace osgVis::oracle
