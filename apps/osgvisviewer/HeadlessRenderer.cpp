// SPDX-License-Identifier: MIT
#include "HeadlessRenderer.h"

#include <CameraSetup.h>
#include "CullingModes.h"
#include "DebugMap.h"
#include <FrameCapture.h>
#include "RunReport.h"

#include <osgVis/oracle/OffscreenContext.h>

#include <osgDB/WriteFile>
#include <osgViewer/Viewer>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace osgVis::viewer
{
namespace
{
std::string numberedPng(const std::string& directory, const char* prefix, std::size_t index)
{
    char name[64];
    std::snprintf(name, sizeof(name), "%s-%04zu.png", prefix, index);
    return (std::filesystem::path(directory) / name).string();
}

// Creates the folder if missing and proves it takes files, so a run never ends with nothing written.
bool prepareOutputDirectory(const std::string& directory)
{
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error && !std::filesystem::is_directory(directory))
    {
        std::cerr << "osgvisviewer: cannot create output folder '" << directory << "': " << error.message() << "\n";
        return false;
    }
    const std::filesystem::path probe = std::filesystem::path(directory) / ".osgvisviewer-write-test";
    bool writable = bool(std::ofstream(probe));
    std::filesystem::remove(probe, error);
    if (!writable)
        std::cerr << "osgvisviewer: cannot write into output folder '" << directory << "'\n";
    return writable;
}

// Draws one frame and returns the pixels the camera's final draw callback read back.
osg::ref_ptr<osg::Image> drawFrame(osgViewer::Viewer& viewer, apps::FrameCapture& capture, double time)
{
    capture.arm();
    viewer.frame(time);
    return capture.take();
}

bool writePng(const osg::Image* image, const std::string& path)
{
    if (image && osgDB::writeImageFile(*image, path))
        return true;
    std::cerr << "osgvisviewer: cannot write '" << path << "'" << (image ? "" : " (no pixels were read back)") << "\n";
    return false;
}

// The X display the offscreen buffer goes on; null, after saying how to get one, where DISPLAY is not set.
const char* displayOrHint(const std::string& headlessDir)
{
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
        std::cerr << "osgvisviewer: --headless renders into an offscreen OpenGL buffer and needs an X display, but "
                     "DISPLAY is not set.\n"
                     "  Run it under a virtual display, e.g.:  xvfb-run -a -s \"-screen 0 1280x1024x24\" osgvisviewer "
                     "... --headless "
                  << headlessDir << "\n";
        return nullptr;
    }
    return display;
}

// Null, after saying why, where the pbuffer cannot be created.
osg::ref_ptr<osg::GraphicsContext> createContext(unsigned width, unsigned height, const char* display)
{
    try
    {
        return oracle::createOffscreenContext(width, height, true);
    }
    catch (const std::runtime_error& error)
    {
        std::cerr << "osgvisviewer: cannot create a " << width << "x" << height
                  << " offscreen OpenGL buffer (pbuffer) on DISPLAY=" << display << ": " << error.what() << "\n";
        return nullptr;
    }
}

// Points the viewer's camera at the offscreen buffer with the walk's projection, reads each frame back
// through `capture` and collects the statistics the report needs; returns them.
osg::Stats& setUpViewer(osgViewer::Viewer& viewer, osg::Group* root, osg::GraphicsContext* context,
                        const core::Walk& walk, apps::FrameCapture* capture, DebugMap& map)
{
    const unsigned width = walk.width, height = walk.height;
    // note: one thread keeps capture and statistics in step with the frame just drawn.
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer.setSceneData(root);
    osg::Camera* camera = viewer.getCamera();
    camera->setGraphicsContext(context);
    camera->setViewport(0, 0, int(width), int(height));
    camera->setDrawBuffer(GL_BACK);
    camera->setReadBuffer(GL_BACK);
    apps::applyWalkProjection(*camera, walk.projection, walk.aspect());
    camera->setFinalDrawCallback(capture);
    map.setObservedCamera(camera);
    map.setViewport(0, 0, int(width), int(height));

    osg::Stats* stats = camera->getStats();
    stats->collectStats("scene", true);
    stats->collectStats("rendering", true);
    stats->collectStats("osgVis", true);
    return *stats;
}

