// SPDX-License-Identifier: MIT
#include "Options.h"

#include <ThreadingModel.h>

#include <sstream>
#include <vector>

namespace osgVis::viewer
{
namespace
{
std::uint64_t parseUnsigned(const std::string& option, const std::string& text)
{
    std::size_t used = 0;
    unsigned long long value = 0;
    try
    {
        value = std::stoull(text, &used);
    }
    catch (const std::exception&)
    {
        used = 0;
    }
    if (used == 0 || used != text.size() || text[0] == '-')
        throw OptionsError(option + " expects a non-negative integer, got '" + text + "'");
    return value;
}

void parseSize(const std::string& text, unsigned& width, unsigned& height)
{
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string::npos)
        throw OptionsError("--size expects WxH (e.g. 640x512), got '" + text + "'");
    const std::uint64_t w = parseUnsigned("--size", text.substr(0, x));
    const std::uint64_t h = parseUnsigned("--size", text.substr(x + 1));
    if (w == 0 || h == 0 || w > 16384 || h > 16384)
        throw OptionsError("--size must lie between 1x1 and 16384x16384, got '" + text + "'");
    width = unsigned(w);
    height = unsigned(h);
}
} // namespace

ViewerOptions parseOptions(int argc, char** argv)
{
    ViewerOptions options;
    bool modeGiven = false;
    std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size(); ++i)
    {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size())
                throw OptionsError(arg + " expects a value");
            return args[++i];
        };
        if (arg == "--help" || arg == "-h")
            options.help = true;
        else if (arg == "--mode")
        {
            options.mode = value();
            modeGiven = true;
        }
        else if (arg == "--walk")
            options.walkPath = value();
        else if (arg == "--record")
            options.recordPath = value();
        else if (arg == "--headless")
            options.headlessDir = value();
        else if (arg == "--size")
            parseSize(value(), options.width, options.height);
        else if (arg == "--generate")
            options.generateKind = value();
        else if (arg == "--layout")
            options.forestLayout = value();
        else if (arg == "--triangles")
            options.triangles = parseUnsigned(arg, value());
        else if (arg == "--seed")
            options.seed = std::uint32_t(parseUnsigned(arg, value()));
        else if (arg == "--threading" || arg == "--async")
        {
            try
            {
                if (arg == "--async")
                    options.async = apps::parseOnOff(arg, value(), false).front();
                else
                    options.threading = apps::threadingModelName(apps::parseThreadingModel(value()));
            }
            catch (const apps::ThreadingNameError& error)
            {
                throw OptionsError(error.what());
            }
        }
        else if (arg.size() > 1 && arg[0] == '-')
            throw OptionsError("unknown option '" + arg + "' (see --help)");
        else if (options.scenePath.empty())
            options.scenePath = arg;
        else
            throw OptionsError("more than one scene given: '" + options.scenePath + "' and '" + arg + "'");
    }
    if (options.help)
        return options;
    if (!options.generateKind.empty() && !options.scenePath.empty())
        throw OptionsError("give either a SCENE file or --generate, not both");
    if (options.generateKind.empty() && options.scenePath.empty())
        throw OptionsError(
            "no scene given: pass a model file or --generate office|city|floor|tetra|forest (see --help)");
    // A baked .pvs is there to be walked with its cells and portals.
    const std::string pvs = ".pvs";
    if (!modeGiven && options.scenePath.size() > pvs.size() &&
        options.scenePath.compare(options.scenePath.size() - pvs.size(), pvs.size(), pvs) == 0)
        options.mode = "cellportal";
    return options;
}

std::string usageText(const std::string& programName)
{
    std::ostringstream out;
    out << "usage: " << programName
        << " [SCENE] [--mode M] [--walk FILE|auto|orbit] [--record FILE] [--headless OUTDIR] [--size WxH]\n"
           "       [--generate office|city|floor|tetra|forest [--layout L]] [--triangles N] [--seed S]\n"
           "       [--threading MODEL] [--async on|off] [--help]\n"
           "\n"
           "Walks through SCENE (any model OpenSceneGraph reads, or a .pvs baked by osgvispvs: the model it\n"
           "names, culled with its cells and portals) or a generated scene, culled by mode M.\n"
           "\n"
           "  SCENE              model file; its walk is SCENE's stem + .walk when that file exists\n"
           "  --mode M           osg (OSG's own culling) or a module chain, e.g. frustum or frustum+octree\n"
           "                     (a name osgVis lacks loads the plugin osgvis_module_<name>.so from\n"
           "                     OSGVIS_MODULE_PATH or lib/osgvis-modules)\n"
           "                     (default frustum; cellportal for a .pvs); an unknown mode lists the known ones\n"
           "  --walk FILE|auto|orbit  walk file (docs/walk-format.md), auto (eyes at a person's height in\n"
           "                     the model's free space) or orbit (around it); default: the walk beside\n"
           "                     SCENE, the generator's walk with --generate, else auto\n"
           "  --record FILE      where key r saves the recorded eye path\n"
           "  --headless OUTDIR  render every view of the walk offscreen to OUTDIR/frame-NNNN.png,\n"
           "                     map-NNNN.png and report.{json,txt}; needs an X display (xvfb-run)\n"
           "  --size WxH         window / image size (default: the walk's size)\n"
           "  --generate KIND    generate an office, city, floor, tetra or forest scene instead of loading one\n"
           "  --layout L         forest only: single, line or dense (default dense); docs/scenes.md\n"
           "  --triangles N      size of the generated scene (default 200000)\n"
           "  --seed S           seed of the generated scene (default 1)\n"
           "  --threading MODEL  OSG threading model of the window: " << apps::threadingModelChoices() << "\n"
           "                     (default: OSG's choice; key n cycles them); --headless renders\n"
           "                     SingleThreaded so captures stay in step with their frame\n"
           "  --async on|off     asynchronous visibility (default off): a worker per view computes the\n"
           "                     visible set of the region the eye is heading into; the cull thread\n"
           "                     only intersects it with the frustum (stats, key i: osgVis cull ms,\n"
           "                     osgVis async fallback)\n"
           "\n"
           "Keys: W/A/S/D or arrows move, Q/E down/up, left-drag looks, wheel changes speed,\n"
           "      m next culling mode, p play the walk, r start/stop recording, t top-down map,\n"
           "      b drop a building box a few metres ahead, B or Delete delete the building nearest the\n"
           "      centre of the view (the culling re-extracts with stable object ids),\n"
           "      i statistics (I prints them), h help, f fullscreen, c screenshot, space home,\n"
           "      o polygon mode, x texturing, l lighting, k back-face culling, n threading model.\n";
    return out.str();
}
} // namespace osgVis::viewer
