// SPDX-License-Identifier: MIT
#pragma once
// Order statistics of timing samples, shared by the rendered passes and the cull sweeps so both
// report medians and percentiles the same way.
#include <optional>
#include <vector>

namespace osgVis::bench
{
// The finite values of `samples`, ascending (NaN marks a sample the source could not give).
std::vector<double> sortedFinite(const std::vector<double>& samples);
// Of an ascending list; nullopt when it is empty.
std::optional<double> median(const std::vector<double>& sorted);
// Nearest-rank percentile of an ascending list: the smallest value with at least p of the samples at
// or below it; nullopt when the list is empty.
std::optional<double> percentile(const std::vector<double>& sorted, double p);
} // namespace osgVis::bench
