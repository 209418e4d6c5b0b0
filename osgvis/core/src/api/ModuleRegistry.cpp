// SPDX-License-Identifier: MIT
#include <osgVis/core/api/ModuleRegistry.h>

#include <osgVis/core/api/ModuleSettings.h>
#include <osgVis/core/plugin/CallbackModule.h>
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

std::string joined(const std::vector<std::string>& names)
{
    std::string out;
    for (const std::string& n : names)
    {
        if (!out.empty())
            out += ", ";
        out += n;
    }
    return out;
}

std::string trimmed(const std::string& s)
{
    const char* space = " \t\r\n";
    const std::size_t first = s.find_first_not_of(space);
    if (first == std::string::npos)
        return {};
    const std::size_t last = s.find_last_not_of(space);
    return s.substr(first, last - first + 1);
}
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
    std::size_t start = 0;
    while (true)
    {
        const std::size_t comma = names.find_first_of(",+", start);
        const std::string name =
            trimmed(names.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (name.empty())
            throw UnknownModeError("empty mode name in '" + names + "' (known: " + joined(moduleNames()) + ")");
        // "octree:occluders=64": a built-in module with settings (ModuleSettings.h).
        chain.add(name.find(':') == std::string::npos ? createModule(name) : createModule(parseStageSettings(name)));
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
    return chain;
}
} // namespace osgVis::core
