// SPDX-License-Identifier: MIT
// The node kit must not change the picture: the same scene rendered as a plain graph, under a
// VisibilityGroup and with osgVis::CullVisitor gives identical pixels, while the culler reports that
// it did cull something (so the comparison is not vacuous). Needs a display (Xvfb).
//
//   top view (camera at y = -30 looking +y, 60° field of view, the graph shifted by (1, 2, 0)):
//
//        x: -40  -20   0   20   40
//   y=20    □    □    □    □    □      boxes at |x| = 40 lie outside the frustum
//   y=10    □    □    □    □    □
//   y= 0    □    □    □    □    □
//   y=-5      ▪    ▪    ▪    ▪         one Geode, four drawables (outer two outside)
//   y=-30             ◉                camera
//   y=-50             □                behind the camera
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osg/Image>
#include <osg/MatrixTransform>
#include <osgViewer/Renderer>
#include <osgViewer/Viewer>

#include <gtest/gtest.h>

using osgVis::test::CaptureImage;
using osgVis::test::setUpCapturingCamera;
using osgVis::test::makeBox;
using osgVis::test::litPixels;
using osgVis::test::samePixels;

namespace
{
constexpr unsigned Width = 160, Height = 120;

osg::Vec4 colourOf(unsigned i)
{
    return osg::Vec4(0.2f + 0.8f * float(i % 3) / 2.f, 0.2f + 0.8f * float((i / 3) % 3) / 2.f,
                     0.2f + 0.8f * float((i / 9) % 3) / 2.f, 1.f);
}

// The scene's top-level nodes, to be put under either a plain group or a VisibilityGroup.
std::vector<osg::ref_ptr<osg::Node>> sceneContent()
{
    std::vector<osg::ref_ptr<osg::Node>> nodes;
    unsigned colour = 0;
    const auto addBox = [&](const osg::Vec3& centre) {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(makeBox(centre - osg::Vec3(2, 2, 2), centre + osg::Vec3(2, 2, 2), colourOf(colour++)));
        nodes.push_back(geode);
    };
    for (int row = 0; row < 3; ++row)
        for (int column = -2; column <= 2; ++column)
            addBox(osg::Vec3(column * 20.f, row * 10.f, 0.f));
    addBox(osg::Vec3(0, -50, 0));

    osg::ref_ptr<osg::Geode> strip = new osg::Geode;
    for (float x : {-30.f, -10.f, 10.f, 30.f})
        strip->addDrawable(makeBox(osg::Vec3(x - 1, -6, 4), osg::Vec3(x + 1, -4, 6), colourOf(colour++)));
    nodes.push_back(strip);
    return nodes;
}

constexpr unsigned SceneObjects = 15 + 1 + 4;

osg::ref_ptr<osg::Node> wrap(osg::Group* group, const std::vector<osg::ref_ptr<osg::Node>>& content)
{
    for (const auto& node : content)
        group->addChild(node);
    osg::ref_ptr<osg::MatrixTransform> shifted = new osg::MatrixTransform(osg::Matrix::translate(1, 2, 0));
    shifted->addChild(group);
    return shifted;
}


enum class Culling
{
    Osg,
    CullVisitor
};

struct Frame
{
    osg::ref_ptr<osg::Image> image;
    osgVis::CullStatistics cullVisitorFigures;
    double statsVisible = -1; // "osgVis visible" in the camera's stats, -1 when absent
};

Frame render(osg::Node* scene, Culling culling,
             osgViewer::ViewerBase::ThreadingModel threading = osgViewer::ViewerBase::SingleThreaded)
{
    osgViewer::Viewer viewer;
    viewer.setThreadingModel(threading);
    osg::Camera* camera = viewer.getCamera();
    osg::ref_ptr<CaptureImage> capture = setUpCapturingCamera(*camera, Width, Height);
    if (!capture)
        return {};
    camera->setProjectionMatrixAsPerspective(60.0, double(Width) / Height, 1.0, 200.0);
    camera->setViewMatrixAsLookAt(osg::Vec3d(0, -30, 5), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1));
    if (culling == Culling::CullVisitor)
        osgVis::CullVisitor::installOn(viewer, "frustum");
    viewer.setSceneData(scene);
    viewer.realize();
    // Several frames: the Renderer's two SceneViews alternate and share one per-view state.
    viewer.frame();
    viewer.frame();
    viewer.frame();
    viewer.stopThreading(); // the last draw (and its capture) may still run on a draw thread

