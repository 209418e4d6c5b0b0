#pragma once
// Runs the built osgvisviewer binary (its path comes in by compile definition) and collects its
// exit code and everything it printed.
#include <string>

namespace osgVis::test
{
struct ViewerRun
{
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

// `arguments` are appended to the binary's path as they are (quote paths with spaces yourself).
ViewerRun runViewer(const std::string& arguments);
// A fresh, empty folder for one test under the build tree.
std::string scratchDirectory(const std::string& name);
// Whether an X display is set: headless rendering needs one (scripts/test.sh provides Xvfb).
bool haveDisplay();
} // namespace osgVis::test
