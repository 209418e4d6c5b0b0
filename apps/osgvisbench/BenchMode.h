// SPDX-License-Identifier: MIT
#pragma once
// The modes osgvisbench compares. Three are the bench's own reference points; every other name is
// an osgVis module chain (core::createChain) run through an osgVis::VisibilityGroup.
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::bench
{
struct BenchMode
{
    enum class Kind
    {
        OsgDefault,       // "osg": the plain graph, OSG's own culling (frustum + bounding spheres)
        OcclusionQueries, // "osg-oq": every object under its own osg::OcclusionQueryNode
        Exact,            // "exact": draws precisely the oracle's visible set (the frame-rate limit)
        ModuleChain       // anything core::createChain accepts, chain written "a+b"
    };
    std::string name; // as given on the command line: the table row and the JSON key
    Kind kind = Kind::OsgDefault;
    std::string chain; // ModuleChain only: the comma form core::createChain takes
    // A conservative mode must never cull a visible object: false_invisible > 0 fails the run.
    // osg-oq (thresholded, stale queries) and chains with an approximate stage are exempt.
    bool conservative = true;
};

struct UnknownBenchModeError : std::invalid_argument
{
    using std::invalid_argument::invalid_argument;
};

// Validates every name before any heavy work; throws UnknownBenchModeError listing valid modes.
std::vector<BenchMode> parseBenchModes(const std::vector<std::string>& names);
// "osg, osg-oq, exact" and the registered module names.
std::string validModeList();
} // namespace osgVis::bench
