// SPDX-License-Identifier: MIT
// The viewer's debug map draws what a module recorded about its query (core::DebugRecord): an
// occluded node as a red rectangle, the active occluders as thick blue lines, the eye's cell as a
// yellow rectangle; a module that records nothing (frustum) leaves those places empty. The map is
// rendered offscreen (needs an X display) over two boxes, with a test module that records a fixed
// description at places where no object lies.
#include "../../apps/osgvisviewer/CullingModes.h"
#include "../../apps/osgvisviewer/DebugMap.h"
#include <FrameCapture.h>
#include "AppProcess.h"
#include "RecordingTestModule.h"

#include <osgVis/SceneExtractor>
#include <osgVis/oracle/OffscreenContext.h>

#include <osg/Geode>
#include <osg/ShapeDrawable>
#include <osgViewer/Viewer>

#include <gtest/gtest.h>

#include <functional>

using namespace osgVis;

namespace
{
constexpr int MapSize = 256;

test::RecordedScene recordedScene()
{
    // The boxes lie at x = 0 and x = 10 on y = 0; the map spans about y ∈ [-6, 6].
    test::RecordedScene recorded;
    recorded.node = core::Aabb(core::Vec3(2, 1, 0), core::Vec3(8, 3, 1));
    recorded.occluder = {core::Vec3(2, -2, 0), core::Vec3(8, -2, 0), core::Vec3(8, -2, 3), core::Vec3(2, -2, 3)};
    recorded.eyeCell = core::Aabb(core::Vec3(0, -5, 0), core::Vec3(2, -3, 2));
    return recorded;
}

osg::ref_ptr<osg::Node> twoBoxes()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(0, 0, 0.5f), 1.0f)));
    geode->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(10, 0, 0.5f), 1.0f)));
    return geode;
}

struct RenderedMap
{
    osg::ref_ptr<osg::Image> image;
    osg::Matrixd projection; // of the map camera (its view matrix is the identity)
};

// Renders the map alone (it covers the whole frame) after the culling group has extracted the model.
RenderedMap renderMap(const std::string& mode)
{
    osg::ref_ptr<osg::Node> model = twoBoxes();
    osg::ref_ptr<ExtractedScene> objects = extractScene(*model);
    viewer::CullingModes modes(model.get(), mode);
    viewer::DebugMap map(*objects, modes);
    osg::ref_ptr<osg::Group> root = map.sceneWithMap(modes);

    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer.setSceneData(root.get());
    osg::Camera* camera = viewer.getCamera();
    camera->setGraphicsContext(oracle::createOffscreenContext(MapSize, MapSize, true).get());
    camera->setViewport(0, 0, MapSize, MapSize);
    camera->setDrawBuffer(GL_BACK);
    camera->setReadBuffer(GL_BACK);
    camera->setProjectionMatrixAsPerspective(60.0, 1.0, 0.1, 100.0);
    camera->setViewMatrixAsLookAt(osg::Vec3d(5, -20, 0.5), osg::Vec3d(5, 0, 0.5), osg::Vec3d(0, 0, 1));
    osg::ref_ptr<apps::FrameCapture> capture = new apps::FrameCapture;
    camera->setFinalDrawCallback(capture.get());
    map.setObservedCamera(camera);
    map.setViewport(0, 0, MapSize, MapSize);
    map.setEnabled(true);
    viewer.realize();

    // The group extracts its model in the first frame's cull; the map follows it from the next update.
    viewer.frame(0.0);
    capture->arm();
    viewer.frame(0.1);
    return {capture->take(), map.camera()->getProjectionMatrix()};
}

using ColourTest = std::function<bool(int r, int g, int b)>;

// Whether a pixel within `radius` pixels of the world point (x, y) passes `test`.
bool colourNear(const RenderedMap& map, double x, double y, const ColourTest& test, int radius = 3)
{
    const osg::Vec3d ndc = osg::Vec3d(x, y, 0.0) * map.projection;
    const int column = int((ndc.x() + 1.0) * 0.5 * MapSize), row = int((ndc.y() + 1.0) * 0.5 * MapSize);
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
        {
            const int c = column + dx, r = row + dy;
            if (c < 0 || r < 0 || c >= map.image->s() || r >= map.image->t())
                continue;
            const unsigned char* pixel = map.image->data(c, r);
            if (test(pixel[0], pixel[1], pixel[2]))
                return true;
        }
    return false;
}

const ColourTest reddish = [](int r, int g, int b) { return r > g + 30 && r > b + 30; };
const ColourTest blue = [](int r, int, int b) { return b > 200 && r < 100; };
const ColourTest yellow = [](int r, int g, int b) { return r > 230 && g > 230 && b < 30; };
} // namespace

TEST(DebugMapRecord, RecordedNodesOccludersAndEyeCellAreDrawn)
{
    ASSERT_TRUE(test::haveDisplay()) << "needs an X display: run the tests through scripts/test.sh";
    test::registerRecordingTestModule(recordedScene());
    const RenderedMap map = renderMap(test::RecordingTestModule::Name);
    ASSERT_TRUE(map.image);
    ASSERT_EQ(map.image->s(), MapSize);

    EXPECT_TRUE(colourNear(map, 5.0, 2.0, reddish)) << "the occluded node's rectangle is red";
    EXPECT_TRUE(colourNear(map, 5.0, -2.0, blue)) << "the occluder is a blue line";
    EXPECT_TRUE(colourNear(map, 0.0, -4.0, yellow)) << "the eye cell's left edge is yellow";
}

TEST(DebugMapRecord, ModulesThatRecordNothingLeaveThoseSpotsEmpty)
{
    ASSERT_TRUE(test::haveDisplay()) << "needs an X display: run the tests through scripts/test.sh";
    const RenderedMap map = renderMap("frustum");
    ASSERT_TRUE(map.image);

    EXPECT_FALSE(colourNear(map, 5.0, 2.0, reddish));
    EXPECT_FALSE(colourNear(map, 5.0, -2.0, blue));
    EXPECT_FALSE(colourNear(map, 0.0, -4.0, yellow));
    // The objects themselves are still drawn: the box at x = 0 is in view, hence green.
    EXPECT_TRUE(colourNear(map, 0.0, 0.0, [](int r, int g, int b) { return g > r + 30 && g > b + 30; }));
}
