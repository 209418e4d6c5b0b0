// SPDX-License-Identifier: MIT
#pragma once
// Seeded random numbers that are identical on every platform: std::mt19937's output sequence is fixed
// by the standard, but the std distributions are implementation-defined, so the mapping from the
// engine's integers to numbers is ours.
#include <cstdint>
#include <random>

namespace osgVis::gen
{
class Random
{
public:
    explicit Random(std::uint32_t seed) : _engine(seed) {}

    // Uniform in [0, 1) with 53 random bits (two engine outputs, as genrand_res53 of the reference MT).
    double unit();
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    // Uniform integer in [0, n) for n > 0 (multiply-shift; the bias is below 2^-32 · n).
    std::uint32_t below(std::uint32_t n);
    // Uniform integer in [lo, hi].
    int between(int lo, int hi) { return lo + int(below(std::uint32_t(hi - lo + 1))); }
    bool chance(double p) { return unit() < p; }

private:
    std::mt19937 _engine;
};
} // namespace osgVis::gen
