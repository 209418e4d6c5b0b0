// SPDX-License-Identifier: MIT
// osgvisglfw renders in its own GLFW window under an X display (Xvfb with Mesa in the tests):
// the built-in demo with and without osgVis, and a model file written here.
#include "GlfwAppProcess.h"

#include <osgVis/gen/BoxGeometry.h>

#include <osg/Geode>
#include <osg/Image>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <cstring>

using namespace osgVis::test;

namespace
{
std::string quoted(const std::filesystem::path& path)
{
    return "\"" + path.string() + "\"";
}

// Whether any pixel differs from the first one.
bool hasTwoColours(const osg::Image& image)
{
    const unsigned pixelBytes = image.getPixelSizeInBits() / 8;
    const unsigned char* data = image.data();
    const std::size_t size = image.getTotalSizeInBytes();
    for (std::size_t i = pixelBytes; i + pixelBytes <= size; i += pixelBytes)
        if (std::memcmp(data, data + i, pixelBytes) != 0)
            return true;
    return false;
}

osg::Vec4ub pixel(const osg::Image& image, unsigned x, unsigned y)
{
    const unsigned char* p = image.data(x, y);
    return osg::Vec4ub(p[0], p[1], p[2], 255);
}
} // namespace

// The demo seen from the trackball's home:
//
//   ┌──────────── wall ───────────┐     behind it, four boxes lower than the wall: culled
//   │  [front left]  [front right]│     in front of it, two boxes: drawn
//   └─────────────────────────────┘
TEST(GlfwApp, DemoCullsTheHiddenBoxesAndDrawsTheSamePixelsAsOsg)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (run under scripts/with-display.sh)";
    const std::filesystem::path dir = scratchDirectory("glfw", "demo");
    const AppRun culled = runGlfwApp("--frames 5 --size 320x240 --screenshot " + quoted(dir / "culled.png"));
    const AppRun plain = runGlfwApp("--frames 5 --size 320x240 --mode osg --screenshot " + quoted(dir / "osg.png"));
    ASSERT_EQ(culled.exitCode, 0) << culled.output;
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_NE(culled.output.find("osgvisglfw: 5 frames, mode frustum+octree"), std::string::npos) << culled.output;
    EXPECT_NE(plain.output.find("osgvisglfw: 5 frames, mode osg"), std::string::npos) << plain.output;
    EXPECT_NE(plain.output.find("osgVis: not in the graph"), std::string::npos) << plain.output;

    // The wall and the two boxes in front of it; the four boxes behind it are culled.
    const LastFrameFigures figures = lastFrameFigures(culled.output);
    EXPECT_EQ(figures.objects, 7) << culled.output;
    EXPECT_EQ(figures.visible, 3) << culled.output;

    const osg::ref_ptr<osg::Image> culledImage = osgDB::readRefImageFile((dir / "culled.png").string());
    const osg::ref_ptr<osg::Image> plainImage = osgDB::readRefImageFile((dir / "osg.png").string());
    ASSERT_TRUE(culledImage && plainImage);
    EXPECT_EQ(culledImage->s(), 320);
    EXPECT_EQ(culledImage->t(), 240);
    EXPECT_TRUE(hasTwoColours(*culledImage));
    ASSERT_EQ(culledImage->getTotalSizeInBytes(), plainImage->getTotalSizeInBytes());
    // Conservative culling changes no pixel.
    EXPECT_EQ(std::memcmp(culledImage->data(), plainImage->data(), culledImage->getTotalSizeInBytes()), 0);
}

TEST(GlfwApp, RendersAModelFileFromAFixedCamera)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (run under scripts/with-display.sh)";
    const std::filesystem::path dir = scratchDirectory("glfw", "model");
    // A red box at the origin, unlit so it draws exactly its colour, and two boxes off to the
    // sides, all three inside the view from (0,-10,0).
    osg::ref_ptr<osg::Group> model = new osg::Group;
    const osg::Vec4 red(1, 0, 0, 1), green(0, 1, 0, 1);
    const struct
    {
        osg::Vec3 lo, hi;
        osg::Vec4 colour;
    } boxes[] = {{{-1, -1, -1}, {1, 1, 1}, red}, {{-3, 0, -1}, {-2, 1, 0}, green}, {{2, 0, 0}, {3, 1, 1}, green}};
    for (const auto& box : boxes)
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(osgVis::gen::boxGeometry(box.lo, box.hi, box.colour, "box"));
        model->addChild(geode);
    }
    model->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    const std::filesystem::path modelPath = dir / "boxes.osgt";
    ASSERT_TRUE(osgDB::writeNodeFile(*model, modelPath.string()));

    const AppRun run = runGlfwApp(quoted(modelPath) + " --frames 3 --size 200x100 --eye 0,-10,0 --center 0,0,0" +
                                  " --screenshot " + quoted(dir / "shot.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const LastFrameFigures figures = lastFrameFigures(run.output);
    EXPECT_EQ(figures.objects, 3) << run.output;
    EXPECT_EQ(figures.visible, 3) << run.output;

    const osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile((dir / "shot.png").string());
    ASSERT_TRUE(image);
    EXPECT_EQ(image->s(), 200);
    EXPECT_EQ(image->t(), 100);
    EXPECT_EQ(pixel(*image, 100, 50), osg::Vec4ub(255, 0, 0, 255)) << "the red box fills the centre";
    EXPECT_NE(pixel(*image, 0, 0), osg::Vec4ub(255, 0, 0, 255)) << "the corner shows the background";
}

TEST(GlfwApp, UnwritableScreenshotFails)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (run under scripts/with-display.sh)";
    const std::filesystem::path dir = scratchDirectory("glfw", "unwritable");
    const std::string target = (dir / "no-such-folder" / "shot.png").string();
    const AppRun run = runGlfwApp("--frames 1 --size 64x64 --screenshot \"" + target + "\"");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("cannot write screenshot '" + target + "'"), std::string::npos) << run.output;
}

#ifdef OSGVIS_GLTF_SAMPLE
// A glTF file no one here wrote (a Khronos sample shipped by Debian's assimp-testmodels), read by
// osgVis's osgdb_gltf plugin from the build tree (the tests' OSG_LIBRARY_PATH).
TEST(GlfwApp, RendersAKhronosGlbSample)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (run under scripts/with-display.sh)";
    if (!std::filesystem::exists(OSGVIS_GLTF_SAMPLE))
        GTEST_SKIP() << OSGVIS_GLTF_SAMPLE << " is missing (Debian package assimp-testmodels)";
    const std::filesystem::path dir = scratchDirectory("glfw", "glb");
    const AppRun run = runGlfwApp(quoted(OSGVIS_GLTF_SAMPLE) + " --frames 2 --size 240x180 --screenshot " +
                                  quoted(dir / "engine.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const LastFrameFigures figures = lastFrameFigures(run.output);
    EXPECT_GT(figures.objects, 1) << run.output;
    EXPECT_GT(figures.visible, 0) << run.output;
    EXPECT_LE(figures.visible, figures.objects) << run.output;
    const osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile((dir / "engine.png").string());
    ASSERT_TRUE(image);
    EXPECT_TRUE(hasTwoColours(*image));
}
#endif
