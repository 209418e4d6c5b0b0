// SPDX-License-Identifier: MIT
// osgvisviewer: walk through a scene with osgVis culling, in a window or headless to PNG files.
#include "CullingModes.h"
#include "HeadlessRenderer.h"
#include "InteractiveViewer.h"
#include "Options.h"
#include <SceneSource.h>

#include <CommandLine.h>
#include <PluginPaths.h>
#include <Q3PvsMode.h>

#include <osgVis/core/api/ModuleRegistry.h>

#include <iostream>

int main(int argc, char** argv)
{
    using namespace osgVis::viewer;
    osgVis::apps::addOsgVisPluginPaths(); // .pvs and .gltf/.glb load from the build tree and after install
    const std::string program = "osgvisviewer";
    ViewerOptions options;
    if (const std::optional<int> status =
            osgVis::apps::readCommandLine(options, parseOptions, argc, argv, program, "", usageText(program)))
        return *status;
    try
    {
        // A Quake 3 level brings its own cells: its mode joins the cycle (SceneSource files them).
        if (options.scenePath.size() > 4 && options.scenePath.compare(options.scenePath.size() - 4, 4, ".bsp") == 0)
            osgVis::apps::registerQ3PvsMode();
        checkMode(options.mode);
    }
    catch (const osgVis::core::UnknownModeError& e)
    {
        std::cerr << program << ": " << e.what() << "\n";
        return 2;
    }

    try
    {
        const osgVis::apps::LoadedScene scene = osgVis::apps::loadScene(options);
        return options.headlessDir.empty() ? runInteractive(scene, options) : renderHeadless(scene, options);
    }
    catch (const osgVis::apps::SceneError& e)
    {
        std::cerr << program << ": " << e.what() << "\n";
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << program << ": unexpected error: " << e.what() << "\n";
        return 1;
    }
}
