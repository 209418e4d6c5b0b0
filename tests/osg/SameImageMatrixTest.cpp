// SPDX-License-Identifier: MIT
// The "same image" matrix (issue 54, item 3): for every everyday OSG application pattern of
// SameImagePatterns.cpp, animated over 30 frames, the pixels of every frame must be those plain OSG
// draws, when the scene's content stands under an osgVis::VisibilityGroup and when a plain graph is
// culled by osgVis::CullVisitor, in every conservative mode (each registered module that is not
// approximate, alone, and frustum+octree). One viewer per (pattern, door, mode) run, single-threaded,
// 128 × 96. The plain-OSG reference is rendered twice and must come out the same both times, so a
// difference can only mean that the kit changed the picture. The base pattern also checks that the
// comparison is not vacuous: the occlusion modes report that they culled boxes in view.
//
// Needs a display (Xvfb). OSGVIS_SAME_IMAGE_MODES=frustum,octree limits the modes (to look into one);
// OSGVIS_SAME_IMAGE_DUMP=folder writes the first differing frame of each failing run (reference, kit,
// and the pixels that differ in white) and a few reference frames of each pattern as PPM files.
#include "SameImagePatterns.h"
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/GraphicsContext>
#include <osg/Image>
#include <osgUtil/SceneView>
#include <osgViewer/Renderer>
#include <osgViewer/Viewer>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace si = osgVis::test::sameimage;
using osgVis::test::CaptureImage;

enum class Door
{
    Osg,             // the content under a plain osg::Group, OSG's own cull visitor
    VisibilityGroup, // the content under an osgVis::VisibilityGroup(mode)
    CullVisitor      // the plain graph, culled by osgVis::CullVisitor::installOn(viewer, mode)
};

const char* nameOf(Door door)
{
    switch (door)
    {
    case Door::Osg: return "osg";
    case Door::VisibilityGroup: return "VisibilityGroup";
    case Door::CullVisitor: return "CullVisitor";
    }
    return "?";
}

// Every registered mode that is not approximate, alone, and frustum+octree ("osg" is the reference).
std::vector<std::string> conservativeModes()
{
    std::vector<std::string> modes;
    if (const char* only = std::getenv("OSGVIS_SAME_IMAGE_MODES"); only && *only)
    {
        std::stringstream list(only);
        for (std::string mode; std::getline(list, mode, ',');)
            if (!mode.empty())
                modes.push_back(mode);
        return modes;
    }
    for (const std::string& name : osgVis::core::moduleNames())
    {
        if (name == "osg" || osgVis::core::createModule(name)->approximate())
            continue;
        modes.push_back(name);
    }
    modes.push_back("frustum+octree");
    return modes;
}

// Modes that cull by occlusion: in the base scene each must cull more than what lies out of view.
bool occludes(const std::string& mode)
{
    for (const char* prefix : {"octree", "mask", "cdt", "frustum+octree"})
        if (mode.rfind(prefix, 0) == 0)
            return true;
    return false;
}

// An offscreen context as createTestContext makes it, with stencil bits and multisampling.
osg::ref_ptr<osg::GraphicsContext> createContext(unsigned stencil, unsigned samples)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->width = int(si::Width);
    traits->height = int(si::Height);
    traits->red = traits->green = traits->blue = traits->alpha = 8;
    traits->depth = 24;
    traits->stencil = stencil;
    traits->sampleBuffers = samples > 0 ? 1 : 0;
    traits->samples = samples;
    traits->windowDecoration = false;
    traits->doubleBuffer = true;
    traits->pbuffer = true;
    osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits);
    if (!gc)
    {
        traits->pbuffer = false;
        gc = osg::GraphicsContext::createGraphicsContext(traits);
    }
    return gc;
}

osg::Vec4i wholeFrame()
{
    return osg::Vec4i(0, 0, int(si::Width), int(si::Height));
}

