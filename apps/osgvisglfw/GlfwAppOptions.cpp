// SPDX-License-Identifier: MIT
#include "GlfwAppOptions.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace osgVis::glfwapp
{
namespace
{
unsigned parsePositive(const std::string& option, const std::string& text, unsigned largest)
{
    std::size_t used = 0;
    unsigned long value = 0;
    try
    {
        value = std::stoul(text, &used);
    }
    catch (const std::exception&)
    {
        used = 0;
    }
    if (used == 0 || used != text.size() || text[0] == '-' || value == 0 || value > largest)
        throw OptionsError(option + " expects an integer from 1 to " + std::to_string(largest) + ", got '" + text +
                           "'");
    return unsigned(value);
}

void parseSize(const std::string& text, unsigned& width, unsigned& height)
{
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string::npos)
        throw OptionsError("--size expects WxH (e.g. 1024x768), got '" + text + "'");
    width = parsePositive("--size", text.substr(0, x), 16384);
    height = parsePositive("--size", text.substr(x + 1), 16384);
}

osg::Vec3d parseVector(const std::string& option, const std::string& text)
{
    std::istringstream in(text);
    osg::Vec3d v;
    char comma1 = 0, comma2 = 0;
    in >> v.x() >> comma1 >> v.y() >> comma2 >> v.z();
    const bool finite = std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
    if (!in || comma1 != ',' || comma2 != ',' || in.peek() != std::istringstream::traits_type::eof() || !finite)
        throw OptionsError(option + " expects x,y,z (three numbers), got '" + text + "'");
    return v;
}
} // namespace

GlfwAppOptions parseOptions(int argc, char** argv)
{
    GlfwAppOptions options;
    bool eyeGiven = false, centerGiven = false;
    const std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size(); ++i)
    {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string&
        {
            if (i + 1 >= args.size())
                throw OptionsError(arg + " expects a value");
            return args[++i];
        };
        if (arg == "--help" || arg == "-h")
            options.help = true;
        else if (arg == "--mode")
            options.mode = value();
        else if (arg == "--size")
            parseSize(value(), options.width, options.height);
        else if (arg == "--frames")
            options.frames = parsePositive(arg, value(), 1000000000);
        else if (arg == "--screenshot")
            options.screenshotPath = value();
        else if (arg == "--eye")
        {
            options.eye = parseVector(arg, value());
            eyeGiven = true;
        }
        else if (arg == "--center")
        {
            options.center = parseVector(arg, value());
            centerGiven = true;
        }
        else if (arg.size() > 1 && arg[0] == '-')
            throw OptionsError("unknown option '" + arg + "' (see --help)");
        else if (options.modelPath.empty())
            options.modelPath = arg;
        else
            throw OptionsError("more than one model given: '" + options.modelPath + "' and '" + arg + "'");
    }
    if (options.help)
        return options;
    if (eyeGiven != centerGiven)
        throw OptionsError("--eye and --center go together");
    if (eyeGiven && (options.eye - options.center).length2() == 0.0)
        throw OptionsError("--eye and --center must differ");
    options.cameraGiven = eyeGiven;
    // Only a run with a known last frame can capture that frame before it is swapped away.
    if (!options.screenshotPath.empty() && options.frames == 0)
        throw OptionsError("--screenshot needs --frames N (it captures the last frame)");
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
