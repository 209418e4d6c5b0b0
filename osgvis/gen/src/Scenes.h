// SPDX-License-Identifier: MIT
#pragma once
// The scene kinds as models (layout decided, tessellation density still free) with their walks.
#include "Model.h"

#include <osgVis/core/scene/Walk.h>
#include <osgVis/gen/Forest.h>

#include <cstdint>
#include <string>

namespace osgVis::gen
{
struct SceneModel
{
    Model model;
    core::Walk walk;
};

// Each lays out a scene whose coarsest meshing stays well below `triangles`, so that calibrating the
// tessellation density can reach the budget.
SceneModel officeModel(std::uint64_t triangles, std::uint32_t seed);
// One storey of the office with a fixed room count: its layout does not depend on the budget.
SceneModel floorModel(std::uint32_t seed);
SceneModel cityModel(std::uint64_t triangles, std::uint32_t seed);
SceneModel tetraModel(std::uint64_t triangles, std::uint32_t seed);
// The trees of a layout: the layout does not depend on the budget, only the tessellation does.
SceneModel forestModel(ForestLayout layout, std::uint32_t seed);

// Throws std::invalid_argument naming the known scenes.
SceneModel adversarialModel(const std::string& name);
} // namespace osgVis::gen
