// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Everything a cell-portal bake produces and a `.pvs` file stores: the cells and portals, per
/// source cell the stab tree (portal sequences a sightline can pass), the cells and objects visible
/// from anywhere in it, and a fingerprint of the model it was baked for.
#include <osgVis/core/pvs/CellGraph.h>
#include <osgVis/core/scene/SceneFingerprint.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::core
{
constexpr std::uint32_t NoStabParent = ~std::uint32_t(0);

/// One portal sequence of a stab tree, stored in depth-first preorder: the sequence is the chain of
/// portals from the tree's root down to this node. Its subtree is the nodes [index+1, subtreeEnd).
struct StabNode
{
    std::uint32_t portal = 0;     ///< index into CellGraph::portals, crossed into `cell`
    std::uint32_t cell = 0;       ///< the cell reached through this sequence
    std::uint32_t parent = NoStabParent;
    std::uint32_t subtreeEnd = 0; ///< index one past the last node of this node's subtree
};

struct SourceCellVisibility
{
    std::vector<StabNode> stabTree;
    /// The search gave up past its budget; every cell reachable from here then counts as visible
    /// and the stab tree is incomplete (eye-to-cell falls back to cellToObject for this cell).
    bool budgetExceeded = false;
    VisibleSet cellToCell;   ///< capacity = cell count; includes the cell itself
    VisibleSet cellToObject; ///< capacity = object count: the cell's PVS
};

/// Figures of the baked data only: no wall-clock time, so that the same bake gives the same bytes
/// (osgvispvs reports how long it took).
struct BakeStatistics
{
    std::uint32_t cells = 0, portals = 0;
    std::uint32_t budgetExceededCells = 0; ///< source cells whose stab-tree search hit its budget
    std::uint64_t stabNodes = 0;
    double averageVisibleCells = 0.0, averagePvsObjects = 0.0;
};

struct CellPortalData
{
    std::uint64_t fingerprint = 0; ///< sceneFingerprint() of the model it was baked for
    std::uint32_t objectCount = 0;
    CellGraph graph;
    std::vector<SourceCellVisibility> sources; ///< one per cell
    BakeStatistics statistics;
    /// Set when baked on a complete paged database (Scene::tiles): its objects' tile keys, so that
    /// the data serve a scene with any tiles loaded (mapToBakedObjects). Null otherwise.
    std::shared_ptr<const SceneTiles> tiles;
};

/// The figures of `data`'s cells, portals and sources (everything but `statistics` itself), as the
/// bake and the merge of split bakes both record them.
BakeStatistics bakeStatisticsOf(const CellPortalData& data);
/// A source cell not baked in this file (a range of a split bake): no stab tree, empty sets of the
/// right capacities.
SourceCellVisibility placeholderSource(std::size_t cellCount, std::size_t objectCount);
/// True for a source that placeholderSource could have made.
bool isPlaceholderSource(const SourceCellVisibility& source);
} // namespace osgVis::core
