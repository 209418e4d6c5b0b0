// SPDX-License-Identifier: MIT
#include "RawOptions.h"

#include <CommandLine.h>

namespace osgVis::rawgl
{
using apps::UsageError;

std::string rawUsage()
{
    return "usage: osgvisrawgl MODEL.gltf|MODEL.glb [--walk FILE.walk] [--modes frustum,octree,...]\n"
           "                   [--dump-visible DIR] [--pixels] [--hierarchy] [--show] [--help]\n"
           "\n"
           "A renderer that is not OSG: reads the glTF model with tinygltf into its own scene, culls\n"
           "every view of the walk through osgVis's C interface (osgVis/visapi.h) and draws the\n"
           "visible objects with OpenGL 3.3 core in a GLFW window (docs/visapi.md, \"A renderer that\n"
           "is not OSG\"). Prints, per mode, the views, the mean visible objects, the median cull ms\n"
           "and, with --pixels, the pixels that differ from the unculled frame.\n"
           "--walk FILE: the walk to follow (docs/walk-format.md). Default: MODEL's stem + .walk beside\n"
           "  it; `osgvisbench --scene MODEL --save-walk FILE` writes one for any model.\n"
           "--modes: the visibility modes, each a module chain written a+b (default frustum); a name\n"
           "  osgVis lacks loads the plugin osgvis_module_<name>.so (OSGVIS_MODULE_PATH).\n"
           "--dump-visible DIR: write DIR/<mode>.visible, one line per view: its index, the number of\n"
           "  visible objects and their canonical identities (glTF node path and primitive,\n"
           "  \"n0/n3/n12#p1\"), sorted; and DIR/objects.txt, every object's identity, flags,\n"
           "  triangles, world bounds and a hash of its world triangles. osgvisbench --dump-visible\n"
           "  writes the same files from OSG's side.\n"
           "--pixels: also draw every view unculled and compare the frames pixel for pixel; a mode\n"
           "  is conservative unless its name says approx (docs/visapi.md).\n"
           "--hierarchy: hand osgVis this program's own hierarchy, the glTF node instances as boxes\n"
           "  (overlapping), walked by callback; modes that walk a hierarchy (cdt, octree, mask) walk\n"
           "  it instead of their own tree, cdt by depth only since the boxes overlap (docs/visapi.md).\n"
           "--show: show the frames in a window (default: drawn off-screen in a hidden window).\n"
           "Exit status: 0 ok; 1 the model, the walk or GL failed, or (--pixels) a conservative mode's\n"
           "frame differs from the unculled one; 2 bad command line.\n";
}

RawOptions parseRawOptions(int argc, char** argv)
{
    RawOptions options;
    apps::CommandLine line;
    line.flag({"--help", "-h"}, options.help)
        .value({"--walk"}, options.walk)
        .value({"--modes"},
               [&](const std::string& v)
               {
                   options.modes.clear();
                   for (const std::string& mode : apps::splitList(v))
                   {
                       if (mode.empty())
                           throw UsageError("--modes contains an empty name");
                       for (const std::string& earlier : options.modes)
                           if (earlier == mode)
                               throw UsageError("mode '" + mode + "' is listed twice");
                       options.modes.push_back(mode);
                   }
                   if (options.modes.empty())
                       throw UsageError("--modes is empty");
               })
        .value({"--dump-visible"}, options.dumpDir)
        .flag({"--pixels"}, options.pixels)
        .flag({"--show"}, options.show)
        .flag({"--hierarchy"}, options.hierarchy)
        .positional(options.model, "more than one model:");
    line.parse(argc, argv);
    if (!options.help && options.model.empty())
        throw UsageError("no model given");
    return options;
}
} // namespace osgVis::rawgl
