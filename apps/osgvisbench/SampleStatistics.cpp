// SPDX-License-Identifier: MIT
#include "SampleStatistics.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace osgVis::bench
{
std::vector<double> sortedFinite(const std::vector<double>& samples)
{
    std::vector<double> finite;
    std::copy_if(samples.begin(), samples.end(), std::back_inserter(finite), [](double x) { return std::isfinite(x); });
    std::sort(finite.begin(), finite.end());
    return finite;
}

std::optional<double> median(const std::vector<double>& sorted)
{
    if (sorted.empty())
        return std::nullopt;
    const std::size_t n = sorted.size();
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

std::optional<double> percentile(const std::vector<double>& sorted, double p)
{
    if (sorted.empty())
        return std::nullopt;
    const std::size_t rank = std::size_t(std::ceil(p * double(sorted.size())));
    return sorted[std::min(sorted.size(), std::max<std::size_t>(rank, 1)) - 1];
}
} // namespace osgVis::bench