// Pixels inside `region` whose RGBA bytes differ (every pixel where the sizes differ).
unsigned differingPixels(const osg::Image& a, const osg::Image& b, const osg::Vec4i& region)
{
    if (a.s() != b.s() || a.t() != b.t() || a.getPixelSizeInBits() != b.getPixelSizeInBits())
        return unsigned(std::max(a.s() * a.t(), b.s() * b.t()));
    unsigned differing = 0;
    const unsigned bytes = a.getPixelSizeInBits() / 8;
    for (int y = std::max(0, region.y()); y < std::min(a.t(), region.y() + region.w()); ++y)
        for (int x = std::max(0, region.x()); x < std::min(a.s(), region.x() + region.z()); ++x)
            differing += !std::equal(a.data(x, y), a.data(x, y) + bytes, b.data(x, y));
    return differing;
}

// One run of a pattern through one door in one mode: the frames drawn and the kit's figures.
struct RunFrames
{
    bool drawn = false; // false without a display
    std::string error;  // the kit refused the mode, or the run could not be set up
    std::vector<osg::ref_ptr<osg::Image>> frames;
    std::vector<osg::Vec4i> regions;                // the part of each frame to compare
    std::vector<osgVis::CullStatistics> figures;    // the kit's, after each frame
};

osgVis::CullStatistics cullVisitorFigures(osgViewer::Viewer& viewer)
{
    if (auto* renderer = dynamic_cast<osgViewer::Renderer*>(viewer.getCamera()->getRenderer()))
        for (unsigned i = 0; i < 2; ++i)
            if (osgUtil::SceneView* sceneView = renderer->getSceneView(i))
                if (auto* cv = dynamic_cast<osgVis::CullVisitor*>(sceneView->getCullVisitor()))
                    return cv->getLastStatistics();
    return {};
}

RunFrames render(const si::Pattern& pattern, Door door, const std::string& mode)
{
    RunFrames run;
    try
    {
        si::Build build;
        osg::ref_ptr<osgVis::VisibilityGroup> group;
        if (door == Door::VisibilityGroup)
            build.group = group = new osgVis::VisibilityGroup(mode);
        else
            build.group = new osg::Group;
        build.makeInnerGroup = [door, mode]() -> osg::ref_ptr<osg::Group> {
            if (door == Door::Osg)
                return new osg::Group;
            return new osgVis::VisibilityGroup(mode);
        };
        const si::Scene scene = pattern.build(build);

        osgViewer::Viewer viewer;
        viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
        osg::Camera* camera = viewer.getCamera();
        osg::ref_ptr<CaptureImage> capture = osgVis::test::setUpCapturingCamera(*camera, si::Width, si::Height);
        if (!capture)
            return run;
        if (scene.stencilBits || scene.samples)
        {
            osg::ref_ptr<osg::GraphicsContext> gc = createContext(scene.stencilBits, scene.samples);
            if (!gc)
            {
                run.error = "no context with " + std::to_string(scene.stencilBits) + " stencil bits and " +
                            std::to_string(scene.samples) + " samples";
                return run;
            }
            camera->setGraphicsContext(gc);
            const GLenum buffer = gc->getTraits()->doubleBuffer ? GL_BACK : GL_FRONT;
            camera->setDrawBuffer(buffer);
            camera->setReadBuffer(buffer);
        }
        capture->keepFrames = true;
        si::standardProjection(*camera);
        si::standardView(viewer, 0);
        if (scene.setUpViewer)
            scene.setUpViewer(viewer);
        viewer.setSceneData(scene.root.get());
        if (door == Door::CullVisitor)
            osgVis::CullVisitor::installOn(viewer, mode);
        viewer.realize();
        if (!viewer.isRealized())
        {
            run.error = "the viewer did not realize";
            return run;
        }
        for (unsigned f = 0; f < si::FrameCount; ++f)
        {
            scene.animate(f);
            scene.view(viewer, f);
            viewer.frame(f / 30.0); // simulation time, the same in every run
            run.regions.push_back(scene.comparedRegion ? scene.comparedRegion(f) : wholeFrame());
            if (door == Door::VisibilityGroup)
                run.figures.push_back(group->getLastStatistics());
            else if (door == Door::CullVisitor)
                run.figures.push_back(cullVisitorFigures(viewer));
        }
        run.frames = capture->waitForFrames(si::FrameCount, std::chrono::seconds(10));
        run.drawn = true;
    }
    catch (const std::exception& e)
    {
        run.error = e.what();
    }
    return run;
}

