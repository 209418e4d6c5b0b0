// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Object-space occlusion culling after Coorg & Teller, "A Spatially and Temporally Coherent Object
/// Space Visibility Algorithm": a few large occluders near the eye (area-angle selection from the
/// eye's cell) cull whole kd-tree nodes by supporting/separating planes; connected occluders fuse;
/// each node keeps the planes that decided it last frame and re-checks only those; frustum
/// culling is folded into the same traversal; subtrees are traversed in parallel (TBB work
/// stealing) with the same answer at every thread count.
/// Modes: "octree" (connected occluders fuse, then an occlusion-tree sweep fuses those that share
/// no edge), "octree-paper" (the paper's method: no sweep) and "octree-single" (each occluder
/// tested on its own, the paper's comparison; no sweep).
/// A renderer's own hierarchy (Scene::hierarchy, visibility API §3.3) is walked instead of the
/// module's kd-tree when it passes HierarchyIndex's checks: each node is tested by the tight box of
/// what it holds as recorded, so neither its declared regions nor its order need to be true.
#include <osgVis/core/octree/BoxOcclusion.h>
#include <osgVis/core/spatial/KdTree.h>
#include <osgVis/core/occluders/OccluderBuilder.h>
#include <osgVis/core/occluders/OccluderSelector.h>
#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <string>

namespace osgVis::core
{
struct OctreeOptions
{
    std::uint32_t occluders = 32;      ///< k: actual occluders per frame
    double areaAngleThreshold = 0.002; ///< potential-occluder threshold
    bool fuseConnected = true;         ///< false: "octree-single"
    bool temporalCoherence = true;
    bool coplanarUnions = true; ///< coplanar pieces of different objects as one occluder
    /// After the occluder test, objects still visible are swept front to back through an occlusion
    /// tree of the polygons of the objects found visible before them, so occluders that share no
    /// edge (many small ones) hide together. Point eyes only; off in "octree-paper" and
    /// "octree-single".
    bool fuseDisjoint = true;
    /// A kept object's polygon joins the occlusion tree only when its area-angle reaches this
    /// (5e-5 sr: about 40 pixels at the centre of a 60-degree-high 1280x1024 view). Smaller ones cost insertions and
    /// fill the tree's leaves (four occluders each) while hiding almost nothing on their own.
    double sweepAreaAngleThreshold = 5e-5;
    std::uint32_t occlusionTreeMaxNodes = 4096; ///< stop inserting occluders beyond this
    std::uint32_t maxLeafObjects = 4;
    std::uint32_t parallelMinObjects = 256; ///< subtrees smaller than this run on the calling thread
    OccluderBuildOptions occluderBuild;
    /// Work a query may do, in deterministic units (docs/octree.md, "Budget"): the traversal counts
    /// ten units per box it reaches and per occluder the box is tested against, and takes at
    /// most 3/5 of the budget; the sweep counts the occlusion tree's steps and takes the rest. What
    /// the budget does not reach stays visible, so the answer stays conservative and the same
    /// whatever the machine's load. A budget makes the traversal serial (a fixed order is what
    /// makes the spent budget reproducible). 0: no limit.
    std::uint64_t workBudget = 0;
    /// Walk the scene's TraversalHierarchy (when it has a usable one) instead of building a kd-tree.
    /// Its traversal runs on the calling thread (a renderer's callback is not split into tasks).
    bool sceneHierarchy = true;
};

class OctreeModule : public VisibilityModule
{
public:
    explicit OctreeModule(const OctreeOptions& options = {});
    ~OctreeModule() override;
    const char* name() const override;
    void setScene(const Scene& scene) override;
    /// Moved and inserted objects are tested on their own and no polygon resting on a changed
    /// object occludes, in time that grows with the change; a quarter of the objects changed (or
    /// other stated occluders) rebuilds.
    void sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes) override;
    void cull(const View& view, VisibleSet& visible) override;
    /// Regions: the same traversal with every decision made for the whole box of eyes (a box is
    /// hidden only when the eye volume lies inside all the deciding planes), no frustum, up to 64
    /// occluders chosen around the box's centre, none that a region's near plane could clip.
    bool supportsRegions() const override { return true; }
    void cullRegion(const ViewRegion& region, VisibleSet& visible) override;
    void setDebugRecord(DebugRecord* record) override;

    const OctreeOptions& options() const { return _options; }
    /// Figures of the last query, for benchmarks and tests.
    struct Statistics
    {
        std::uint32_t nodesVisited = 0, nodesInvisible = 0, nodesOutsideFrustum = 0;
        std::uint32_t planeTests = 0, cachedDecisions = 0, activeOccluders = 0;
        /// The occlusion-tree sweep: objects it hid, polygons it inserted, nodes of its tree.
        std::uint32_t sweptHidden = 0, sweptOccluders = 0, sweptTreeNodes = 0;
        /// Nodes of the renderer's traversal that differ from what was recorded: kept, not tested.
        std::uint32_t nodesStrayed = 0;
        /// Objects moved or inserted since the tree was built, tested on their own.
        std::uint32_t changedTested = 0;
        /// Work units the traversal and the sweep spent (OctreeOptions::workBudget), and whether
        /// the budget cut either short.
        std::uint64_t traversalWork = 0, sweepWork = 0;
        bool overBudget = false;
    };
    Statistics lastStatistics() const;
    /// True when the last setScene took the scene's hierarchy; else why not ("" when it had none).
    bool walksSceneHierarchy() const;
    const std::string& hierarchyProblem() const;

private:
    struct Impl;
    OctreeOptions _options;
    std::unique_ptr<Impl> _impl;
};
} // namespace osgVis::core
