// SPDX-License-Identifier: MIT
// osgvisglfw: how an application that owns its window and GL context hosts an OSG scene culled by
// osgVis. The shape, for copying:
//
//   1. GLFW creates the window and its GL context and makes the context current on this thread.
//   2. osgViewer::Viewer::setUpViewerAsEmbeddedInWindow gives the viewer a GraphicsWindowEmbedded:
//      a stand-in window that draws into whatever context is current and never creates, makes
//      current or swaps one itself.
//   3. GlfwEventAdapter forwards GLFW's input to that window's event queue, so OSG's manipulators
//      and event handlers work as in an osgViewer window.
//   4. The application's loop: glfwPollEvents → viewer.frame() (event, update, cull and draw
//      traversals) → glfwSwapBuffers.
//
// osgVis is one node in the graph: the scene goes under an osgVis::VisibilityGroup (GlfwAppScene).
#include "GlfwAppOptions.h"
#include "GlfwAppScene.h"
#include "GlfwEventAdapter.h"

#include <CommandLine.h>
#include <PluginPaths.h>

#include <osgVis/Statistics>
#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/GL>
#include <osgDB/WriteFile>
#include <osgGA/TrackballManipulator>
#include <osgViewer/Viewer>
#include <osgViewer/ViewerEventHandlers>

#define GLFW_INCLUDE_NONE // <osg/GL> brought the GL headers
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

