// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Forwarding header kept for one release: AxialRect.h moved to <osgVis/core/geometry/AxialRect.h>. Include that path;
/// this one goes away in the next release. Define OSGVIS_NO_MOVED_HEADER_WARNINGS to silence the warning.
#ifndef OSGVIS_NO_MOVED_HEADER_WARNINGS
#pragma message("<osgVis/core/AxialRect.h> moved to <osgVis/core/geometry/AxialRect.h>: this path goes away in the next osgVis release")
#endif
#include <osgVis/core/geometry/AxialRect.h>
