// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Creates visibility modules by mode name. Later modules register here so every app and test
/// reaches them by name.
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

using ModuleFactory = std::function<std::unique_ptr<VisibilityModule>()>;

/// Names of all registered modules ("frustum", ...), sorted.
std::vector<std::string> moduleNames();
bool hasModule(const std::string& name);
void registerModule(const std::string& name, ModuleFactory factory);
/// Throws UnknownModeError naming the known modules.
std::unique_ptr<VisibilityModule> createModule(const std::string& name);
/// Module names joined by '+' or ',' → chain, e.g. "frustum+octree" (the apps' spelling, since their
/// --modes lists are comma-separated) or "frustum,octree". Throws UnknownModeError.
ModuleChain createChain(const std::string& names);
} // namespace osgVis::core
