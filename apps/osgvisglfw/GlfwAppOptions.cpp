// SPDX-License-Identifier: MIT
#include "GlfwAppOptions.h"

#include <CommandLine.h>

#include <sstream>

namespace osgVis::glfwapp
{
using apps::UsageError;

GlfwAppOptions parseOptions(int argc, char** argv)
{
    GlfwAppOptions options;
    bool eyeGiven = false, centerGiven = false;
    apps::CommandLine line;
    // --eye and --center: a point, and whether it was given (they are checked together below).
    const auto point = [&line](const char* name, osg::Vec3d& target, bool& given)
    {
        line.value({name},
                   [name, &target, &given](const std::string& v)
                   {
                       const std::array<double, 3> p = apps::parseTriple(name, v);
                       target.set(p[0], p[1], p[2]);
                       given = true;
                   });
    };
    line.flag({"--help", "-h"}, options.help)
        .value({"--mode"}, options.mode)
        .value({"--size"}, [&](const std::string& v) { apps::parseSize("--size", v, options.width, options.height); })
        .value({"--frames"}, [&](const std::string& v)
               { options.frames = unsigned(apps::parseUnsigned("--frames", v, 1, 1000000000)); })
        .value({"--screenshot"}, options.screenshotPath)
        .positional(options.modelPath, "more than one model given:");
    point("--eye", options.eye, eyeGiven);
    point("--center", options.center, centerGiven);
    line.parse(argc, argv);
    if (options.help)
        return options;
    if (eyeGiven != centerGiven)
        throw UsageError("--eye and --center go together");
    if (eyeGiven && (options.eye - options.center).length2() == 0.0)
        throw UsageError("--eye and --center must differ");
    options.cameraGiven = eyeGiven;
    // Only a run with a known last frame can capture that frame before it is swapped away.
    if (!options.screenshotPath.empty() && options.frames == 0)
        throw UsageError("--screenshot needs --frames N (it captures the last frame)");
    return options;
}

std::string usageText(const std::string& programName)
{
    std::ostringstream out;
    out << "usage: " << programName
        << " [MODEL] [--mode M] [--size WxH] [--frames N] [--screenshot FILE.png]\n"
           "       [--eye x,y,z --center x,y,z] [--help]\n"
           "\n"
           "Example of an application that owns its window and GL context through GLFW and renders an\n"
           "OpenSceneGraph scene culled by osgVis in its own loop (osgViewer::GraphicsWindowEmbedded).\n"
           "\n"
           "  MODEL                 any file OpenSceneGraph reads (.osgb, .osgt, .gltf/.glb with osgVis's\n"
           "                        glTF plugin, ...); default: a built-in demo, a wall with boxes behind it\n"
           "  --mode M              osg (OSG's own culling, no osgVis node) or a module chain such as\n"
           "                        frustum or frustum+octree (default); an unknown mode lists the known ones;\n"
           "                        a name osgVis lacks loads the plugin osgvis_module_<name>.so from\n"
           "                        OSGVIS_MODULE_PATH or lib/osgvis-modules\n"
           "  --size WxH            window size (default 1024x768)\n"
           "  --frames N            exit after N frames (default: run until the window closes)\n"
           "  --screenshot FILE     write the last frame (read from the back buffer before the swap) to\n"
           "                        FILE in any format osgDB writes, e.g. .png; needs --frames\n"
           "  --eye x,y,z           with --center: start the camera (and its home, key space) at this eye\n"
           "  --center x,y,z        looking at this point, z up; default: the trackball's computed home\n"
           "\n"
           "Mouse: left-drag rotates, middle-drag pans, right-drag or wheel zooms; space goes home,\n"
           "Escape quits. At exit it prints the frame count and osgVis's figures of the last frame.\n";
    return out.str();
}
} // namespace osgVis::glfwapp
