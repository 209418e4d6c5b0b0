// SPDX-License-Identifier: MIT
#include "IdRenderer.h"

#include "IdColour.h"

#include <cstring>
#include <limits>

namespace osgVis::oracle
{
namespace
{
constexpr std::uint32_t NoChild = std::numeric_limits<std::uint32_t>::max();
} // namespace

IdRenderer::IdRenderer(unsigned width, unsigned height, const IdPassState& pass,
                       const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& opaque,
                       const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& transparent,
                       std::size_t objectCount)
    : _transparentChildOf(objectCount, NoChild)
{
    _graph = createIdPassGraph(pass);
    for (const auto& [index, chain] : opaque)
        _graph.addOpaque(chain.get());
    for (const auto& [index, chain] : transparent)
    {
        _transparentChildOf[index] = _graph.transparentIds->getNumChildren();
        _graph.transparentIds->addChild(chain.get());
    }
    _viewer = std::make_unique<IdViewer>(width, height, _graph.root.get());
}

std::size_t IdRenderer::collectIds(std::vector<std::uint8_t>& seen, std::vector<std::uint32_t>* pixelCounts)
{
    const osg::Image& image = _viewer->image();
    const std::size_t pixels = std::size_t(image.s()) * std::size_t(image.t());
    const unsigned char* data = image.data();
    std::size_t found = 0;
    std::uint32_t previous = 0;
    for (std::size_t p = 0; p < pixels; ++p)
    {
        std::uint32_t rgba;
        std::memcpy(&rgba, data + 4 * p, 4);
        const std::uint32_t idPlusOne = idPlusOneOfPixel(rgba);
        if (pixelCounts && idPlusOne != 0 && idPlusOne <= pixelCounts->size())
            ++(*pixelCounts)[idPlusOne - 1];
        if (idPlusOne == previous)
            continue; // runs of one id are the common case
        previous = idPlusOne;
        if (idPlusOne == 0 || idPlusOne > seen.size() || seen[idPlusOne - 1])
            continue;
        const std::uint32_t index = idPlusOne - 1;
        seen[index] = 1;
        ++found;
        if (_transparentChildOf[index] != NoChild)
            _graph.transparentIds->setValue(_transparentChildOf[index], false);
    }
    return found;
}

void IdRenderer::render(const osg::Matrixd& view, const osg::Matrixd& projection, std::vector<std::uint8_t>& seen,
                        std::vector<std::uint32_t>* pixels)
{
    _graph.showOpaqueIds(true);
    _viewer->drawFrame(view, projection);
    collectIds(seen, pixels);
    if (_graph.transparentIds->getNumChildren() == 0)
        return;

    // Transparent objects hide nothing, so each pass shows only the last one drawn at a pixel: repeat
    // without the ones found until a pass finds none.
    _graph.showOpaqueIds(false);
    _graph.transparentIds->setAllChildrenOn();
    do
        _viewer->drawFrame(view, projection);
    while (collectIds(seen, pixels) != 0);
}
} // namespace osgVis::oracle
