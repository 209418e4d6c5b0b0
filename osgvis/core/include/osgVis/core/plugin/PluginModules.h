// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Modules as plugins: `osgvis_module_<name>.so` exporting osgvis_module_entry (osgVis/visapi.h),
/// found by name in the folders of OSGVIS_MODULE_PATH (':'-separated, searched first) and then in
/// `osgvis-modules/` beside libosgVisCore, the way osgDB finds its plugins. A plugin once loaded
/// stays loaded for the life of the process (modules made from it may live anywhere).
#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <string>
#include <vector>

namespace osgVis::core
{
/// "osgvis_module_<name>.so".
std::string pluginFileName(const std::string& name);
/// The folders searched, in order.
std::vector<std::string> pluginSearchPath();
/// A module from the plugin of that name, or nullptr when no folder holds one (or the name cannot
/// name a file: empty, or with '/' or a leading '.'). Throws ModuleLoadFailure naming the file and
/// the reason when the file is there but unusable: it does not load, lacks the entry point, refuses
/// or gives a table of another API version or without a required callback, or create fails.
/// Safe to call from several threads.
std::unique_ptr<VisibilityModule> loadPluginModule(const std::string& name);
} // namespace osgVis::core
