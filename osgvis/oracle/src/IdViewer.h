// SPDX-License-Identifier: MIT
#pragma once

#include <osg/Image>
#include <osg/Matrixd>
#include <osg/Node>
#include <osgViewer/Viewer>

namespace osgVis::oracle
{
// Where an ID pass draws: its own single-threaded viewer on a pbuffer context, drawing `scene` into an
// FBO whose RGBA8 colour (alpha kept: blending is off in every ID pass) is read back into an image each
// frame. The context is current only inside drawFrame(), so other viewers in the process keep theirs.
class IdViewer
{
public:
    IdViewer(unsigned width, unsigned height, osg::Node* scene); // throws std::runtime_error
    ~IdViewer();
    IdViewer(const IdViewer&) = delete;
    IdViewer& operator=(const IdViewer&) = delete;

    // One frame with this view and projection, used as given (no near/far recomputation).
    void drawFrame(const osg::Matrixd& view, const osg::Matrixd& projection);
    // The last frame's pixels: width × height RGBA bytes, row 0 at the bottom.
    const osg::Image& image() const { return *_image; }

private:
    osg::ref_ptr<osg::Node> _scene;
    osg::ref_ptr<osgViewer::Viewer> _viewer;
    osg::ref_ptr<osg::Image> _image;
};
} // namespace osgVis::oracle