    Frame frame;
    frame.image = capture->image;
    if (culling == Culling::CullVisitor)
        if (auto* renderer = dynamic_cast<osgViewer::Renderer*>(camera->getRenderer()))
            if (auto* cv = dynamic_cast<osgVis::CullVisitor*>(renderer->getSceneView(0)->getCullVisitor()))
                frame.cullVisitorFigures = cv->getLastStatistics();
    if (osg::Stats* stats = camera->getStats())
        stats->getAttribute(viewer.getFrameStamp()->getFrameNumber(), osgVis::STATS_VISIBLE, frame.statsVisible);
    return frame;
}

} // namespace

TEST(RenderEquivalence, VisibilityGroupAndCullVisitorDrawTheSamePixelsAsOsg)
{
    const auto content = sceneContent();
    osg::ref_ptr<osg::Node> plain = wrap(new osg::Group, content);
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");
    osg::ref_ptr<osg::Node> culled = wrap(group.get(), content);

    const Frame reference = render(plain.get(), Culling::Osg);
    if (!reference.image || !reference.image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_GT(litPixels(*reference.image), Width * Height / 50) << "the scene should cover part of the frame";

    const Frame byGroup = render(culled.get(), Culling::Osg);
    ASSERT_TRUE(byGroup.image && byGroup.image->data());
    EXPECT_TRUE(samePixels(*reference.image, *byGroup.image));
    const osgVis::CullStatistics groupFigures = group->getLastStatistics();
    EXPECT_EQ(groupFigures.objects, SceneObjects);
    EXPECT_GT(groupFigures.visible, 0u);
    EXPECT_LT(groupFigures.visible, groupFigures.objects) << "nothing was culled: the comparison proves nothing";
    EXPECT_EQ(groupFigures.trianglesVisible, 12u * groupFigures.visible);
    EXPECT_EQ(byGroup.statsVisible, double(groupFigures.visible));

    const Frame byCullVisitor = render(plain.get(), Culling::CullVisitor);
    ASSERT_TRUE(byCullVisitor.image && byCullVisitor.image->data());
    EXPECT_TRUE(samePixels(*reference.image, *byCullVisitor.image));
    EXPECT_EQ(byCullVisitor.cullVisitorFigures.objects, SceneObjects);
    EXPECT_EQ(byCullVisitor.cullVisitorFigures.visible, groupFigures.visible);
    EXPECT_EQ(byCullVisitor.statsVisible, double(groupFigures.visible));
}

TEST(RenderEquivalence, ThreadedModelsDrawTheSamePixels)
{
    const auto content = sceneContent();
    osg::ref_ptr<osg::Node> plain = wrap(new osg::Group, content);
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum");
    osg::ref_ptr<osg::Node> culled = wrap(group.get(), content);

    const Frame reference = render(plain.get(), Culling::Osg);
    if (!reference.image || !reference.image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    for (auto threading : {osgViewer::ViewerBase::DrawThreadPerContext,
                           osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext})
    {
        SCOPED_TRACE(threading);
        const Frame byGroup = render(culled.get(), Culling::Osg, threading);
        ASSERT_TRUE(byGroup.image && byGroup.image->data());
        EXPECT_TRUE(samePixels(*reference.image, *byGroup.image));
        const Frame byCullVisitor = render(plain.get(), Culling::CullVisitor, threading);
        ASSERT_TRUE(byCullVisitor.image && byCullVisitor.image->data());
        EXPECT_TRUE(samePixels(*reference.image, *byCullVisitor.image));
        EXPECT_LT(byCullVisitor.cullVisitorFigures.visible, SceneObjects);
    }
}
