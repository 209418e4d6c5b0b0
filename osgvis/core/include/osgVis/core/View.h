// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Forwarding header kept for one release: View.h moved to <osgVis/core/scene/View.h>. Include that path;
/// this one goes away in the next release. Define OSGVIS_NO_MOVED_HEADER_WARNINGS to silence the warning.
#ifndef OSGVIS_NO_MOVED_HEADER_WARNINGS
#pragma message("<osgVis/core/View.h> moved to <osgVis/core/scene/View.h>: this path goes away in the next osgVis release")
#endif
#include <osgVis/core/scene/View.h>
