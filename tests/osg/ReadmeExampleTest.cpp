// SPDX-License-Identifier: MIT
// The README's example as written (issue 54, item 4): a model read by osgDB under
// VisibilityGroup("frustum+octree"), handed to an osgViewer::Viewer with nothing else set (its default
// camera: near and far computed by OSG, small-feature culling on, its default projection and threading),
// draws every frame exactly what the same model under a plain osg::Group draws. On a real level nobody
// here made (OpenArena's oa_dm4 as OSG's bsp plugin reads it, raw and as the apps repair it, walked
// from its spawn points with the gaze turning) and on a generated city along its walk. Needs a display.
#include "TestScenes.h"

#include <osgVis/ModelRepair>
#include <osgVis/Q3Solids>
#include <osgVis/VisibilityGroup>
#include <osgVis/gen/Generator.h>

#include <osgDB/ReadFile>
#include <osgViewer/Viewer>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using osgVis::test::CaptureImage;
using osgVis::test::createTestContext;
using osgVis::test::litPixels;
using osgVis::test::samePixels;

namespace
{
constexpr unsigned Width = 256, Height = 192;
const char* const Pk3 = "/usr/share/games/openarena/baseoa/pak1-maps.pk3";

struct Eye
{
    osg::Vec3d position, centre, up;
};

// What the README's main() does, with the offscreen context the test needs and the eye set per frame
// instead of a manipulator: every frame's pixels.
// `culledFrames` counts the frames in which the group let fewer objects through than it holds.
std::vector<osg::ref_ptr<osg::Image>> drawAsTheReadmeDoes(osg::Node* model, bool culled, const std::vector<Eye>& eyes,
                                                          unsigned* culledFrames = nullptr)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = culled ? new osgVis::VisibilityGroup("frustum+octree") : nullptr;
    osg::ref_ptr<osg::Group> root = culled ? group.get() : new osg::Group;
    root->addChild(model);
    osgViewer::Viewer viewer;
    osg::Camera* camera = viewer.getCamera();
    osg::ref_ptr<osg::GraphicsContext> gc = createTestContext(Width, Height);
    if (!gc)
        return {};
    camera->setGraphicsContext(gc);
    camera->setViewport(0, 0, int(Width), int(Height));
    const GLenum buffer = gc->getTraits()->doubleBuffer ? GL_BACK : GL_FRONT;
    camera->setDrawBuffer(buffer);
    camera->setReadBuffer(buffer);
    camera->setProjectionMatrixAsPerspective(30.0, double(Width) / Height, 1.0, 10000.0); // osgViewer's own
    osg::ref_ptr<CaptureImage> capture = new CaptureImage(Width, Height);
    capture->keepFrames = true;
    camera->setFinalDrawCallback(capture);
    viewer.setSceneData(root);
    viewer.realize();
    for (const Eye& eye : eyes)
    {
        camera->setViewMatrixAsLookAt(eye.position, eye.centre, eye.up);
        viewer.frame();
        if (group && culledFrames)
        {
            const osgVis::CullStatistics figures = group->getLastStatistics(); // this frame's: culled in frame()
            *culledFrames += figures.visible < figures.objects;
        }
    }
    std::vector<osg::ref_ptr<osg::Image>> frames = capture->waitForFrames(unsigned(eyes.size()));
    viewer.stopThreading();
    return frames;
}

unsigned differingPixels(const osg::Image& a, const osg::Image& b)
{
    unsigned count = 0;
    const auto* pa = reinterpret_cast<const std::uint32_t*>(a.data());
    const auto* pb = reinterpret_cast<const std::uint32_t*>(b.data());
    for (unsigned i = 0; i < Width * Height; ++i)
        count += pa[i] != pb[i];
    return count;
}

