// SPDX-License-Identifier: MIT
// Every OSG threading model with an osgViewer::CompositeViewer of two views of one VisibilityGroup
// (so two cull threads may cull it at once): each view draws exactly the pixels of the plain graph,
// synchronous modes let through the same objects per view as SingleThreaded does, and with async
// on the views are answered from regions after a few frames. Needs a display (Xvfb); the
// ThreadSanitizer build runs it too.
//
//   top view: a wall across x in [-12, 12] at y = 10; a row of boxes behind it at y = 25, one box
//   before it. View "front" walks towards the wall from y = -20 (the boxes behind are hidden);
//   view "side" stands at x = 40 looking along -x past the wall's end (it sees them).
#include "TestScenes.h"

#include <osgVis/Statistics>
#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osg/Image>
#include <osgViewer/CompositeViewer>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

using osgVis::test::CaptureImage;
using osgVis::test::setUpCapturingCamera;
using osgVis::test::makeBox;
using osgVis::test::samePixels;

namespace
{
constexpr unsigned Width = 128, Height = 96, Frames = 14, MovingFrames = 10;
constexpr unsigned Objects = 1 + 8 + 1;

osg::ref_ptr<osg::Group> content(osg::Group* group)
{
    const auto add = [&](const osg::Vec3& lo, const osg::Vec3& hi, const osg::Vec4& colour)
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(makeBox(lo, hi, colour));
        group->addChild(geode);
    };
    add({-12, 10, 0}, {12, 11, 12}, {0.8f, 0.8f, 0.8f, 1});
    for (int i = 0; i < 8; ++i)
        add({-10.f + 2.5f * i, 25, 0}, {-9.f + 2.5f * i, 26, 2}, {0.2f + 0.1f * i, 0.3f, 1.0f - 0.1f * i, 1});
    add({-1, 0, 0}, {1, 1, 1}, {1, 0.3f, 0.2f, 1});
    return group;
}


// The views move for MovingFrames frames, then hold still: the worker's last region then surely
// holds them however slowly it runs (sanitizers), so the last frame must be answered from it.
osg::Matrixd viewAt(unsigned view, unsigned frame)
{
    frame = std::min(frame, MovingFrames);
    if (view == 0)
        return osg::Matrixd::lookAt(osg::Vec3d(0.3 * frame, -20.0 + 0.5 * frame, 1.7),
                                    osg::Vec3d(0.3 * frame, 0.0 + 0.5 * frame, 1.5), osg::Vec3d(0, 0, 1));
    return osg::Matrixd::lookAt(osg::Vec3d(40.0 - 0.4 * frame, 18, 1.7), osg::Vec3d(0, 18 + 0.1 * frame, 1.2),
                                osg::Vec3d(0, 0, 1));
}

struct Result
{
    std::array<osg::ref_ptr<osg::Image>, 2> images;
    std::array<double, 2> visible{-1, -1}, fallback{-1, -1}; // the last frame's stats per view
};

Result render(osg::Node* scene, osgViewer::ViewerBase::ThreadingModel threading)
{
    osgViewer::CompositeViewer viewer;
    viewer.setThreadingModel(threading);
    std::array<osg::ref_ptr<CaptureImage>, 2> captures;
    for (unsigned v = 0; v < 2; ++v)
    {
        osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
        osg::Camera* camera = view->getCamera();
        captures[v] = setUpCapturingCamera(*camera, Width, Height);
        if (!captures[v])
            return {};
        camera->setProjectionMatrixAsPerspective(60.0, double(Width) / Height, 0.1, 200.0);
        camera->getStats()->collectStats("rendering", true);
        view->setSceneData(scene);
        viewer.addView(view);
    }
    viewer.realize();
    for (unsigned frame = 0; frame < Frames; ++frame)
    {
        for (unsigned v = 0; v < 2; ++v)
            viewer.getView(v)->getCamera()->setViewMatrix(viewAt(v, frame));
        // Simulation time advances like a 10 Hz walk (temporal coherence reads walk time only).
        viewer.frame(0.1 * frame);
    }
    viewer.stopThreading(); // the last draws may still run on draw threads

    Result result;
    const unsigned last = viewer.getFrameStamp()->getFrameNumber();
    for (unsigned v = 0; v < 2; ++v)
    {
        result.images[v] = captures[v]->image;
        osg::Stats* stats = viewer.getView(v)->getCamera()->getStats();
        stats->getAttribute(last, osgVis::STATS_VISIBLE, result.visible[v]);
        stats->getAttribute(last, osgVis::STATS_ASYNC_FALLBACK, result.fallback[v]);
    }
    return result;
}

const osgViewer::ViewerBase::ThreadingModel AllModels[] = {
    osgViewer::ViewerBase::SingleThreaded, osgViewer::ViewerBase::CullDrawThreadPerContext,
    osgViewer::ViewerBase::DrawThreadPerContext, osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext};
} // namespace

TEST(ThreadingModels, TwoViewsDrawThePlainGraphsPixelsUnderEveryModelSyncAndAsync)
{
    osg::ref_ptr<osg::Node> plain = content(new osg::Group);
    const Result reference = render(plain.get(), osgViewer::ViewerBase::SingleThreaded);
    if (!reference.images[0] || !reference.images[0]->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";

    // mask has no region queries: with async on it stays synchronous (and reports no fallbacks).
    for (const char* modes : {"frustum+octree", "mask"})
        for (const bool async : {false, true})
        {
            std::array<double, 2> singleThreadedVisible{-1, -1};
            for (const auto threading : AllModels)
            {
                SCOPED_TRACE(std::string(modes) + (async ? " async" : " sync") + ", threading model " +
                             std::to_string(int(threading)));
                osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(modes);
                group->setAsync(async);
                const Result culled = render(content(group.get()).get(), threading);
                for (unsigned v = 0; v < 2; ++v)
                {
                    ASSERT_TRUE(culled.images[v] && culled.images[v]->data());
                    EXPECT_TRUE(samePixels(*reference.images[v], *culled.images[v])) << "view " << v;
                    EXPECT_GT(culled.visible[v], 0.0);
                    const bool regions = std::string(modes) != "mask";
                    if (async)
                    {
                        EXPECT_EQ(culled.fallback[v], regions ? 0.0 : -1.0) << "view " << v;
                    }
                }
                // The front view's wall hides the row behind it from the octree, so the comparison is not
                // vacuous. (At this size the mask's occluder choice keeps the row.)
                if (std::string(modes) != "mask")
                {
                    EXPECT_LT(culled.visible[0], double(Objects) - 7.0);
                }
                if (threading == osgViewer::ViewerBase::SingleThreaded)
                    singleThreadedVisible = culled.visible;
                else if (!async)
                {
                    EXPECT_EQ(culled.visible, singleThreadedVisible) << "a synchronous mode must not depend on threads";
                }
            }
        }
}
