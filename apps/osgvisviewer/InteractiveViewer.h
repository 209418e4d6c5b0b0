// SPDX-License-Identifier: MIT
#pragma once
// The windowed walkthrough: walk manipulator, OSG's usual handlers, live mode switching and the
// top-down debug map.
#include "Options.h"
#include <SceneSource.h>

namespace osgVis::viewer
{
// Returns the process exit code.
int runInteractive(const apps::LoadedScene& scene, const ViewerOptions& options);
} // namespace osgVis::viewer
