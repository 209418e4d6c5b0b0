// SPDX-License-Identifier: MIT
#pragma once
// Runs the built osgvisviewer binary (its path comes in by compile definition).
#include "AppProcess.h"

namespace osgVis::test
{
inline AppRun runViewer(const std::string& arguments)
{
    return runApp(OSGVIS_VIEWER_EXE, arguments);
}

// A fresh, empty folder for one viewer test under the build tree.
inline std::string scratchDirectory(const std::string& name)
{
    return scratchDirectory("apps", name).string();
}
} // namespace osgVis::test
