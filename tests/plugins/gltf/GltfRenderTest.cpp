// SPDX-License-Identifier: MIT
// osgdb_gltf rendered offscreen (256 × 256, Mesa under Xvfb) against reference images checked by eye
// when they were stored (reference/*.png: the textured box shows the Cesium logo on every face, the
// engine its blocks, pistons and crankshaft). Camera: looking at the model's bounding sphere centre
// from direction (1, -2, 1) (OSG's Z-up, after the reader's Y-up rotation), at the distance where a
// 40° field of view just holds the sphere; the viewer's headlight. A VisibilityGroup with
// "frustum+octree" around the model must give exactly the same pixels (conservative culling).
#include "GltfTestModels.h"

#include <AppProcess.h>
#include <TestScenes.h>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgViewer/Viewer>
#include <osgVis/VisibilityGroup>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

using namespace osgVis::test::gltf;
using osgVis::test::litPixels;

namespace
{
constexpr unsigned Size = 256;

osg::ref_ptr<osg::Image> render(osg::Node* scene, const osg::BoundingSphere& sphere)
{
    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    osg::Camera* camera = viewer.getCamera();
    osg::ref_ptr<osgVis::test::CaptureImage> capture = osgVis::test::setUpCapturingCamera(*camera, Size, Size);
    if (!capture)
        return nullptr;
    const double fieldOfView = 40.0;
    const double distance = sphere.radius() / std::sin(osg::DegreesToRadians(fieldOfView / 2));
    osg::Vec3d direction(1, -2, 1);
    direction.normalize();
    camera->setProjectionMatrixAsPerspective(fieldOfView, 1.0, distance * 0.1, distance + 2 * sphere.radius());
    camera->setViewMatrixAsLookAt(osg::Vec3d(sphere.center()) + direction * distance, sphere.center(),
                                  osg::Vec3d(0, 0, 1));
    viewer.setSceneData(scene);
    viewer.realize();
    viewer.frame();
    viewer.frame();
    viewer.stopThreading();
    return new osg::Image(*capture->image, osg::CopyOp::DEEP_COPY_ALL);
}

// Pixels whose colour differs by more than `tolerance` in some channel.
unsigned differingPixels(const osg::Image& a, const osg::Image& b, int tolerance)
{
    unsigned differing = 0;
    for (unsigned y = 0; y < Size; ++y)
        for (unsigned x = 0; x < Size; ++x)
        {
            const unsigned char* p = a.data(x, y);
            const unsigned char* q = b.data(x, y);
            for (int c = 0; c < 4; ++c)
                if (std::abs(int(p[c]) - int(q[c])) > tolerance)
                {
                    ++differing;
                    break;
                }
        }
    return differing;
}

void expectMatchesReference(const std::string& sample, const std::string& name)
{
    if (!osgVis::test::haveDisplay())
        GTEST_SKIP() << "no X display (run under scripts/with-display.sh)";
    osgDB::ReaderWriter::ReadResult result = readFile(samplePath(sample));
    ASSERT_TRUE(result.validNode()) << result.message();
    osg::ref_ptr<osg::Node> model = result.getNode();
    const osg::BoundingSphere sphere = model->getBound();

    osg::ref_ptr<osg::Group> plain = new osg::Group;
    plain->addChild(model.get());
    osg::ref_ptr<osg::Image> image = render(plain.get(), sphere);
    ASSERT_TRUE(image) << "no offscreen context";
    ASSERT_EQ(image->s(), int(Size));
    EXPECT_GT(litPixels(*image), Size * Size / 20) << "the model should fill a good part of the view";

    const std::filesystem::path actual = osgVis::test::scratchDirectory("plugins", "gltf-render-" + name) / (name + ".png");
    const std::string reference = std::string(OSGVIS_GLTF_REFERENCE_DIR) + "/" + name + ".png";
    osg::ref_ptr<osg::Image> expected = osgDB::readRefImageFile(reference);
    const bool comparable = expected && expected->s() == int(Size) && expected->t() == int(Size) &&
                            expected->getPixelFormat() == GL_RGBA;
    const unsigned differing = comparable ? differingPixels(*image, *expected, 8) : Size * Size;
    if (differing >= Size * Size / 200)
    {
        osgDB::writeImageFile(*image, actual.string());
        ADD_FAILURE() << differing << " pixels differ from " << reference
                      << (comparable ? "" : " (missing, or not 256 x 256 RGBA)") << "; actual image written to "
                      << actual.string();
    }

    osg::ref_ptr<osgVis::VisibilityGroup> culled = new osgVis::VisibilityGroup("frustum+octree");
    culled->addChild(model.get());
    osg::ref_ptr<osg::Image> culledImage = render(culled.get(), sphere);
    ASSERT_TRUE(culledImage);
    EXPECT_EQ(differingPixels(*image, *culledImage, 0), 0u) << "conservative culling changed pixels";
}
} // namespace

TEST(GltfRender, BoxTexturedMatchesReference)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    expectMatchesReference("BoxTextured-glTF-Binary/BoxTextured.glb", "BoxTextured");
}

TEST(GltfRender, TwoCylinderEngineMatchesReference)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    expectMatchesReference("2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "2CylinderEngine");
}
