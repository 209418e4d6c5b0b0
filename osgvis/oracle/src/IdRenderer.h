// SPDX-License-Identifier: MIT
#pragma once

#include "IdPassState.h"

#include <osg/Group>
#include <osg/Image>
#include <osg/Switch>
#include <osgViewer/Viewer>

#include <cstdint>
#include <vector>

namespace osgVis::oracle
{
// One offscreen ID render at one resolution: its own viewer on a pbuffer context, drawing into an
// FBO whose colour is read back into an image every frame. The context is current only during
// render(), so other viewers in the process keep theirs.
class IdRenderer
{
public:
    // opaque/transparent: the object chains with the object indices they draw.
    IdRenderer(unsigned width, unsigned height, const IdPassState& pass,
               const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& opaque,
               const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& transparent,
               std::size_t objectCount);
    ~IdRenderer();
    IdRenderer(const IdRenderer&) = delete;
    IdRenderer& operator=(const IdRenderer&) = delete;

    // Sets seen[i] = 1 for every object i with a pixel in this image; seen must be zeroed, objectCount long.
    // With `pixels` (zeroed, objectCount long): pixels[i] += the pixels object i shows (a transparent
    // object's pixels also count for what shows through it).
    void render(const osg::Matrixd& view, const osg::Matrixd& projection, std::vector<std::uint8_t>& seen,
                std::vector<std::uint32_t>* pixels = nullptr);

private:
    void drawFrame();
    // Marks the ids in the image; returns how many were new. Newly seen transparent objects leave the
    // transparent switch, so the next pass shows what was behind them.
    std::size_t collectIds(std::vector<std::uint8_t>& seen, std::vector<std::uint32_t>* pixelCounts);

    osg::ref_ptr<osgViewer::Viewer> _viewer;
    osg::ref_ptr<osg::Image> _image;
    osg::ref_ptr<osg::Group> _root;
    osg::ref_ptr<osg::Group> _opaqueIds;
    osg::ref_ptr<osg::Group> _opaqueDepth;
    osg::ref_ptr<osg::Switch> _transparentIds;
    std::vector<std::uint32_t> _transparentChildOf; // object index → child of _transparentIds, or NoChild
};
} // namespace osgVis::oracle
