// SPDX-License-Identifier: MIT
#pragma once
// Runs the built osgvisglfw binary (its path comes in by compile definition) and reads the figures
// it prints at exit.
#include "AppProcess.h"

#include <regex>
#include <string>

namespace osgVis::test
{
inline AppRun runGlfwApp(const std::string& arguments)
{
    return runApp(OSGVIS_GLFW_EXE, arguments);
}

// The "osgVis, last frame: N objects, M visible" line; both -1 when it is missing.
struct LastFrameFigures
{
    int objects = -1, visible = -1;
};

inline LastFrameFigures lastFrameFigures(const std::string& output)
{
    std::smatch match;
    LastFrameFigures figures;
    if (std::regex_search(output, match, std::regex(R"(osgVis, last frame: (\d+) objects, (\d+) visible)")))
    {
        figures.objects = std::stoi(match[1]);
        figures.visible = std::stoi(match[2]);
    }
    return figures;
}
} // namespace osgVis::test
