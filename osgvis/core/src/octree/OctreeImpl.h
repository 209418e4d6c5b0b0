// SPDX-License-Identifier: MIT
#pragma once
// Internal: the octree module's state and steps, shared by its query (OctreeModule.cpp), its
// occlusion-tree sweep (OctreeSweep.cpp) and its answer to scene changes (OctreeChanges.cpp).
#include <osgVis/core/octree/OctreeModule.h>

#include <osgVis/core/module/ChangedObjects.h>
#include <osgVis/core/occluders/OccluderDependents.h>
#include <osgVis/core/spatial/SceneHierarchyChoice.h>
#include "OccluderShadow.h"
#include "OcclusionCache.h"
#include "OcclusionTree.h"

#include <tbb/partitioner.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
namespace octree_impl
{
struct Range
{
    std::uint32_t first, count;
};

// Per-thread scratch of the traversal and what it found.
struct TraversalOutput
{
    std::vector<Range> culled;                     // item ranges of hidden or outside-frustum subtrees
    std::vector<std::vector<std::uint32_t>> lists; // partial-occluder list per depth
    std::vector<const BoxOccluderPlanes*> partialPlanes;
    std::vector<BoxOccluderPlanes> fusedPlanes;
    std::vector<std::uint32_t> fusedCandidates, fusedGroup;
    std::vector<const BoxOccluderPlanes*> fusedCandidatePlanes;
    std::vector<std::size_t> fusedMembers;
    std::vector<std::uint8_t> fusedTaken;
    std::vector<DebugRecord::Node> debugNodes;
    OctreeModule::Statistics statistics;
    // Work units spent and allowed (OctreeOptions::workBudget); once a charge fails every later one
    // does, so what was not reached stays visible. A box reached or an occluder tested against it
    // weighs this many units: about what ten steps of the sweep's occlusion tree cost (fitted on
    // 435 queries of four real levels, docs/octree.md "Budget").
    static constexpr std::uint64_t BoxWork = 10;
    std::uint64_t work = 0, budget = ~std::uint64_t(0);
    bool charge(std::uint64_t units)
    {
        if (statistics.overBudget || units > budget - work)
        {
            statistics.overBudget = true;
            return false;
        }
        work += units;
        return true;
    }
    // The occluders a box is tested against: `candidates` while the budget lasts, none after, when
    // the frustum alone decides (at what the `frustum` mode costs).
    const std::vector<std::uint32_t>& deciding(const std::vector<std::uint32_t>& candidates)
    {
        static const std::vector<std::uint32_t> none;
        return candidates.empty() || charge(BoxWork * (1 + candidates.size())) ? candidates : none;
    }

    // Sized once for the tree's depth (see prepare): the traversal holds references into it.
    std::vector<std::uint32_t>& list(std::uint32_t depth) { return lists[depth]; }
    void prepare(std::size_t treeDepth) { lists.resize(treeDepth + 2); }
};

// A subtree handed from the serial top of the traversal to the parallel part.
struct FrontierTask
{
    std::uint32_t node = 0;
    std::uint32_t depth = 0;
    bool active = false;
    unsigned planeMask = 0;
    std::vector<std::uint32_t> occluders;
    TraversalOutput output;
};
} // namespace octree_impl

struct OctreeModule::Impl
{
    using Range = octree_impl::Range;
    using TraversalOutput = octree_impl::TraversalOutput;
    using FrontierTask = octree_impl::FrontierTask;

    KdTree tree; // empty while the scene's hierarchy is walked
    // The renderer's hierarchy, when usable: its index records the nodes' tight boxes and objects.
    // Each box is tested on its own, so siblings may come in any order.
    SceneHierarchyChoice sceneHierarchy{false};
    std::vector<BoxOcclusionCache> hierarchyCaches; // per node id
    std::uint32_t hierarchyDepth = 0;               // deepest level the last traversal reached
    std::vector<unsigned> hierarchyPlaneMasks;      // per depth: the plane mask a node passes on
    std::vector<OccluderPolygon> polygons;
    std::vector<PreparedOccluder> prepared; // per polygon: its box-independent part of computePlanes
    OccluderSelector selector;
    std::vector<BoxOcclusionCache> nodeCaches, objectCaches;
    std::vector<std::int32_t> frontierSlot; // per node: its frontier task index, or -1
    std::vector<FrontierTask> frontier;
    tbb::affinity_partitioner affinity;
    TraversalOutput serial;
    double sceneSize = 1.0;
    std::uint32_t frame = 0;
    DebugRecord* debug = nullptr;
    Statistics statistics;