// P6 file of an RGBA image, top row first.
void writePpm(const osg::Image& image, const std::string& path)
{
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << image.s() << " " << image.t() << "\n255\n";
    for (int y = image.t() - 1; y >= 0; --y)
        for (int x = 0; x < image.s(); ++x)
            out.write(reinterpret_cast<const char*>(image.data(x, y)), 3);
}

std::string dumpFolder()
{
    const char* folder = std::getenv("OSGVIS_SAME_IMAGE_DUMP");
    return folder && *folder ? std::string(folder) + "/" : std::string();
}

void dumpDifference(const std::string& stem, const osg::Image& reference, const osg::Image& kit)
{
    const std::string folder = dumpFolder();
    if (folder.empty())
        return;
    writePpm(reference, folder + stem + "_osg.ppm");
    writePpm(kit, folder + stem + "_kit.ppm");
    osg::ref_ptr<osg::Image> difference = new osg::Image(reference, osg::CopyOp::DEEP_COPY_ALL);
    for (int y = 0; y < reference.t(); ++y)
        for (int x = 0; x < reference.s(); ++x)
        {
            const bool same = std::equal(reference.data(x, y), reference.data(x, y) + 4, kit.data(x, y));
            std::fill(difference->data(x, y), difference->data(x, y) + 3, same ? 0 : 255);
        }
    writePpm(*difference, folder + stem + "_diff.ppm");
}

std::string patternName(const ::testing::TestParamInfo<std::size_t>& info)
{
    return si::patterns()[info.param].name;
}
} // namespace

class SameImage : public ::testing::TestWithParam<std::size_t>
{
};

