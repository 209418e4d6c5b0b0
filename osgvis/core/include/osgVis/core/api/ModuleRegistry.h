// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Creates visibility modules by mode name. Later modules register here so every app and test
/// reaches them by name; a name no module registered is looked for as a plugin
/// (plugin/PluginModules.h), so every host takes plugins without being rebuilt.
#include <osgVis/core/module/ModuleChain.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::core
{
struct UnknownModeError : std::invalid_argument
{
    using std::invalid_argument::invalid_argument;
};

/// The name found a plugin (or a registered C module) that cannot be used; the message names the
/// file and the reason. An UnknownModeError, so hosts that validate mode names report it as such.
struct ModuleLoadError : UnknownModeError
{
    using UnknownModeError::UnknownModeError;
};

using ModuleFactory = std::function<std::unique_ptr<VisibilityModule>()>;

/// Names of all registered modules ("frustum", ...), sorted (plugins not yet loaded are not listed).
std::vector<std::string> moduleNames();
bool hasModule(const std::string& name);
void registerModule(const std::string& name, ModuleFactory factory);
/// A registered module, else the plugin osgvis_module_<name>.so. Throws UnknownModeError naming the
/// known modules and the folders searched, or ModuleLoadError when a plugin was found but failed.
std::unique_ptr<VisibilityModule> createModule(const std::string& name);
/// Module names joined by '+' or ',' → chain, e.g. "frustum+octree" (the apps' spelling, since their
/// --modes lists are comma-separated) or "frustum,octree"; a built-in name may carry settings,
/// "octree:occluders=64" (ModuleSettings.h). Throws UnknownModeError.
ModuleChain createChain(const std::string& names);
} // namespace osgVis::core
