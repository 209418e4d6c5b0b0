// SPDX-License-Identifier: MIT
#pragma once
// Runs a built osgVis program as a user would (a shell command line) and keeps its exit code and
// everything it printed, for the end-to-end tests of the apps.
#include <filesystem>
#include <string>

namespace osgVis::test
{
struct AppRun
{
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

// `arguments` are appended to the quoted executable path as they are (quote paths yourself).
// A crash shows as 128 + signal number.
AppRun runApp(const std::string& executable, const std::string& arguments);
// A fresh, empty folder under the build tree: <build>/tests/<area>/<name>.
std::filesystem::path scratchDirectory(const std::string& area, const std::string& name);
// Whether an X display is set: headless rendering needs one (scripts/test.sh provides Xvfb).
bool haveDisplay();
// The whole file, or empty when it cannot be read.
std::string readText(const std::filesystem::path& path);
} // namespace osgVis::test