void expectSamePicture(osg::Node* model, const std::vector<Eye>& eyes)
{
    const auto plain = drawAsTheReadmeDoes(model, false, eyes);
    if (plain.empty())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    unsigned culledFrames = 0;
    const auto culled = drawAsTheReadmeDoes(model, true, eyes, &culledFrames);
    EXPECT_GT(culledFrames, 0u) << "the group culled nothing: the comparison proves nothing";
    ASSERT_EQ(plain.size(), eyes.size());
    ASSERT_EQ(culled.size(), eyes.size());
    unsigned lit = 0;
    for (std::size_t frame = 0; frame < eyes.size(); ++frame)
    {
        lit += litPixels(*plain[frame]) > Width * Height / 20;
        EXPECT_TRUE(samePixels(*plain[frame], *culled[frame]))
            << "frame " << frame << ": " << differingPixels(*plain[frame], *culled[frame]) << " pixels differ";
    }
    EXPECT_GT(lit, eyes.size() / 2) << "most frames should show the model";
}

// Each spawn point of the level, the gaze turning a full circle over `perEye` frames.
std::vector<Eye> turningAt(const std::vector<osgVis::core::Vec3>& points, unsigned perEye)
{
    std::vector<Eye> eyes;
    for (const osgVis::core::Vec3& p : points)
        for (unsigned i = 0; i < perEye; ++i)
        {
            const double angle = 2.0 * M_PI * i / perEye;
            const osg::Vec3d eye(p.x, p.y, p.z);
            eyes.push_back({eye, eye + osg::Vec3d(std::cos(angle), std::sin(angle), -0.1), osg::Z_AXIS});
        }
    return eyes;
}

std::string extractedLevel(const std::string& map)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "osgvis-readme-example";
    std::filesystem::create_directories(dir);
    const std::string command =
        "unzip -o -q '" + std::string(Pk3) + "' 'maps/" + map + ".bsp' -d '" + dir.string() + "'";
    if (std::system(command.c_str()) != 0)
        return {};
    return (dir / "maps" / (map + ".bsp")).string();
}
} // namespace

TEST(ReadmeExample, DrawsARealLevelAsOsgDoes)
{
    if (!std::filesystem::exists(Pk3))
        GTEST_SKIP() << Pk3 << " is not installed (Debian package openarena-081-maps)";
    const std::string level = extractedLevel("oa_dm4");
    ASSERT_FALSE(level.empty()) << "cannot extract oa_dm4 from " << Pk3;
    std::vector<osgVis::core::Vec3> spawns = osgVis::readQ3Solids(level).eyePoints;
    ASSERT_GE(spawns.size(), 3u);
    spawns.resize(3);
    const std::vector<Eye> eyes = turningAt(spawns, 10);

    osg::ref_ptr<osg::Node> raw = osgDB::readRefNodeFile(level);
    ASSERT_TRUE(raw) << "OSG's bsp plugin cannot read " << level;
    {
        SCOPED_TRACE("as OSG's bsp plugin reads it");
        expectSamePicture(raw.get(), eyes);
    }
    osg::ref_ptr<osg::Node> repaired = osgDB::readRefNodeFile(level);
    osgVis::repairLoadedModel(*repaired, level);
    {
        SCOPED_TRACE("as the apps repair it");
        expectSamePicture(repaired.get(), eyes);
    }
}

TEST(ReadmeExample, DrawsAGeneratedCityAsOsgDoes)
{
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::City;
    options.triangles = 40000;
    const osgVis::gen::GeneratedScene city = osgVis::gen::generate(options);
    std::vector<Eye> eyes;
    const auto& keys = city.walk.keys;
    ASSERT_FALSE(keys.empty());
    for (unsigned i = 0; i < 30; ++i)
    {
        const auto& key = keys[i * keys.size() / 30];
        eyes.push_back({osg::Vec3d(key.eye.x, key.eye.y, key.eye.z), osg::Vec3d(key.center.x, key.center.y, key.center.z),
                        osg::Vec3d(key.up.x, key.up.y, key.up.z)});
    }
    expectSamePicture(city.root.get(), eyes);
}
