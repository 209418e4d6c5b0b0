// SPDX-License-Identifier: MIT
// osgvisviewer --headless writes one PNG per walk view, and a conservative mode draws exactly the
// pixels of the `osg` baseline (same projection, fixed near/far, no small-feature culling).
#include "ViewerProcess.h"

#include <osgVis/core/scene/Walk.h>
#include <osgVis/gen/Generator.h>

#include <osg/Geode>
#include <osg/Group>
#include <osg/Image>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using osgVis::test::readText;
using osgVis::test::runViewer;
using osgVis::test::scratchDirectory;

namespace
{
constexpr unsigned Width = 160, Height = 128;

std::string frameName(const std::string& dir, const char* prefix, unsigned index)
{
    char name[32];
    std::snprintf(name, sizeof(name), "/%s-%04u.png", prefix, index);
    return dir + name;
}

std::size_t distinctColours(const osg::Image& image)
{
    std::set<std::uint32_t> colours;
    const unsigned bytesPerPixel = osg::Image::computePixelSizeInBits(image.getPixelFormat(), image.getDataType()) / 8;
    for (int row = 0; row < image.t(); ++row)
    {
        const unsigned char* pixel = image.data(0, row);
        for (int column = 0; column < image.s(); ++column, pixel += bytesPerPixel)
            colours.insert(std::uint32_t(pixel[0]) << 16 | std::uint32_t(pixel[1]) << 8 | pixel[2]);
    }
    return colours.size();
}

// Three views spread over the generator's walk of a small office, at the test's image size. The
// walk's last view faces the end wall from close by (one flat colour), so the views stop at 2/3.
std::string writeThreeViewWalk(const std::string& dir)
{
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::Office;
    options.triangles = 5000;
    options.seed = 1;
    osgVis::core::Walk walk = osgVis::gen::generate(options).walk;
    const std::size_t n = walk.keys.size();
    EXPECT_GE(n, 3u);
    walk.keys = {walk.keys[0], walk.keys[n / 3], walk.keys[2 * n / 3]};
    walk.width = Width;
    walk.height = Height;
    const std::string path = dir + "/three-views.walk";
    walk.save(path);
    return path;
}
} // namespace

TEST(ViewerHeadless, FrustumModeDrawsTheSamePixelsAsOsg)
{
    ASSERT_TRUE(osgVis::test::haveDisplay()) << "needs an X display: run the tests through scripts/test.sh";
    const std::string dir = scratchDirectory("headless-identical");
    const std::string walk = writeThreeViewWalk(dir);

    // frustum+cfrustum: the plugin lib/osgvis-modules/osgvis_module_cfrustum.so as a stage (visapi.h).
    const char* const culledModes[] = {"frustum", "frustum+cfrustum"};
    for (const char* mode : {"osg", culledModes[0], culledModes[1]})
    {
        const auto run = runViewer("--generate office --triangles 5000 --seed 1 --walk \"" + walk + "\" --mode " +
                                   mode + " --size 160x128 --headless \"" + dir + "/" + mode + "\"");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const std::string report = readText(dir + "/" + mode + "/report.json");
        EXPECT_NE(report.find("\"views\": 3"), std::string::npos) << report;
        EXPECT_NE(report.find(std::string("\"mode\": \"") + mode + "\""), std::string::npos) << report;
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + mode + "/report.txt"));
        EXPECT_TRUE(std::filesystem::exists(frameName(dir + "/" + mode, "map", 0)));
    }

    for (unsigned view = 0; view < 3; ++view)
        for (const char* mode : culledModes)
        {
            osg::ref_ptr<osg::Image> baseline = osgDB::readRefImageFile(frameName(dir + "/osg", "frame", view));
            osg::ref_ptr<osg::Image> culled = osgDB::readRefImageFile(frameName(dir + "/" + mode, "frame", view));
            ASSERT_TRUE(baseline && culled) << "view " << view;
            ASSERT_EQ(baseline->s(), int(Width));
            ASSERT_EQ(baseline->t(), int(Height));
            ASSERT_EQ(culled->s(), baseline->s());
            ASSERT_EQ(culled->t(), baseline->t());
            ASSERT_EQ(culled->getTotalSizeInBytes(), baseline->getTotalSizeInBytes());
            EXPECT_GT(distinctColours(*baseline), 1u) << "view " << view << " is one flat colour: nothing was drawn";
            EXPECT_EQ(std::memcmp(baseline->data(), culled->data(), baseline->getTotalSizeInBytes()), 0)
                << "view " << view << " differs between modes osg and " << mode;
        }
    EXPECT_FALSE(std::filesystem::exists(frameName(dir + "/osg", "frame", 3)));
}

// A plain OSG model file with a walk beside it: the viewer finds SCENE's stem + .walk by itself.
TEST(ViewerHeadless, ModelFileUsesTheWalkBesideIt)
{
    ASSERT_TRUE(osgVis::test::haveDisplay()) << "needs an X display: run the tests through scripts/test.sh";
    const std::string dir = scratchDirectory("model-file");

    //   y
    //   ^   [box][box][box][box]     four unit boxes on the x axis, seen from -y
    //   |
    //   +--> x        eye (1.5, -8, 0.5)
    osg::ref_ptr<osg::Geode> boxes = new osg::Geode;
    for (int i = 0; i < 4; ++i)
        boxes->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(float(i) * 1.5f, 0.0f, 0.5f), 1.0f)));
    ASSERT_TRUE(osgDB::writeNodeFile(*boxes, dir + "/boxes.osgt"));

    osgVis::core::Walk walk;
    walk.width = Width;
    walk.height = Height;
    walk.projection.zNear = 0.5;
    walk.projection.zFar = 50.0;
    for (int i = 0; i < 2; ++i)
    {
        osgVis::core::WalkKey key;
        key.time = i;
        key.eye = osgVis::core::Vec3(2.25 + i, -8.0, 0.5);
        key.center = osgVis::core::Vec3(2.25 + i, 0.0, 0.5);
        walk.keys.push_back(key);
    }
    walk.save(dir + "/boxes.walk");

    const auto run = runViewer("\"" + dir + "/boxes.osgt\" --mode frustum --headless \"" + dir + "/out\"");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (unsigned view = 0; view < 2; ++view)
    {
        osg::ref_ptr<osg::Image> frame = osgDB::readRefImageFile(frameName(dir + "/out", "frame", view));
        ASSERT_TRUE(frame) << "view " << view;
        EXPECT_EQ(frame->s(), int(Width)) << "the walk's own size applies without --size";
        EXPECT_GT(distinctColours(*frame), 1u);
    }
    EXPECT_FALSE(std::filesystem::exists(frameName(dir + "/out", "frame", 2)));
    const std::string report = readText(dir + "/out/report.json");
    EXPECT_NE(report.find("boxes.walk"), std::string::npos) << report;
    EXPECT_NE(report.find("\"objects\": 4"), std::string::npos) << report;
}
