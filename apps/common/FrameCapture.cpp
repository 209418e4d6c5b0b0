// SPDX-License-Identifier: MIT
#include "FrameCapture.h"

#include <osg/RenderInfo>

namespace osgVis::apps
{
void FrameCapture::arm()
{
    std::lock_guard<std::mutex> lock(_mutex);
    _armed = true;
    _image = nullptr;
}

osg::ref_ptr<osg::Image> FrameCapture::take()
{
    std::lock_guard<std::mutex> lock(_mutex);
    osg::ref_ptr<osg::Image> image = _image;
    _image = nullptr;
    return image;
}

void FrameCapture::operator()(osg::RenderInfo& renderInfo) const
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (!_armed)
        return;
    const osg::Camera* camera = renderInfo.getCurrentCamera();
    const osg::Viewport* viewport = camera ? camera->getViewport() : nullptr;
    if (!viewport)
        return;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->readPixels(int(viewport->x()), int(viewport->y()), int(viewport->width()), int(viewport->height()), GL_RGB,
                      GL_UNSIGNED_BYTE);
    _image = image;
    _armed = false;
}
} // namespace osgVis::apps
