// SPDX-License-Identifier: MIT
#pragma once
// Command line of osgvisviewer: what to show (a model file or a generated scene), how to cull it,
// which walk to follow and whether to render it offscreen.
#include <SceneSource.h>

#include <string>

namespace osgVis::viewer
{
// The scene, walk and size (SCENE or --generate, --walk, --size) are the SceneRequest part.
struct ViewerOptions : apps::SceneRequest
{
    std::string mode = "frustum";     // "osg" or a module chain such as "frustum+octree"
    std::string recordPath;           // where `r` saves the recorded eye path
    std::string headlessDir;          // non-empty: render the walk offscreen into this folder
    std::string threading;            // --threading: an OSG threading model name; empty: OSG's choice
    bool async = false;               // --async on: asynchronous visibility for the module chains
    bool help = false;
};

// Parses argv; throws apps::UsageError naming the offending argument.
ViewerOptions parseOptions(int argc, char** argv);
std::string usageText(const std::string& programName);
} // namespace osgVis::viewer
