// SPDX-License-Identifier: MIT
#pragma once
// The walks the bench derives from the scene's walk: fewer keys (--views), the six cube faces of
// every key (--cube), and the observer moving several times faster (--speeds). Pure functions of
// the walk; nothing here renders.
#include <osgVis/core/scene/Walk.h>

namespace osgVis::bench
{
// `count` keys spread evenly from the first to the last key (both kept); 0 or more than the walk
// holds keeps every key.
core::Walk subsampledWalk(const core::Walk& walk, unsigned count);

// Every key becomes six keys with its eye and time, looking along the key's own forward, back,
// left, right, up and down axes (in this order), under a 90° square perspective of H×H pixels (H
// the walk's height) with the walk's near/far: together the full sphere of directions.
core::Walk cubeFaceWalk(const core::Walk& walk);

// The observer `speed` times faster: frame k shows key k·speed. One pass over the walk, extended to
// at least min(30, keys) frames by bouncing back and forth at the walk's ends (same step size), so
// that fast observers still give enough samples. Frame k keeps the time of key k (times past the
// walk's end continue at its mean key interval): the frame rate stays, the path is covered faster.
core::Walk pacedWalk(const core::Walk& walk, unsigned speed);
} // namespace osgVis::bench
