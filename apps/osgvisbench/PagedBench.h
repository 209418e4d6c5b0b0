// SPDX-License-Identifier: MIT
#pragma once
// osgvisbench --paged: every mode walks a paged database (osgvisgen --paged) with OSG's own
// DatabasePager running, each from a fresh read of the root file, and is measured for what it made
// the pager do (tiles requested, loaded, bytes read, peak resident tiles, peak heap) and for what
// the eye missed: objects the oracle sees on the fully loaded database whose tile was not loaded yet
// (pop-in) or that a mode did not draw although their tile was loaded (false-invisible).
// docs/paging.md has the method.
#include "BenchMode.h"
#include "BenchOptions.h"

#include <ostream>
#include <vector>

namespace osgVis::bench
{
// Prints the table (and writes --json); returns 1 when a conservative mode missed a loaded object.
int runPagedBench(const BenchOptions& options, const std::vector<BenchMode>& modes, std::ostream& out);
} // namespace osgVis::bench
