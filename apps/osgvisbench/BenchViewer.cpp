// SPDX-License-Identifier: MIT
#include "BenchViewer.h"

#include <CameraSetup.h>

#include <osgVis/Statistics>
#include <osgVis/oracle/OffscreenContext.h>

#include <osg/GL>
#include <osgUtil/GLObjectsVisitor>
#include <osgViewer/Renderer>

#include <chrono>
#include <limits>
#include <string>

namespace osgVis::bench
{
namespace
{
// note: a final-draw callback, not a post-draw one: in OSG 3.6.5 a camera with a post-draw callback
// makes every osg::OcclusionQueryNode silently skip its queries, which would falsify `osg-oq`.
// It reads the frame back when the capture is armed (pictures), then waits for the GPU.
struct FinishFrame : osg::Camera::DrawCallback
{
    explicit FinishFrame(apps::FrameCapture* capture) : capture(capture) {}
    void operator()(osg::RenderInfo& renderInfo) const override
    {
        (*capture)(renderInfo);
        glFinish();
    }
    osg::ref_ptr<apps::FrameCapture> capture;
};
} // namespace

BenchViewer::BenchViewer(unsigned width, unsigned height, const core::WalkProjection& projection, osg::Node& model,
                         osgViewer::ViewerBase::ThreadingModel threading)
    : _viewer(new osgViewer::Viewer), _capture(new apps::FrameCapture)
{
    _viewer->setThreadingModel(threading);
    _viewer->setKeyEventSetsDone(0);
    _viewer->setQuitEventSetsDone(false);

    osg::Camera* camera = _viewer->getCamera();
    // The oracle's context helper: same pixel format, and it retries the X connection Xvfb sometimes
    // refuses when processes connect in quick succession.
    camera->setGraphicsContext(oracle::createOffscreenContext(width, height).get());
    camera->setViewport(0, 0, int(width), int(height));
    camera->setDrawBuffer(GL_FRONT);
    camera->setReadBuffer(GL_FRONT);
    camera->setProjectionResizePolicy(osg::Camera::FIXED);
    apps::applyWalkProjection(*camera, projection, double(width) / double(height));
    camera->setFinalDrawCallback(new FinishFrame(_capture.get()));
    camera->getStats()->collectStats("rendering", true);

    _viewer->setRealizeOperation(new osgUtil::GLObjectsOperation(&model));
    _viewer->realize();
    if (!_viewer->isRealized())
        throw ViewerError("the offscreen viewer failed to realize its OpenGL context");
}

BenchViewer::~BenchViewer()
{
    _viewer->stopThreading(); // the last draw may still run on a draw thread
}

void BenchViewer::setSceneData(osg::Node* scene)
{
    // The draw thread must finish the previous graph's last frame before the graph goes.
    const bool threaded = _viewer->areThreadsRunning();
    if (threaded)
        _viewer->stopThreading();
    _viewer->setSceneData(scene);
    if (threaded)
        _viewer->startThreading();
}

BenchViewer::FrameTiming BenchViewer::renderFrame(const BenchView& view)
{
    osg::Camera* camera = _viewer->getCamera();
    camera->setViewMatrix(view.view);
    camera->setProjectionMatrix(view.projection);

    FrameTiming timing;
    const auto start = std::chrono::steady_clock::now();
    // The walk's time stamp is the simulation time: temporal-coherence logic sees walk time, never
    // the wall clock, so runs are deterministic.
    _viewer->frame(view.key.time);
    timing.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    double cullSeconds = 0.0;
    const unsigned frameNumber = _viewer->getFrameStamp()->getFrameNumber();
    timing.cullMs = camera->getStats()->getAttribute(frameNumber, "Cull traversal time taken", cullSeconds)
                        ? cullSeconds * 1000.0
                        : std::numeric_limits<double>::quiet_NaN();
    double chainMs = 0.0;
    timing.chainMs = camera->getStats()->getAttribute(frameNumber, STATS_CULL_MS, chainMs)
                         ? chainMs
                         : std::numeric_limits<double>::quiet_NaN();
    return timing;
}

osg::ref_ptr<osg::Image> BenchViewer::renderAndCapture(const BenchView& view)
{
    _capture->arm();
    renderFrame(view);
    osg::ref_ptr<osg::Image> image = _capture->take();
    if (!image)
        throw ViewerError("the frame drawn for a picture could not be read back");
    return image;
}

const osgUtil::RenderStage& BenchViewer::lastRenderStage() const
{
    // note: a single-threaded viewer always culls through the renderer's first SceneView; threaded
    // ones alternate between two, and a SceneView's cull visitor carries the number of the frame
    // it last culled.
    const auto* renderer = dynamic_cast<const osgViewer::Renderer*>(_viewer->getCamera()->getRenderer());
    if (!renderer || !renderer->getSceneView(0) || !renderer->getSceneView(0)->getRenderStage())
        throw ViewerError("the viewer has no render stage to read the drawn objects from");
    const unsigned frameNumber = _viewer->getFrameStamp()->getFrameNumber();
    for (unsigned i = 0; i < 2; ++i)
    {
        const osgUtil::SceneView* sceneView = renderer->getSceneView(i);
        if (sceneView && sceneView->getRenderStage() && sceneView->getCullVisitor() &&
            sceneView->getCullVisitor()->getTraversalNumber() == frameNumber)
            return *sceneView->getRenderStage();
    }
    throw ViewerError("no SceneView of the renderer culled frame " + std::to_string(frameNumber));
}
} // namespace osgVis::bench
