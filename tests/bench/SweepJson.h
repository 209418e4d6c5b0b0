// SPDX-License-Identifier: MIT
#pragma once
// Reading the cull-only sweep part of osgvisbench's JSON for the tests: the `sweeps` array has one
// flat object per line, and `identical_across_threads` maps mode names to booleans.
#include <optional>
#include <string>
#include <vector>

namespace osgVis::test
{
struct SweepEntry
{
    std::string mode;
    double speed = 0, threads = 0, views = 0;
    std::optional<double> cullMsMedian, cullMsP99, visibleMean;
};

std::vector<SweepEntry> sweepEntries(const std::string& json);
// The boolean of `mode` in "identical_across_threads", nullopt when absent.
std::optional<bool> identicalAcrossThreads(const std::string& json, const std::string& mode);
} // namespace osgVis::test
