// SPDX-License-Identifier: MIT
#pragma once
// osgvisrawgl's own hierarchy handed to osgVis by callback (osgvis_scene_set_hierarchy): the glTF
// node instances as a BVH, each node's box the union of its subtree's object bounds. glTF nodes
// overlap freely, so it is declared OSGVIS_HIERARCHY_OVERLAPPING (docs/visapi.md, "Ordered
// traversal"); nodes whose subtree holds no object with bounds are left out.
#include "RawScene.h"

#include <osgVis/visapi.h>

#include <array>
#include <vector>

namespace osgVis::rawgl
{
class RawHierarchy
{
public:
    explicit RawHierarchy(const RawScene& scene);
    // Valid as long as this object; traverse calls go to it.
    osgvis_hierarchy_desc desc();

private:
    struct Node
    {
        std::array<double, 3> min, max;
        std::vector<std::uint32_t> objects, children; // children: indices into _nodes
    };
    static void traverse(void* self, const double eye[3], const osgvis_hierarchy_visitor* visitor);
    std::uint32_t build(const RawScene& scene, std::uint32_t rawNode); // returns ~0u when empty
    void visit(std::uint32_t node, const double eye[3], const osgvis_hierarchy_visitor& visitor) const;
    double distance(std::uint32_t node, const double eye[3]) const;
    std::vector<Node> _nodes; // 0: a root over the scene's root nodes
};
} // namespace osgVis::rawgl
