// SPDX-License-Identifier: MIT
#pragma once
// Command line of osgvisglfw: what to show, how to cull it, the window size, and the optional
// frame limit, screenshot and fixed camera that make a run scriptable.
#include <osg/Vec3d>

#include <string>

namespace osgVis::glfwapp
{
struct GlfwAppOptions
{
    std::string modelPath;               // any OSG-readable file; empty: the built-in demo
    std::string mode = "frustum+octree"; // "osg" (no osgVis node) or a module chain
    unsigned width = 1024, height = 768; // window size in screen coordinates
    unsigned frames = 0;                 // stop after this many frames; 0: when the window closes
    std::string screenshotPath;          // written after the last frame's draw; needs frames > 0
    bool cameraGiven = false;            // --eye and --center: the manipulator's home is this view
    osg::Vec3d eye, center;
    bool help = false;
};

// Parses argv; throws apps::UsageError naming the offending argument.
GlfwAppOptions parseOptions(int argc, char** argv);
std::string usageText(const std::string& programName);
} // namespace osgVis::glfwapp
