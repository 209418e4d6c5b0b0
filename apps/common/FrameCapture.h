// SPDX-License-Identifier: MIT
#pragma once
// Reads back the pixels of one drawn frame. Installed as the camera's FINAL draw callback: a
// post-draw callback would make osg::OcclusionQueryNode stop querying in OSG 3.6.5 ("Invalid
// RQCB"), which would change what the `osg` baseline draws.
#include <osg/Camera>
#include <osg/Image>

#include <mutex>

namespace osgVis::apps
{
class FrameCapture : public osg::Camera::DrawCallback
{
public:
    // The next frame drawn after this call is kept.
    void arm();
    // The kept frame (RGB, bottom row first), or null when none was drawn since arm().
    osg::ref_ptr<osg::Image> take();

    void operator()(osg::RenderInfo& renderInfo) const override;

private:
    mutable std::mutex _mutex;
    mutable bool _armed = false;
    mutable osg::ref_ptr<osg::Image> _image;
};
} // namespace osgVis::apps