    // Per-frame inputs. A region query has a volume of eyes and no frustum (root plane mask 0).
    Vec3 eye{0.0};
    EyeVolume eyes;
    const Frustum* frustum = nullptr;
    unsigned rootPlaneMask = 0x3Fu;
    double nearDistance = 0.0;
    std::vector<std::uint32_t> active;
    std::vector<double> margins; // per polygon index, valid for `active` ones
    OccluderShadows shadows;     // of the `active` ones, for a point eye
    std::vector<Aabb> polygonBounds;
    std::vector<std::pair<double, std::uint32_t>> ranked;
    double threshold = 0.0;

    // The occlusion-tree sweep (fuseDisjoint): each object's own polygons, the stated ones, and
    // per-frame scratch.
    std::vector<std::vector<std::uint32_t>> objectPolygons;
    std::vector<double> largestPolygonArea; // per object: bounds the area-angle of all its polygons
    std::vector<std::uint32_t> statedPolygons;
    std::vector<Vec3> objectPoints;         // per object its distinct vertices (static objects)…
    std::vector<std::uint32_t> pointsFirst; // …from pointsFirst[id] to pointsFirst[id + 1]
    OcclusionTree occlusionTree;
    std::vector<std::pair<double, ObjectId>> sweepOrder;
    std::vector<std::uint64_t> insertedAs; // per polygon: 2·stamp + (1 when flipped) if inserted this round
    std::vector<std::uint32_t> sweptIn;    // per polygon: the frame it joined the sweep's tree
    std::uint64_t insertStamp = 0;
    std::uint64_t sweepBudget = ~std::uint64_t(0); // occlusion-tree work the sweep may spend this query
    std::vector<Vec3> insertVertices;
    std::vector<double> insertMargins;

    // Changes since the last build (OctreeChanges.cpp): a moved or inserted object leaves the tree's
    // answer and is tested on its own at each query; no polygon resting on a changed object occludes.
    ChangedObjects changed;
    OccluderDependents dependents;
    std::vector<OccluderCandidate> statedFrom; // the stated occluders built from
    TraversalOutput movedScratch;
    std::vector<std::uint32_t> movedPartial;

    bool applyChanges(const Scene& scene, const std::vector<SceneChange>& changes);
    void testMoved(const Scene& scene, const OctreeOptions& options, VisibleSet& visible);

    void build(const Scene& scene, const OctreeOptions& options);
    void collectObjectPoints(const Scene& scene);
    void chooseFrontier(std::size_t wanted);
    std::size_t treeDepth() const;
    void traverse(const Scene& scene, const OctreeOptions& options, std::uint32_t node, std::uint32_t depth,
                  unsigned planeMask, const std::vector<std::uint32_t>& candidates, TraversalOutput& out,
                  bool stopAtFrontier);
    Occlusion testBox(BoxOcclusionCache& cache, const Aabb& box, const std::vector<std::uint32_t>& occluders, bool fuse,
                      std::vector<std::uint32_t>& partial, TraversalOutput& out);
    bool depthSeparated(const OccluderPolygon& polygon, const Aabb& box) const;
    double depthTolerance(const Aabb& box) const;
    double marginOf(const OccluderPolygon& polygon) const;
    void sweep(const Scene& scene, const View& view, const OctreeOptions& options, VisibleSet& visible);
    void insertPolygons(const std::vector<std::uint32_t>& batch, const View& view, const OctreeOptions& options,
                        bool oneObject);
    void chooseOccluders(const View& view, std::uint32_t k);
    void chooseRegionOccluders(const ViewRegion& region, std::uint32_t k);
    template <class Usable> void chooseBest(std::uint32_t k, Usable usable);
    void rank(std::uint32_t o, double metric, std::uint32_t k);
    void activateRanked();
    void beginQuery(const OctreeOptions& options, const Vec3& center, const Vec3& halfExtent);
    void traverseAll(const Scene& scene, const OctreeOptions& options, VisibleSet& visible);
    void traverseHierarchy(const Scene& scene, const OctreeOptions& options);
    void testObjects(const Scene& scene, const OctreeOptions& options, const std::vector<std::uint32_t>& items,
                     Range range, unsigned planeMask, const std::vector<std::uint32_t>& partial,
                     std::vector<std::uint32_t>& objectPartial, std::uint32_t depth, TraversalOutput& out);
    void applyCulled(const TraversalOutput& out, const std::vector<std::uint32_t>& items, VisibleSet& visible);
    bool hasObjects() const
    {
        return sceneHierarchy.walks() ? !sceneHierarchy.index().objects().empty() : !tree.empty();
    }
    bool fusedHidden(const Aabb& box, const std::vector<std::uint32_t>& partial, TraversalOutput& out);
};
} // namespace osgVis::core
