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
} // namespace

int renderHeadless(const apps::LoadedScene& scene, const ViewerOptions& options)
{
    if (!prepareOutputDirectory(options.headlessDir))
        return 1;
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
        std::cerr << "osgvisviewer: --headless renders into an offscreen OpenGL buffer and needs an X display, but "
                     "DISPLAY is not set.\n"
                     "  Run it under a virtual display, e.g.:  xvfb-run -a -s \"-screen 0 1280x1024x24\" osgvisviewer "
                     "... --headless "
                  << options.headlessDir << "\n";
        return 3;
    }

    const core::Walk& walk = scene.walk;
    const unsigned width = walk.width, height = walk.height;
    osg::ref_ptr<osg::GraphicsContext> context;
    try
    {
        context = oracle::createOffscreenContext(width, height, true);
    }
    catch (const std::runtime_error& error)
    {
        std::cerr << "osgvisviewer: cannot create a " << width << "x" << height
                  << " offscreen OpenGL buffer (pbuffer) on DISPLAY=" << display << ": " << error.what() << "\n";
        return 1;
    }

    CullingModes modes(scene.model.get(), options.mode, options.async);
    DebugMap map(*scene.objects, modes);
    osg::ref_ptr<osg::Group> root = map.sceneWithMap(modes);

    osgViewer::Viewer viewer;
    // note: one thread keeps capture and statistics in step with the frame just drawn.
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer.setSceneData(root.get());
    osg::Camera* camera = viewer.getCamera();
    camera->setGraphicsContext(context.get());
    camera->setViewport(0, 0, int(width), int(height));
    camera->setDrawBuffer(GL_BACK);
    camera->setReadBuffer(GL_BACK);
    apps::applyWalkProjection(*camera, walk.projection, walk.aspect());
    osg::ref_ptr<apps::FrameCapture> capture = new apps::FrameCapture;
    camera->setFinalDrawCallback(capture.get());
    map.setObservedCamera(camera);
    map.setViewport(0, 0, int(width), int(height));

    osg::Stats* stats = camera->getStats();
    stats->collectStats("scene", true);
    stats->collectStats("rendering", true);
    stats->collectStats("osgVis", true);

    viewer.realize();
    if (!viewer.isRealized())
    {
        std::cerr << "osgvisviewer: the offscreen OpenGL buffer could not be realized on DISPLAY=" << display << "\n";
        return 1;
    }

    RunReport report;
    report.scene = scene.name;
    report.walk = scene.walkSource;
    report.mode = options.mode;
    report.width = width;
    report.height = height;
    report.objects = scene.objects->scene.objects.size();
    report.sceneTriangles = scene.objects->scene.totalTriangles();

    const std::size_t views = walk.keys.size();
    const std::size_t progressStep = std::max<std::size_t>(1, (views + 9) / 10);
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < views; ++i)
    {
        const core::WalkKey& key = walk.keys[i];
        camera->setViewMatrix(apps::walkViewMatrix(key));
        osg::ref_ptr<osg::Image> frame = drawFrame(viewer, *capture, key.time);
        report.frames.push_back(readFrameFigures(*stats, viewer.getFrameStamp()->getFrameNumber()));
        if (!writePng(frame.get(), numberedPng(options.headlessDir, "frame", i)))
            return 1;

        if (i % MapInterval == 0)
        {
            // The map covers the whole frame for its own image; the frame images never contain it.
            map.setEnabled(true);
            osg::ref_ptr<osg::Image> plan = drawFrame(viewer, *capture, key.time);
            map.setEnabled(false);
            if (!writePng(plan.get(), numberedPng(options.headlessDir, "map", i)))
                return 1;
        }
        if (views >= 20 && ((i + 1) % progressStep == 0 || i + 1 == views))
            std::cerr << "osgvisviewer: " << (i + 1) << "/" << views << " views (" << (100 * (i + 1) / views) << "%)\n";
    }
    report.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    try
    {
        report.write(options.headlessDir);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisviewer: " << e.what() << "\n";
        return 1;
    }
    std::cout << "osgvisviewer: " << views << " views of '" << scene.name << "' in mode " << options.mode
              << " written to " << options.headlessDir << "\n";
    return 0;
}
} // namespace osgVis::viewer
