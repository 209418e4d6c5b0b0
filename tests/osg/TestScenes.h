// SPDX-License-Identifier: MIT
#pragma once
// Small hand-built geometry and a view without GL for the adapter tests.
#include <osg/Camera>
#include <osg/FrameStamp>
#include <osg/Geometry>
#include <osg/GraphicsContext>
#include <osg/Image>
#include <osg/Vec3>
#include <osg/Vec4>
#include <osgUtil/CullVisitor>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <vector>

namespace osgVis::test
{
// Axis-aligned box as 12 indexed triangles, one flat colour, lighting off.
osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& min, const osg::Vec3& max,
                                    const osg::Vec4& colour = osg::Vec4(1, 1, 1, 1));

// One view culled by a bare cull visitor with its own render stage and state graph, no GL. OSG's own
// culling is off (NO_CULLING), so what is drawn is what osgVis let through: a VisibilityGroup in the
// graph, or the visitor itself when it is an osgVis::CullVisitor. Each draw is a frame: the frame
// stamp advances by one frame of 1/60 s, as a viewer's does.
class TestView
{
public:
    // `cv`: the visitor to cull with (null: a stock osgUtil::CullVisitor); it gets an identifier of
    // its own, so the view keeps its own state in every VisibilityGroup.
    explicit TestView(osgUtil::CullVisitor* cv = nullptr);

    // Drawables that reached the render graph when `root` is culled with the view matrix `view`, a
    // 40° square frustum from 0.5 to 1000 and a 256 × 256 viewport.
    std::set<const osg::Drawable*> draw(osg::Node& root, const osg::Matrixd& view = lookingDownX());
    // The eye at the origin looking down +x, z up.
    static osg::Matrixd lookingDownX();

private:
    osg::ref_ptr<osgUtil::CullVisitor> _cv;
    osg::ref_ptr<osg::FrameStamp> _frameStamp;
    unsigned _frames = 0;
};

// An offscreen RGBA8 context with a 24-bit depth buffer, double-buffered: a pbuffer, or a small
// undecorated window where the GLX server has no pbuffers. Null without a display.
osg::ref_ptr<osg::GraphicsContext> createTestContext(unsigned width, unsigned height);

// A camera's final-draw callback reading its colour buffer (width × height RGBA) into `image` and,
// with `keepFrames` (set before the first draw), a copy of it at every draw. A threaded viewer draws
// behind its main thread, and its stopThreading() drops the draws still queued: waitForFrames first.
struct CaptureImage : public osg::Camera::DrawCallback
{
    CaptureImage(unsigned w, unsigned h) : width(w), height(h) {}
    unsigned width, height;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    bool keepFrames = false;
    void operator()(osg::RenderInfo&) const override;

    // Waits until `draws` draws have been captured (for at most `timeout`) and returns the copies
    // kept, one per draw in drawing order (none without keepFrames).
    std::vector<osg::ref_ptr<osg::Image>> waitForFrames(unsigned draws,
                                                        std::chrono::seconds timeout = std::chrono::seconds(60)) const;

private:
    mutable std::mutex _mutex;
    mutable std::condition_variable _drawn;
    mutable unsigned _draws = 0;
    mutable std::vector<osg::ref_ptr<osg::Image>> _frames;
};

// Gives `camera` an offscreen context of width × height (createTestContext), the whole viewport,
// the context's colour buffer to draw and read, a black clear colour, fixed near/far, no
// small-feature culling, and a CaptureImage as its final-draw callback, which it returns. Null
// (the camera untouched) without a display.
osg::ref_ptr<CaptureImage> setUpCapturingCamera(osg::Camera& camera, unsigned width, unsigned height);

// Same size and the same bytes: what conservative culling must leave of a frame.
bool samePixels(const osg::Image& a, const osg::Image& b);
// Pixels of an RGBA image that are not black (the captures clear to black).
unsigned litPixels(const osg::Image& image);
} // namespace osgVis::test
