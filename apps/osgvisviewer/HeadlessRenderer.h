// SPDX-License-Identifier: MIT
#pragma once
// Renders every view of the walk offscreen (a pbuffer on the X display) and writes
// OUTDIR/frame-NNNN.png, a top-down map-NNNN.png every MapInterval views, and report.{json,txt}.
#include "Options.h"
#include <SceneSource.h>

namespace osgVis::viewer
{
constexpr unsigned MapInterval = 50;

// Returns the process exit code; prints what went wrong on stderr.
int renderHeadless(const apps::LoadedScene& scene, const ViewerOptions& options);
} // namespace osgVis::viewer
