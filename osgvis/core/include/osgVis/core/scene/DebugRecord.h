// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// What a module decided in its last query, for debug views (the viewer's top-down map): tree
/// nodes with their state, the occluders it used and the cell the eye was in. Filled only on
/// request, so queries pay nothing for it otherwise.
#include <osgVis/core/geometry/Aabb.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
enum class NodeState : std::uint8_t
{
    OutsideFrustum,
    Visible, ///< visible or partially occluded: drawn
    Invisible ///< occluded
};

struct DebugRecord
{
    struct Node
    {
        Aabb bounds;
        NodeState state = NodeState::Visible;
        std::uint32_t depth = 0;
    };
    std::vector<Node> nodes;                        ///< the nodes where traversal stopped
    std::vector<std::vector<Vec3>> activeOccluders; ///< polygons used as occluders (world space)
    Aabb eyeCell;                                   ///< empty when the module has none

    void clear()
    {
        nodes.clear();
        activeOccluders.clear();
        eyeCell = Aabb();
    }
};
} // namespace osgVis::core
