// SPDX-License-Identifier: MIT
#include "Options.h"

#include <CommandLine.h>
#include <ThreadingModel.h>

#include <sstream>

namespace osgVis::viewer
{
using apps::UsageError;

ViewerOptions parseOptions(int argc, char** argv)
{
    ViewerOptions options;
    bool modeGiven = false;
    apps::CommandLine line;
    line.flag({"--help", "-h"}, options.help)
        .value({"--mode"},
               [&](const std::string& v)
               {
                   options.mode = v;
                   modeGiven = true;
               })
        .value({"--walk"}, options.walkPath)
        .value({"--record"}, options.recordPath)
        .value({"--headless"}, options.headlessDir)
        .value({"--size"}, [&](const std::string& v) { apps::parseSize("--size", v, options.width, options.height); })
        .value({"--generate"}, options.generateKind)
        .value({"--layout"}, options.forestLayout)
        .value({"--triangles"},
               [&](const std::string& v) { options.triangles = apps::parseUnsigned("--triangles", v); })
        .value({"--seed"}, [&](const std::string& v)
               { options.seed = std::uint32_t(apps::parseUnsigned("--seed", v, 0, 4294967295u)); })
        .value({"--threading"}, [&](const std::string& v)
               { options.threading = apps::threadingModelName(apps::parseThreadingModel(v)); })
        .value({"--async"},
               [&](const std::string& v) { options.async = apps::parseOnOff("--async", v, false).front(); })
        .positional(options.scenePath, "more than one scene given:");
    try
    {
        line.parse(argc, argv);
    }
    catch (const apps::ThreadingNameError& error) // --threading, --async: parsers shared with osgvisbench
    {
        throw UsageError(error.what());
    }
    if (options.help)
        return options;
    if (!options.generateKind.empty() && !options.scenePath.empty())
        throw UsageError("give either a SCENE file or --generate, not both");
    if (options.generateKind.empty() && options.scenePath.empty())
        throw UsageError("no scene given: pass a model file or --generate office|city|floor|tetra|forest (see --help)");
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
           "  --threading MODEL  OSG threading model of the window: "
        << apps::threadingModelChoices()
        << "\n"
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