namespace
{
using namespace osgVis::glfwapp;

const char* const Program = "osgvisglfw";

struct AppError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

std::string lastGlfwError = "no error text from GLFW";

void rememberGlfwError(int /*code*/, const char* description)
{
    lastGlfwError = description;
}

// glfwTerminate on every way out of main once glfwInit succeeded.
struct GlfwLibrary
{
    GlfwLibrary()
    {
        glfwSetErrorCallback(rememberGlfwError);
        if (!glfwInit())
            throw AppError("cannot initialise GLFW: " + lastGlfwError);
    }
    ~GlfwLibrary() { glfwTerminate(); }
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

struct WindowDeleter
{
    void operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

WindowPtr openWindow(const GlfwAppOptions& options)
{
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    WindowPtr window(glfwCreateWindow(int(options.width), int(options.height), Program, nullptr, nullptr));
    if (!window)
        throw AppError("cannot create a " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                       " GLFW window: " + lastGlfwError);
    glfwMakeContextCurrent(window.get());
    glfwSwapInterval(1);
    return window;
}

// One projection for every frame and every mode, and no small-feature culling: near/far computed
// from the drawn objects would differ between modes (and small-feature culling hides visible
// objects), so a conservative mode could not give exactly the pixels of mode osg.
void setUpCamera(osgViewer::Viewer& viewer, const osg::BoundingSphere& bound, const GlfwAppOptions& options,
                 int pixelWidth, int pixelHeight)
{
    osg::Camera& camera = *viewer.getCamera();
    camera.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera.setCullingMode(camera.getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
    double reach = bound.radius();
    if (options.cameraGiven)
        reach = std::max(reach, (options.eye - osg::Vec3d(bound.center())).length() + bound.radius());
    camera.setProjectionMatrixAsPerspective(30.0, double(pixelWidth) / pixelHeight, bound.radius() / 100.0,
                                            reach * 100.0);

    osg::ref_ptr<osgGA::TrackballManipulator> manipulator = new osgGA::TrackballManipulator;
    if (options.cameraGiven)
    {
        const osg::Vec3d view = options.center - options.eye;
        const bool lookingVertically = std::abs(view.z()) > 0.999 * view.length();
        manipulator->setHomePosition(options.eye, options.center,
                                     lookingVertically ? osg::Vec3d(0, 1, 0) : osg::Vec3d(0, 0, 1));
    }
    viewer.setCameraManipulator(manipulator);
}

// The frame just drawn, read from the back buffer before the swap hands it to the screen.
void writeScreenshot(const std::string& path, int width, int height)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(width, height, 1, GL_RGB, GL_UNSIGNED_BYTE, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image->data());
    if (!osgDB::writeImageFile(*image, path))
        throw AppError("cannot write screenshot '" + path + "' (no osgDB plugin for its extension, or no access)");
}

void printStatistics(unsigned frames, const GlfwAppOptions& options, const CulledScene& scene)
{
    std::cout << Program << ": " << frames << " frames, mode " << options.mode << "\n";
    if (!scene.visibilityGroup)
    {
        std::cout << "osgVis: not in the graph (mode " << OsgMode << ")\n";
        return;
    }
    const osgVis::CullStatistics last = scene.visibilityGroup->getLastStatistics();
    std::cout << std::fixed << std::setprecision(3) << "osgVis, last frame: " << last.objects << " objects, "
              << last.visible << " visible, " << last.trianglesVisible << " triangles visible, cull " << last.cullMs
              << " ms\n";
}

int run(const GlfwAppOptions& options)
{
    osg::ref_ptr<osg::Node> model = options.modelPath.empty() ? demoScene() : readModel(options.modelPath);
    const CulledScene scene = cullWithMode(model.get(), options.mode);

    // Declared before the viewer so that the viewer, which releases its GL objects when destroyed,
    // goes while its context is still alive and current.
    GlfwLibrary glfw;
    WindowPtr window = openWindow(options);
    int pixelWidth = 0, pixelHeight = 0;
    glfwGetFramebufferSize(window.get(), &pixelWidth, &pixelHeight);

    osgViewer::Viewer viewer;
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> embedded =
        viewer.setUpViewerAsEmbeddedInWindow(0, 0, pixelWidth, pixelHeight);
    // The context is current on this thread only (GLFW made it so, and the embedded window cannot
    // make it current anywhere else), so every traversal, draw included, must run on this thread.
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    viewer.setSceneData(scene.root.get());
    setUpCamera(viewer, model->getBound(), options, pixelWidth, pixelHeight);
    osg::ref_ptr<osgViewer::StatsHandler> stats = new osgViewer::StatsHandler;
    osgVis::addStatsLines(*stats); // key s shows osgVis's figures beside OSG's
    viewer.addEventHandler(stats);
    GlfwEventAdapter events(window.get(), embedded.get());
    viewer.realize();

    unsigned frames = 0;
    while (!glfwWindowShouldClose(window.get()) && !viewer.done())
    {
        glfwPollEvents();
        viewer.frame();
        ++frames;
        const bool last = frames == options.frames;
        if (last && !options.screenshotPath.empty())
        {
            glfwGetFramebufferSize(window.get(), &pixelWidth, &pixelHeight);
            writeScreenshot(options.screenshotPath, pixelWidth, pixelHeight);
        }
        glfwSwapBuffers(window.get());
        if (last)
            break;
    }
    printStatistics(frames, options, scene);
    if (!options.screenshotPath.empty() && frames < options.frames)
        throw AppError("the window closed after " + std::to_string(frames) + " of " + std::to_string(options.frames) +
                       " frames: no screenshot written");
    return 0;
}
} // namespace

int main(int argc, char** argv)
{
    osgVis::apps::addOsgVisPluginPaths(); // .gltf/.glb and .pvs load from the build tree and after install
    GlfwAppOptions options;
    try
    {
        if (const std::optional<int> status =
                osgVis::apps::readCommandLine(options, parseOptions, argc, argv, Program, "", usageText(Program)))
            return *status;
        return run(options);
    }
    catch (const osgVis::core::UnknownModeError& e)
    {
        std::cerr << Program << ": " << e.what() << "\n";
        return 2;
    }
    catch (const std::exception& e) // SceneError, AppError (GLFW, screenshot)
    {
        std::cerr << Program << ": " << e.what() << "\n";
        return 1;
    }
}
