// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A hierarchy node as osgVis/visapi.h spells it and as the core does (scene/TraversalHierarchy.h):
/// both sides of the C interface hand nodes across, a renderer's to the modules, the core's to a
/// module written in C.
#include <osgVis/visapi.h>

#include <osgVis/core/scene/TraversalHierarchy.h>

#include <type_traits>

namespace osgVis::core::capi
{
static_assert(std::is_same_v<ObjectId, uint32_t>, "visapi.h hands object ids out as uint32_t arrays");

inline HierarchyNode coreNode(const osgvis_hierarchy_node& node)
{
    HierarchyNode out;
    out.id = node.id;
    out.region = {{node.region_min[0], node.region_min[1], node.region_min[2]},
                  {node.region_max[0], node.region_max[1], node.region_max[2]}};
    out.objects = node.objects;
    out.objectCount = node.object_count;
    return out;
}

inline osgvis_hierarchy_node cNode(const HierarchyNode& node)
{
    osgvis_hierarchy_node out;
    out.id = node.id;
    for (int k = 0; k < 3; ++k)
    {
        out.region_min[k] = node.region.min[k];
        out.region_max[k] = node.region.max[k];
    }
    out.objects = node.objects;
    out.object_count = static_cast<uint32_t>(node.objectCount);
    return out;
}
} // namespace osgVis::core::capi