// What drawing a view uses: the viewer, its camera's read-back and statistics, and the map.
struct Drawing
{
    osgViewer::Viewer& viewer;
    apps::FrameCapture& capture;
    osg::Stats& stats;
    DebugMap& map;
};

RunReport emptyReport(const apps::LoadedScene& scene, const ViewerOptions& options)
{
    RunReport report;
    report.scene = scene.name;
    report.walk = scene.walkSource;
    report.mode = options.mode;
    report.width = scene.walk.width;
    report.height = scene.walk.height;
    report.objects = scene.objects->scene.objects.size();
    report.sceneTriangles = scene.objects->scene.totalTriangles();
    return report;
}

// Draws and writes view i of the walk and, every MapInterval views, its map; false where an image
// cannot be written.
bool renderView(const Drawing& drawing, const core::Walk& walk, std::size_t i, const std::string& headlessDir,
                RunReport& report)
{
    const core::WalkKey& key = walk.keys[i];
    drawing.viewer.getCamera()->setViewMatrix(apps::walkViewMatrix(key));
    osg::ref_ptr<osg::Image> frame = drawFrame(drawing.viewer, drawing.capture, key.time);
    report.frames.push_back(readFrameFigures(drawing.stats, drawing.viewer.getFrameStamp()->getFrameNumber()));
    if (!writePng(frame.get(), numberedPng(headlessDir, "frame", i)))
        return false;

    if (i % MapInterval == 0)
    {
        // The map covers the whole frame for its own image; the frame images never contain it.
        drawing.map.setEnabled(true);
        osg::ref_ptr<osg::Image> plan = drawFrame(drawing.viewer, drawing.capture, key.time);
        drawing.map.setEnabled(false);
        if (!writePng(plan.get(), numberedPng(headlessDir, "map", i)))
            return false;
    }
    return true;
}

// Every view of the walk, with a progress line every tenth of a long walk; false where an image
// cannot be written.
bool renderWalk(const Drawing& drawing, const core::Walk& walk, const std::string& headlessDir, RunReport& report)
{
    const std::size_t views = walk.keys.size();
    const std::size_t progressStep = std::max<std::size_t>(1, (views + 9) / 10);
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < views; ++i)
    {
        if (!renderView(drawing, walk, i, headlessDir, report))
            return false;
        if (views >= 20 && ((i + 1) % progressStep == 0 || i + 1 == views))
            std::cerr << "osgvisviewer: " << (i + 1) << "/" << views << " views (" << (100 * (i + 1) / views) << "%)\n";
    }
    report.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}
} // namespace

int renderHeadless(const apps::LoadedScene& scene, const ViewerOptions& options)
{
    if (!prepareOutputDirectory(options.headlessDir))
        return 1;
    const char* display = displayOrHint(options.headlessDir);
    if (!display)
        return 3;

    const core::Walk& walk = scene.walk;
    osg::ref_ptr<osg::GraphicsContext> context = createContext(walk.width, walk.height, display);
    if (!context)
        return 1;

    CullingModes modes(scene.model.get(), options.mode, options.async);
    DebugMap map(*scene.objects, modes);
    osg::ref_ptr<osg::Group> root = map.sceneWithMap(modes);

    osgViewer::Viewer viewer;
    osg::ref_ptr<apps::FrameCapture> capture = new apps::FrameCapture;
    osg::Stats& stats = setUpViewer(viewer, root.get(), context.get(), walk, capture.get(), map);
    viewer.realize();
    if (!viewer.isRealized())
    {
        std::cerr << "osgvisviewer: the offscreen OpenGL buffer could not be realized on DISPLAY=" << display << "\n";
        return 1;
    }

    RunReport report = emptyReport(scene, options);
    if (!renderWalk(Drawing{viewer, *capture, stats, map}, walk, options.headlessDir, report))
        return 1;
    try
    {
        report.write(options.headlessDir);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisviewer: " << e.what() << "\n";
        return 1;
    }
    std::cout << "osgvisviewer: " << walk.keys.size() << " views of '" << scene.name << "' in mode " << options.mode
              << " written to " << options.headlessDir << "\n";
    return 0;
}
} // namespace osgVis::viewer
