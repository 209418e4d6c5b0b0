// SPDX-License-Identifier: MIT
#pragma once
// The one offscreen viewer every mode renders in: a pbuffer of the walk's size, single-threaded by
// default (the threading table runs the others), the walk's fixed projection and near/far,
// small-feature culling off, and a glFinish at the end of every frame so a frame's wall time
// includes the GPU work it queued. The render stage of the frame just culled can be read back
// after frame() under every model: OSG returns only once the frame's cull is done.
#include "BenchView.h"

#include <FrameCapture.h>

#include <osgVis/core/scene/Walk.h>

#include <osgUtil/RenderStage>
#include <osgViewer/Viewer>

#include <stdexcept>

namespace osgVis::bench
{
struct ViewerError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

class BenchViewer
{
public:
    // Compiles the GL objects of `model` once at realize, so that no mode pays the first upload of
    // buffers and textures inside its timed frames. Throws std::runtime_error when no pbuffer can be made.
    BenchViewer(unsigned width, unsigned height, const core::WalkProjection& projection, osg::Node& model,
                osgViewer::ViewerBase::ThreadingModel threading = osgViewer::ViewerBase::SingleThreaded);
    ~BenchViewer();

    void setSceneData(osg::Node* scene);
    // The pager the viewer's scene pages through (a paged database); call before setSceneData.
    void setDatabasePager(osgDB::DatabasePager* pager) { _viewer->setDatabasePager(pager); }

    struct FrameTiming
    {
        double seconds = 0.0; // wall time of the whole frame, glFinish included
        double cullMs = 0.0;  // OSG's "Cull traversal time taken" of this frame; NaN if OSG gave none
        double chainMs = 0.0; // osgVis's own visibility query in that cull (STATS_CULL_MS); NaN if none ran
    };
    FrameTiming renderFrame(const BenchView& view);
    // Renders the view once and returns its pixels (RGB, bottom row first), for pictures: not timed.
    osg::ref_ptr<osg::Image> renderAndCapture(const BenchView& view);

    // The main render stage of the frame just culled (its bins still hold the frame's leaves; with a
    // draw thread, it may be drawing them meanwhile, which only reads them).
    const osgUtil::RenderStage& lastRenderStage() const;

private:
    osg::ref_ptr<osgViewer::Viewer> _viewer;
    osg::ref_ptr<apps::FrameCapture> _capture;
};
} // namespace osgVis::bench
