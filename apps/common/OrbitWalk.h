// SPDX-License-Identifier: MIT
#pragma once
// A walk for a scene that comes without one: an orbit around the scene's bounds, looking at its
// centre, with one near/far derived from the bounds so every view keeps the same depth range.
// Uses core types only, so other apps (osgvisbench) can reuse it unchanged.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/scene/Walk.h>

namespace osgVis::apps
{
struct OrbitWalkOptions
{
    unsigned views = 120;            // keys on one full turn
    double secondsPerTurn = 12.0;    // time stamps run from 0 to this
    double distanceFactor = 2.0;     // eye distance from the centre, in bounding-sphere radii
    double elevationDegrees = 25.0;  // eye height above the centre, as an angle (z is up)
    double fovYDegrees = 60.0;
    unsigned width = 1280, height = 1024;
};

// Throws std::invalid_argument for empty or non-finite bounds.
core::Walk makeOrbitWalk(const core::Aabb& bounds, const OrbitWalkOptions& options = {});
} // namespace osgVis::apps
