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
//
// The second test changes that scene from update callbacks every frame, as applications do, and
// never calls dirtyScene(); every frame of both views must still be the plain graph's.
#include "TestScenes.h"

#include <osgVis/Statistics>
#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osg/Image>
#include <osg/MatrixTransform>
#include <osg/NodeCallback>
#include <osgViewer/CompositeViewer>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <string>
#include <thread>
#include <utility>
#include <vector>

using osgVis::test::CaptureImage;
using osgVis::test::makeBox;
using osgVis::test::samePixels;
using osgVis::test::setUpCapturingCamera;

namespace
{
constexpr unsigned Width = 128, Height = 96, Frames = 14, MovingFrames = 10;
constexpr unsigned Objects = 1 + 8 + 1;

osg::ref_ptr<osg::Geode> boxGeode(const osg::Vec3& lo, const osg::Vec3& hi, const osg::Vec4& colour)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(lo, hi, colour));
    return geode;
}

osg::ref_ptr<osg::Geode> wall()
{
    return boxGeode({-12, 10, 0}, {12, 11, 12}, {0.8f, 0.8f, 0.8f, 1});
}

osg::ref_ptr<osg::Geode> boxBeforeTheWall()
{
    return boxGeode({-1, 0, 0}, {1, 1, 1}, {1, 0.3f, 0.2f, 1});
}

void addRowBehindTheWall(osg::Group* group)
{
    for (int i = 0; i < 8; ++i)
        group->addChild(
            boxGeode({-10.f + 2.5f * i, 25, 0}, {-9.f + 2.5f * i, 26, 2}, {0.2f + 0.1f * i, 0.3f, 1.0f - 0.1f * i, 1}));
}

osg::ref_ptr<osg::Group> content(osg::Group* group)
{
    group->addChild(wall());
    addRowBehindTheWall(group);
    group->addChild(boxBeforeTheWall());
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
    std::array<std::vector<osg::ref_ptr<osg::Image>>, 2> images; // per view, every frame's in order
    std::vector<unsigned> frameNumbers;                          // every frame's frame stamp number
    std::array<osg::ref_ptr<osg::Stats>, 2> stats;               // per view, its camera's

    // What view `v`'s cull recorded as `name` in the frame numbered `frame` (the last by default);
    // -1 where it recorded nothing.
    double figure(unsigned v, const char* name, unsigned frame = ~0u) const
    {
        double value = -1;
        stats[v]->getAttribute(frame == ~0u ? frameNumbers.back() : frame, name, value);
        return value;
    }
};

// `settle`: before the last frame, the eye having held still since MovingFrames, give asynchronous
// workers time to finish the regions around it (on a loaded machine they may lag a few frames; the
// last frame's fallback figure is then about the design, not the load).
Result render(osg::Node* scene, osgViewer::ViewerBase::ThreadingModel threading, unsigned frames = Frames,
              bool settle = false)
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
        captures[v]->keepFrames = true;
        camera->setProjectionMatrixAsPerspective(60.0, double(Width) / Height, 0.1, 200.0);
        camera->getStats()->collectStats("rendering", true);
        view->setSceneData(scene);
        viewer.addView(view);
    }
    viewer.realize();
    Result result;
    for (unsigned frame = 0; frame < frames; ++frame)
    {
        for (unsigned v = 0; v < 2; ++v)
            viewer.getView(v)->getCamera()->setViewMatrix(viewAt(v, frame));
        if (settle && frame + 1 == frames)
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
        // Simulation time advances like a 10 Hz walk (temporal coherence reads walk time only).
        viewer.frame(0.1 * frame);
        result.frameNumbers.push_back(viewer.getFrameStamp()->getFrameNumber());
    }
    // Draw threads run a frame or two behind, and stopThreading() drops the draws still queued.
    for (unsigned v = 0; v < 2; ++v)
    {
        result.images[v] = captures[v]->waitForFrames(frames);
        result.stats[v] = viewer.getView(v)->getCamera()->getStats();
    }
    viewer.stopThreading();
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
    if (reference.images[0].size() != Frames)
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
                const Result culled = render(content(group.get()).get(), threading, Frames, async);
                for (unsigned v = 0; v < 2; ++v)
                {
                    ASSERT_EQ(culled.images[v].size(), Frames) << "view " << v;
                    EXPECT_TRUE(samePixels(*reference.images[v].back(), *culled.images[v].back())) << "view " << v;
                    EXPECT_GT(culled.figure(v, osgVis::STATS_VISIBLE), 0.0);
                    const bool regions = std::string(modes) != "mask";
                    if (async)
                    {
                        EXPECT_EQ(culled.figure(v, osgVis::STATS_ASYNC_FALLBACK), regions ? 0.0 : -1.0) << "view " << v;
                    }
                }
                const std::array<double, 2> visible{culled.figure(0, osgVis::STATS_VISIBLE),
                                                    culled.figure(1, osgVis::STATS_VISIBLE)};
                // The front view's wall hides the row behind it from the octree, so the comparison is not
                // vacuous. (At this size the mask's occluder choice keeps the row.)
                if (std::string(modes) != "mask")
                {
                    EXPECT_LT(visible[0], double(Objects) - 7.0);
                }
                if (threading == osgViewer::ViewerBase::SingleThreaded)
                    singleThreadedVisible = visible;
                else if (!async)
                {
                    EXPECT_EQ(visible, singleThreadedVisible) << "a synchronous mode must not depend on threads";
                }
            }
        }
}

