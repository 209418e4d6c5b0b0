// SPDX-License-Identifier: MIT
#pragma once
// Internal: the part of an extracted graph a cull traversal can decide where it stands (issue 46).
// From the extraction root down, every node the objects' paths run through, as far as plain groups
// without cull callbacks lead (Group, Geode, MatrixTransform, PositionAttitudeTransform and the kit's
// markers): the ids below each, as runs, and each group's children, aligned with its child list as
// extracted. A node of any other kind (Switch, LOD, paged nodes, nested VisibilityGroups, nodes with
// cull callbacks) ends the tree: what lies below it is decided by the per-drawable callbacks as before.
#include <osgVis/SceneExtractor>

#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace osgVis
{
struct CullTree
{
    static constexpr std::uint32_t None = ~0u;

    struct Node
    {
        const osg::Node* node = nullptr;
        /// In `children`, one per child of the group when extracted (None: a child with no object);
        /// childCount 0 for a node the tree ends at.
        std::uint32_t firstChild = 0, childCount = 0;
        std::uint32_t firstRun = 0, runCount = 0; ///< in `runs`: the ids below, ascending
        std::uint32_t idCount = 0;
        /// The subtree draws nothing but its objects (plain nodes, all enabled, no cull callbacks): it
        /// may be skipped whole when none of them is visible (what ChildRange::closed says of a child).
        bool closed = false;
        /// A plain group without cull callback: the walk may cull it itself, child by child.
        bool enterable = false;
    };
    std::vector<Node> nodes; ///< nodes[0]: the extraction root
    std::vector<std::uint32_t> children;
    std::vector<std::pair<core::ObjectId, core::ObjectId>> runs; ///< [first, end)

    /// How many of the node's ids `visible` holds.
    std::size_t visibleCount(const Node& node, const core::VisibleSet& visible) const
    {
        std::size_t n = 0;
        for (std::uint32_t r = node.firstRun; r < node.firstRun + node.runCount; ++r)
            n += visible.countRange(runs[r].first, runs[r].second);
        return n;
    }
};

// A plain group without cull callback, whose cull traversal the walk may stand in for.
bool enterableNode(const osg::Node& node);

// The tree of `scene`, extracted from `root` (every ref's path starts there).
std::shared_ptr<const CullTree> buildCullTree(const ExtractedScene& scene, const osg::Node& root);
} // namespace osgVis