TEST_P(SameImage, EveryModeDrawsWhatOsgDraws)
{
    const si::Pattern& pattern = si::patterns()[GetParam()];
    const auto started = std::chrono::steady_clock::now();
    SCOPED_TRACE(pattern.name + ": " + pattern.what);

    const RunFrames reference = render(pattern, Door::Osg, "");
    if (!reference.drawn && reference.error.empty())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_TRUE(reference.error.empty()) << reference.error;
    ASSERT_EQ(reference.frames.size(), si::FrameCount) << "the reference lost frames";

    // The reference must not depend on the run: a second one draws the very same frames.
    const RunFrames again = render(pattern, Door::Osg, "");
    ASSERT_EQ(again.frames.size(), si::FrameCount);
    for (unsigned f = 0; f < si::FrameCount; ++f)
        ASSERT_EQ(differingPixels(*reference.frames[f], *again.frames[f], reference.regions[f]), 0u)
            << "plain OSG drew frame " << f << " differently in two runs: the pattern is not deterministic";

    unsigned litFrames = 0;
    for (unsigned f = 0; f < si::FrameCount; ++f)
        litFrames += osgVis::test::litPixels(*reference.frames[f]) > si::Width * si::Height / 50;
    EXPECT_EQ(litFrames, si::FrameCount) << "a frame of the reference is (nearly) empty";
    if (const std::string folder = dumpFolder(); !folder.empty())
        for (unsigned f : {0u, 10u, 20u, si::FrameCount - 1})
            writePpm(*reference.frames[f], folder + pattern.name + "_reference_f" + std::to_string(f) + ".ppm");

    const std::vector<std::string> modes = conservativeModes();
    ASSERT_FALSE(modes.empty());
    unsigned failedRuns = 0, runs = 0;
    for (Door door : {Door::VisibilityGroup, Door::CullVisitor})
        for (const std::string& mode : modes)
        {
            ++runs;
            const RunFrames run = render(pattern, door, mode);
            const std::string where = pattern.name + " / " + nameOf(door) + " / " + mode;
            if (!run.error.empty() || run.frames.size() != si::FrameCount)
            {
                ++failedRuns;
                ADD_FAILURE() << where << ": the run failed: "
                              << (run.error.empty() ? std::to_string(run.frames.size()) + " frames drawn" : run.error);
                std::cout << "[same-image] FAIL " << pattern.name << " " << nameOf(door) << " " << mode
                          << " error=\"" << run.error << "\"" << std::endl;
                continue;
            }
            std::ostringstream frames;
            unsigned differingFrames = 0, mostPixels = 0, first = si::FrameCount;
            for (unsigned f = 0; f < si::FrameCount; ++f)
            {
                const osg::Vec4i region = reference.regions[f];
                const bool same = region == wholeFrame() ? osgVis::test::samePixels(*reference.frames[f], *run.frames[f])
                                                         : differingPixels(*reference.frames[f], *run.frames[f], region) == 0;
                if (same)
                    continue;
                const unsigned differing = differingPixels(*reference.frames[f], *run.frames[f], region);
                frames << " f" << f << ":" << differing;
                if (differingFrames++ == 0)
                {
                    first = f;
                    dumpDifference(pattern.name + "_" + nameOf(door) + "_" + mode + "_f" + std::to_string(f),
                                   *reference.frames[f], *run.frames[f]);
                }
                mostPixels = std::max(mostPixels, differing);
            }
            if (differingFrames > 0)
            {
                ++failedRuns;
                ADD_FAILURE() << where << ": " << differingFrames << " of " << si::FrameCount
                              << " frames differ from plain OSG (frame:pixels)" << frames.str();
                std::cout << "[same-image] FAIL " << pattern.name << " " << nameOf(door) << " " << mode
                          << " frames=" << differingFrames << " first=" << first << " max=" << mostPixels << " |"
                          << frames.str() << std::endl;
            }

            // What the kit did: how much it culled, and in how many frames it left the view to OSG.
            unsigned fewest = ~0u, most = 0, objects = 0, leftToOsg = 0;
            std::string why;
            for (const osgVis::CullStatistics& figures : run.figures)
            {
                fewest = std::min(fewest, figures.visible);
                most = std::max(most, figures.visible);
                objects = std::max(objects, figures.objects);
                if (figures.leftToOsg)
                {
                    ++leftToOsg;
                    why = figures.leftToOsg;
                }
            }
            std::cout << "[same-image] figures " << where << ": visible " << fewest << ".." << most << " of " << objects
                      << ", left to OSG in " << leftToOsg << " frames" << (why.empty() ? "" : " (" + why + ")")
                      << std::endl;

            if (pattern.checksCulling)
            {
                for (const osgVis::CullStatistics& figures : run.figures)
                    EXPECT_EQ(figures.objects, si::BaseObjects) << where;
                // Not vacuous: the frustum leaves out what is out of view, occlusion modes some of what
                // the wall hides too (in every frame).
                if (mode == "frustum")
                {
                    EXPECT_LE(most, si::BaseObjects - si::BaseOutOfView) << where << ": nothing out of view culled";
                }
                if (occludes(mode))
                {
                    EXPECT_LT(most, si::BaseObjects - si::BaseOutOfView)
                        << where << ": no box hidden by the wall culled; the comparison proves nothing";
                }
            }
        }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::cout << "[same-image] " << pattern.name << ": " << runs << " runs of " << si::FrameCount << " frames ("
              << modes.size() << " modes, 2 doors), " << failedRuns << " failed, " << seconds << " s" << std::endl;
}

INSTANTIATE_TEST_SUITE_P(EveryPattern, SameImage, ::testing::Range<std::size_t>(0, si::patterns().size()),
                         patternName);

TEST(SameImagePatterns, AtLeastFortyWithDistinctNames)
{
    const auto& patterns = si::patterns();
    EXPECT_GE(patterns.size(), 40u);
    std::vector<std::string> names;
    for (const si::Pattern& pattern : patterns)
    {
        names.push_back(pattern.name);
        EXPECT_FALSE(pattern.what.empty()) << pattern.name;
        EXPECT_TRUE(std::all_of(pattern.name.begin(), pattern.name.end(),
                                [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }))
            << pattern.name;
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "two patterns share a name";
}