namespace
{
// The changes, by frame number (the update visitor's: the viewer's first frame is 1). Both views look
// the whole time; from frame 11 on they stand where the first test's last frame stands.
constexpr unsigned ChangingFrames = 16, FirstWallAway = 12;

// (a) A box behind the wall at x = 0 drives out past the wall's end to x = 24 and back, every 12 frames.
double driverX(unsigned frame)
{
    return 4.0 * std::min(frame % 12, 12 - frame % 12);
}

// (b) The wall slides 30 m aside (out of the front view) for frames 12 and 13, back for 14 and 15,
// aside again for 16, the last.
bool wallAway(unsigned frame)
{
    return frame >= FirstWallAway && (frame - FirstWallAway) % 4 < 2;
}

// (c) A box joins the row's group at frame 3 and leaves it at frame 7.
bool extraBoxIn(unsigned frame)
{
    return frame >= 3 && frame < 7;
}

// (d) The box before the wall is masked off at frame 5 and on again at frame 9.
bool boxBeforeTheWallOff(unsigned frame)
{
    return frame >= 5 && frame < 9;
}

// The objects the group knows: content()'s, the driving box and the box that comes and goes, less
// the masked one.
double objectsAt(unsigned frame)
{
    return Objects + 1.0 + (extraBoxIn(frame) ? 1 : 0) - (boxBeforeTheWallOff(frame) ? 1 : 0);
}

// Gives `node` an update callback, as an application's: `change(*node, frame number)`, then the
// traversal. (The callback belongs to the node, so it may hold it by address.)
template <class NodeType, class Change> void changeEachFrame(NodeType* node, Change change)
{
    struct EachFrame : public osg::NodeCallback
    {
        EachFrame(NodeType* n, Change c) : node(n), change(std::move(c)) {}
        NodeType* node;
        Change change;
        void operator()(osg::Node* n, osg::NodeVisitor* nv) override
        {
            change(*node, nv->getFrameStamp()->getFrameNumber());
            traverse(n, nv);
        }
    };
    node->setUpdateCallback(new EachFrame(node, std::move(change)));
}

// content() changed by update callbacks (a)–(d), deterministic in the frame number: the wall under a
// MatrixTransform left STATIC (as applications often leave it), the row two plain groups down
// (VisibilityGroup → Group → Group → Geode), the box before the wall in a group that masks it (a
// node masked off runs no update callback of its own), and a DYNAMIC transform driving a green box.
osg::ref_ptr<osg::Group> changingContent(osg::Group* group)
{
    osg::ref_ptr<osg::MatrixTransform> wallMover = new osg::MatrixTransform;
    wallMover->setDataVariance(osg::Object::STATIC);
    wallMover->addChild(wall());
    changeEachFrame(wallMover.get(), [](osg::MatrixTransform& transform, unsigned frame)
                    { transform.setMatrix(osg::Matrixd::translate(wallAway(frame) ? -30.0 : 0.0, 0, 0)); });
    group->addChild(wallMover);

    osg::ref_ptr<osg::Group> rowParent = new osg::Group, row = new osg::Group;
    addRowBehindTheWall(row.get());
    osg::ref_ptr<osg::Geode> extra = boxGeode({-8, 3, 0}, {-6, 4, 3}, {1, 0.9f, 0.2f, 1}); // before the wall
    changeEachFrame(row.get(),
                    [extra](osg::Group& parent, unsigned frame)
                    {
                        if (extraBoxIn(frame) && !parent.containsNode(extra.get()))
                            parent.addChild(extra.get());
                        else if (!extraBoxIn(frame) && parent.containsNode(extra.get()))
                            parent.removeChild(extra.get());
                    });
    rowParent->addChild(row);
    group->addChild(rowParent);

    osg::ref_ptr<osg::Group> masking = new osg::Group;
    masking->addChild(boxBeforeTheWall());
    changeEachFrame(masking.get(), [](osg::Group& parent, unsigned frame)
                    { parent.getChild(0)->setNodeMask(boxBeforeTheWallOff(frame) ? 0u : ~0u); });
    group->addChild(masking);

    osg::ref_ptr<osg::MatrixTransform> driver = new osg::MatrixTransform;
    driver->setDataVariance(osg::Object::DYNAMIC);
    driver->addChild(boxGeode({-1, 17, 0}, {1, 19, 2}, {0.2f, 0.9f, 0.3f, 1}));
    changeEachFrame(driver.get(), [](osg::MatrixTransform& transform, unsigned frame)
                    { transform.setMatrix(osg::Matrixd::translate(driverX(frame), 0, 0)); });
    group->addChild(driver);
    return group;
}
} // namespace

