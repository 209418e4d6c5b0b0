// SPDX-License-Identifier: MIT
#include "BenchMode.h"

#include <osgVis/core/api/ModuleRegistry.h>

#include <algorithm>
#include <set>

namespace osgVis::bench
{
namespace
{
BenchMode chainMode(const std::string& name)
{
    BenchMode mode;
    mode.name = name;
    mode.kind = BenchMode::Kind::ModuleChain;
    mode.chain = name;
    std::replace(mode.chain.begin(), mode.chain.end(), '+', ',');
    try
    {
        // Building the chain is cheap (modules do their work in setScene) and is the one authority
        // on which names exist.
        const core::ModuleChain chain = core::createChain(mode.chain);
        mode.conservative = !chain.approximate() && name.find("approx") == std::string::npos;
    }
    catch (const core::ModuleLoadError& e)
    {
        throw UnknownBenchModeError(e.what()); // names the plugin file and why it cannot be used
    }
    catch (const core::UnknownModeError& e)
    {
        throw UnknownBenchModeError("unknown mode '" + name + "' (" + e.what() + "); valid modes: " + validModeList() +
                                    "; chain modules with '+', e.g. frustum+octree");
    }
    return mode;
}
} // namespace

std::string validModeList()
{
    std::string list = "osg, osg-oq, exact";
    for (const std::string& module : core::moduleNames())
        list += ", " + module;
    return list;
}

std::vector<BenchMode> parseBenchModes(const std::vector<std::string>& names)
{
    std::vector<BenchMode> modes;
    std::set<std::string> seen;
    for (const std::string& name : names)
    {
        if (!seen.insert(name).second)
            throw UnknownBenchModeError("mode '" + name + "' is listed twice");
        if (name == "osg")
            modes.push_back({name, BenchMode::Kind::OsgDefault, {}, true});
        else if (name == "osg-oq")
            modes.push_back({name, BenchMode::Kind::OcclusionQueries, {}, false});
        else if (name == "exact")
            modes.push_back({name, BenchMode::Kind::Exact, {}, true});
        else
            modes.push_back(chainMode(name));
    }
    return modes;
}
} // namespace osgVis::bench
