// SPDX-License-Identifier: MIT
#include <osgVis/core/plugin/PluginModules.h>

#include <osgVis/core/plugin/CallbackModule.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <mutex>

namespace osgVis::core
{
namespace
{
struct LoadedPlugin
{
    std::string path;
    const osgvis_module_callbacks* callbacks = nullptr;
};

// Folder of the library this function is in (libosgVisCore), from the dynamic loader.
std::string coreLibraryFolder()
{
    Dl_info info{};
    if (!dladdr(reinterpret_cast<void*>(&coreLibraryFolder), &info) || !info.dli_fname)
        return {};
    const std::string path = info.dli_fname;
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

bool nameable(const std::string& name)
{
    return !name.empty() && name.front() != '.' && name.find('/') == std::string::npos;
}

// note: dlerror's text for the last failure, read once (reading clears it).
std::string loaderError()
{
    const char* text = dlerror();
    return text ? text : "unknown reason";
}

// Opens the file and reads its table; throws ModuleLoadFailure("plugin <path>: why").
LoadedPlugin openPlugin(const std::string& path)
{
    const std::string origin = "plugin " + path;
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library)
        throw ModuleLoadFailure(origin + ": cannot load: " + loaderError());
    dlerror();
    void* symbol = dlsym(library, OSGVIS_MODULE_ENTRY_SYMBOL);
    if (!symbol)
    {
        const std::string why = loaderError();
        dlclose(library);
        throw ModuleLoadFailure(origin + ": no entry point " OSGVIS_MODULE_ENTRY_SYMBOL " (" + why + ")");
    }
    const auto entry = reinterpret_cast<osgvis_module_entry_fn>(symbol);
    const osgvis_module_callbacks* callbacks = nullptr;
    try
    {
        callbacks = entry(OSGVIS_VISAPI_VERSION);
    }
    catch (...)
    {
        dlclose(library);
        throw ModuleLoadFailure(origin + ": " OSGVIS_MODULE_ENTRY_SYMBOL " threw");
    }
    if (!callbacks)
    {
        dlclose(library);
        throw ModuleLoadFailure(origin + ": " OSGVIS_MODULE_ENTRY_SYMBOL " returned no callback table");
    }
    try
    {
        checkCallbacks(callbacks, origin);
    }
    catch (...)
    {
        dlclose(library);
        throw;
    }
    return {path, callbacks}; // note: never closed, modules made from it may outlive every cache
}
} // namespace

std::string pluginFileName(const std::string& name)
{
    return "osgvis_module_" + name + ".so";
}

std::vector<std::string> pluginSearchPath()
{
    std::vector<std::string> folders;
    if (const char* variable = std::getenv("OSGVIS_MODULE_PATH"))
    {
        const std::string path = variable;
        std::size_t start = 0;
        while (start <= path.size())
        {
            const std::size_t colon = path.find(':', start);
            const std::string folder =
                path.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
            if (!folder.empty())
                folders.push_back(folder);
            if (colon == std::string::npos)
                break;
            start = colon + 1;
        }
    }
    const std::string beside = coreLibraryFolder();
    if (!beside.empty())
        folders.push_back(beside + "/osgvis-modules");
    return folders;
}

std::unique_ptr<VisibilityModule> loadPluginModule(const std::string& name)
{
    if (!nameable(name))
        return nullptr;
    std::string path;
    for (const std::string& folder : pluginSearchPath())
    {
        const std::string candidate = folder + "/" + pluginFileName(name);
        if (access(candidate.c_str(), F_OK) == 0)
        {
            path = candidate;
            break;
        }
    }
    if (path.empty())
        return nullptr;

    static std::mutex mutex;
    static std::map<std::string, LoadedPlugin> loaded; // by path
    LoadedPlugin plugin;
    {
        std::lock_guard<std::mutex> lock(mutex);
        auto found = loaded.find(path);
        if (found == loaded.end())
            found = loaded.emplace(path, openPlugin(path)).first;
        plugin = found->second;
    }
    return std::make_unique<CallbackModule>(*plugin.callbacks, nullptr, "plugin " + plugin.path);
}
} // namespace osgVis::core
