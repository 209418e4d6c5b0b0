// SPDX-License-Identifier: MIT
#pragma once

#include "IdPassState.h"
#include "IdViewer.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::oracle
{
// One offscreen object-ID render at one resolution (its own IdViewer).
class IdRenderer
{
public:
    // opaque/transparent: the object chains with the object indices they draw.
    IdRenderer(unsigned width, unsigned height, const IdPassState& pass,
               const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& opaque,
               const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& transparent,
               std::size_t objectCount);
    IdRenderer(const IdRenderer&) = delete;
    IdRenderer& operator=(const IdRenderer&) = delete;

    // Sets seen[i] = 1 for every object i with a pixel in this image; seen must be zeroed, objectCount long.
    // With `pixels` (zeroed, objectCount long): pixels[i] += the pixels object i shows (a transparent
    // object's pixels also count for what shows through it).
    void render(const osg::Matrixd& view, const osg::Matrixd& projection, std::vector<std::uint8_t>& seen,
                std::vector<std::uint32_t>* pixels = nullptr);

private:
    // Marks the ids in the image; returns how many were new. Newly seen transparent objects leave the
    // transparent switch, so the next pass shows what was behind them.
    std::size_t collectIds(std::vector<std::uint8_t>& seen, std::vector<std::uint32_t>* pixelCounts);

    IdPassGraph _graph;
    std::vector<std::uint32_t> _transparentChildOf; // object index → child of _graph.transparentIds, or NoChild
    std::unique_ptr<IdViewer> _viewer;              // last: released first, while the graph is alive
};
} // namespace osgVis::oracle
