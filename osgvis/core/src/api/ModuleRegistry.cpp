// SPDX-License-Identifier: MIT
#include <osgVis/core/api/ModuleRegistry.h>

#include <osgVis/core/api/ModuleSettings.h>
#include <osgVis/core/plugin/CallbackModule.h>

#include "ModeText.h"
#include <osgVis/core/plugin/PluginModules.h>

#include <cstdlib>
#include <map>
#include <mutex>

namespace osgVis::core
{
namespace
{
struct Registry
{
    // The built-in names and shorthands, each made from its settings (ModuleSettings).
    Registry()
    {
        for (const StageSettings& stage : builtInStages())
            factories[stage.name] = [stage] { return createModule(stage); };
    }

    std::mutex mutex;
    std::map<std::string, ModuleFactory> factories;
};

// note: function-local static, so modules may register from static initializers of other
// libraries in any order.
Registry& registry()
{
    static Registry r;
    return r;
}

using modetext::joined;
} // namespace

std::vector<std::string> moduleNames()
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    std::vector<std::string> names;
    for (const auto& entry : r.factories)
        names.push_back(entry.first); // std::map keeps them sorted
    return names;
}

bool hasModule(const std::string& name)
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    return r.factories.count(name) != 0;
}

void registerModule(const std::string& name, ModuleFactory factory)
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.factories[name] = std::move(factory);
}

std::unique_ptr<VisibilityModule> createModule(const std::string& name)
{
    ModuleFactory factory;
    {
        Registry& r = registry();
        std::lock_guard<std::mutex> lock(r.mutex);
        const auto found = r.factories.find(name);
        if (found != r.factories.end())
            factory = found->second;
    }
    try
    {
        if (factory)
            return factory();
        if (std::unique_ptr<VisibilityModule> plugin = loadPluginModule(name))
            return plugin;
    }
    catch (const ModuleLoadFailure& e)
    {
        throw ModuleLoadError("mode '" + name + "': " + e.what());
    }
    throw UnknownModeError("unknown mode '" + name + "' (known: " + joined(moduleNames()) + "; no plugin " +
                           pluginFileName(name) + " in " + joined(pluginSearchPath()) + ")");
}

ModuleChain createChain(const std::string& names)
{
    ModuleChain chain;
    for (const std::string& name : modetext::split(names, ",+"))
    {
        if (name.empty())
            throw UnknownModeError("empty mode name in '" + names + "' (known: " + joined(moduleNames()) + ")");
        // "octree:occluders=64": a built-in module with settings (ModuleSettings.h).
        chain.add(name.find(':') == std::string::npos ? createModule(name) : createModule(parseStageSettings(name)));
    }
    return chain;
}
} // namespace osgVis::core
