// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A chain's stages as typed settings (issue 46): each stage is a module and that module's options
/// (OctreeOptions, MaskOptions, CdtOptions, ...). Their text form is what every mode string takes
/// (createChain, VisibilityGroup, the apps' --mode/--modes, .osgt files):
///
///     frustum+octree:fuseDisjoint=false:occluders=64+mask:shrinkPixels=3
///
/// a stage's name, then `:key=value` for each setting that differs from that name's. Names such as
/// "octree-paper" or "mask-approx" are shorthands for settings; a setting that makes a module
/// approximate is part of a name ("mask-approx"), never a key, so every mode that may cull a visible
/// object says `approx`. docs/modes.md lists the keys.
#include <osgVis/core/cdt/CdtModule.h>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/mask/MaskModule.h>
#include <osgVis/core/module/ModuleChain.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/octree/OctreeModule.h>

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace osgVis::core
{
struct StageSettings
{
    /// The stage's name as written: a built-in name or shorthand ("octree", "octree-paper"), or a
    /// module registered or found as a plugin (then `options` is empty).
    std::string name;
    /// The module's options: none for frustum, registered modules and plugins.
    std::variant<std::monostate, OctreeOptions, MaskOptions, CdtOptions, CellPortalStage, MultifocalModuleOptions>
        options;
};
using ChainSettings = std::vector<StageSettings>;

/// The settings of one stage's text ("octree-paper:occluders=64"). A name that is no built-in
/// module stays a name (for the registry and plugins). Throws UnknownModeError for settings given to
/// a module that takes none, a key the module lacks (listing its keys) or a bad value.
StageSettings parseStageSettings(const std::string& text);
/// Stages separated by '+' or ','.
ChainSettings parseChainSettings(const std::string& text);
/// The canonical text: per stage the shorthand nearest its settings and the keys that differ from
/// it. parseChainSettings(formatChainSettings(c)) gives c back.
std::string formatStageSettings(const StageSettings& stage);
std::string formatChainSettings(const ChainSettings& chain);
/// A built-in module made with its settings; other names as createModule(name) makes them.
std::unique_ptr<VisibilityModule> createModule(const StageSettings& stage);
ModuleChain createChain(const ChainSettings& chain);

/// The built-in names and shorthands, each with its settings.
const std::vector<StageSettings>& builtInStages();
/// The keys of a built-in name with their values there, e.g. {"occluders", "32"}; empty for
/// frustum and names that are no built-in module.
std::vector<std::pair<std::string, std::string>> stageKeys(const StageSettings& stage);
} // namespace osgVis::core
