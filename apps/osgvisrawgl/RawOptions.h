// SPDX-License-Identifier: MIT
#pragma once
// osgvisrawgl's command line. Parsing only.
#include <string>
#include <vector>

namespace osgVis::rawgl
{
struct RawOptions
{
    std::string model;                         // MODEL.gltf or MODEL.glb
    std::string walk;                          // --walk FILE; empty: MODEL's stem + ".walk" beside it
    std::vector<std::string> modes{"frustum"}; // --modes a,b,c (a chain is written a+b)
    std::string dumpDir;                       // --dump-visible DIR
    bool pixels = false;                       // --pixels
    bool show = false;                         // --show
    bool hierarchy = false;                    // --hierarchy
    bool help = false;
};

// Throws apps::UsageError naming the offending argument.
RawOptions parseRawOptions(int argc, char** argv);
std::string rawUsage();
} // namespace osgVis::rawgl