// Applications change their graphs from update callbacks and never call dirtyScene(). Under every
// threading model, with two views (so two cull threads may cull the group at once), the
// VisibilityGroup must find each change by itself at the first cull of the frame that made it: (a) a
// DYNAMIC transform driving a box from behind the wall into the open and back, every frame; (b) the
// wall's STATIC transform sliding it aside, so the row behind shows at once, and back; (c) a Geode
// added to and removed from a group two levels down; (d) a Geode masked off and on again. Every
// frame of both views, the frames of the changes included and the last (where the wall slides aside),
// must be the plain graph's pixels. The group's statistics show the objects it knows following the
// changes frame by frame (it re-extracted by itself: nothing here forces it) and, with the octree,
// the row hidden while the wall stands, so a culler that missed the wall's slide would leave the row
// out of the next frame.
TEST(ThreadingModels, TwoViewsDrawThePlainGraphsPixelsWhileUpdateCallbacksChangeIt)
{
    osg::ref_ptr<osg::Node> plain = changingContent(new osg::Group);
    const Result reference = render(plain.get(), osgViewer::ViewerBase::SingleThreaded, ChangingFrames);
    if (reference.images[0].size() != ChangingFrames)
        GTEST_SKIP() << "no GL context (run under xvfb-run)";

    std::vector<double> expectedObjects;
    for (const unsigned frame : reference.frameNumbers)
        expectedObjects.push_back(objectsAt(frame));
    for (const char* modes : {"frustum+octree", "mask"})
        for (const auto threading : AllModels)
        {
            SCOPED_TRACE(std::string(modes) + ", threading model " + std::to_string(int(threading)));
            osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(modes);
            const Result culled = render(changingContent(group.get()).get(), threading, ChangingFrames);
            ASSERT_EQ(culled.frameNumbers, reference.frameNumbers);
            for (unsigned v = 0; v < 2; ++v)
            {
                ASSERT_EQ(culled.images[v].size(), ChangingFrames) << "view " << v;
                std::string differing;
                std::vector<double> objects;
                for (unsigned i = 0; i < ChangingFrames; ++i)
                {
                    const unsigned frame = culled.frameNumbers[i];
                    if (!samePixels(*reference.images[v][i], *culled.images[v][i]))
                        differing += " " + std::to_string(frame);
                    objects.push_back(culled.figure(v, osgVis::STATS_OBJECTS, frame));
                }
                EXPECT_EQ(differing, "") << "view " << v << ": the frames whose pixels differ";
                EXPECT_EQ(objects, expectedObjects) << "view " << v << ": the objects the group knew, frame by frame";
            }
            if (std::string(modes) != "mask")
            {
                const unsigned standing = FirstWallAway - 1; // the first test's last pose
                EXPECT_LT(culled.figure(0, osgVis::STATS_VISIBLE, standing), objectsAt(standing) - 7.0);
            }
        }
}
