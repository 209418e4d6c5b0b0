// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Occlusion culling with a view-space constrained Delaunay triangulation after Luka, "Visibility
/// culling with a constrained Delaunay triangulation" (§2.2, §2.3.1): a kd-tree of cells is
/// traversed front to back from the eye; each cell's bound, then each object's, is tested against
/// the triangulation of the occluders drawn so far (hidden when it lies wholly in covered
/// triangles); the occluder polygons of what stays visible are then drawn into it. Object
/// precision: occluders fuse wherever they meet, with no pixel grid and no shrinking beyond the
/// sub-pixel tolerance the GPU's own rasterization needs (docs/cdt.md).
///
/// Which occluders may hide what (§2.3.1, the error of Fig. 4):
/// - "cdt-depthfree": an occluder counts only once the cell holding it is finished, and then for
///   every later cell whatever the depth (cells after it in front-to-back order lie behind it along
///   every ray). Objects straddling a split plane count only after their node's whole subtree.
/// - "cdt-depth": every occluder counts at once, but only where its plane's depth lies in front of
///   the tested box (the farthest depth of the plane over each covered triangle, at its vertices).
/// - "cdt": both: straddling objects count by depth inside their node's subtree and without depth
///   after it, leaf objects without depth after their leaf.
/// Region queries are not answered (supportsRegions() is false): the record holds for one eye.
/// The traversal walks any TraversalHierarchy: its own DisjointCellTree, or the renderer's.
#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <string>

namespace osgVis::core
{
struct CdtOptions
{
    enum class Rule
    {
        Combined,  ///< "cdt"
        DepthFree, ///< "cdt-depthfree"
        DepthOnly, ///< "cdt-depth"
    };
    Rule rule = Rule::Combined;
    /// Constraint edges drawn into the triangulation per frame (0: no cap); occluders past it are
    /// left out (counted), which only culls less.
    std::uint32_t constraintBudget = 8192;
    /// Bound tests per frame (nodes and objects; 0: no cap); past it the rest is kept visible.
    std::uint32_t testBudget = 0;
    /// τ: how far, in pixels, the GPU may place an edge from where exact geometry puts it (vertex
    /// snapping is 1/256 px in GL implementations; the rest is room for float transforms).
    double tolerancePixels = 1.0 / 16.0;
    /// Objects a leaf holds at most: one lets every object hide the cells after it at once
    /// (objects in one leaf are not ordered along rays, so they hide each other only by depth).
    std::uint32_t maxLeafObjects = 1;
    /// Walk the renderer's hierarchy (Scene::hierarchy) when it has one and it passes the checks
    /// of HierarchyIndex, instead of building a kd-tree. One declared Overlapping (or found not to
    /// be disjoint) is walked under the depth-only rule whatever `rule` says: front to back over
    /// overlapping boxes does not order what they hold along rays.
    bool sceneHierarchy = true;
};

class CdtModule : public VisibilityModule
{
public:
    explicit CdtModule(const CdtOptions& options = {});
    ~CdtModule() override;
    const char* name() const override;
    void setScene(const Scene& scene) override;
    /// Moved and inserted objects leave the hierarchy's answer and are tested on their own after
    /// the walk, against the cover drawn with a depth bound; no polygon resting on a changed object
    /// is drawn. A quarter
    /// of the objects changed, or other stated occluders, rebuilds (docs/cdt.md, "Changes").
    void sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes) override;
    void cull(const View& view, VisibleSet& visible) override;
    /// Records the nodes where the traversal stopped (hidden, outside the frustum, visible leaves)
    /// and the occluder polygons drawn into the triangulation.
    void setDebugRecord(DebugRecord* record) override { _debug = record; }

    const CdtOptions& options() const { return _options; }

    struct Statistics
    {
        std::uint32_t nodesVisited = 0, nodesHidden = 0, objectsTested = 0, objectsHidden = 0, outsideFrustum = 0;
        std::uint32_t occludersDrawn = 0, occludersOverBudget = 0, constraintEdges = 0;
        std::uint32_t occludersAlreadyCovered = 0; ///< left out: their outline lay in depth-free cover already
        std::uint32_t sharedEdgesKept = 0; ///< occluder edges not eroded: exactly shared with a drawn neighbour
        std::uint32_t redrawn = 0;         ///< occluders drawn again once the twin across an edge was drawn
        bool testBudgetReached = false;
        /// The traversal strayed from the hierarchy recorded at setScene (another structure, a
        /// sibling out of front-to-back order): this frame kept every candidate.
        bool traversalStrayed = false;
        std::uint32_t triangles = 0; ///< in the triangulation at the end of the frame
        std::uint32_t changedTested = 0; ///< objects moved or inserted since setScene, tested on their own
        double cullMs = 0.0;
    };
    Statistics lastStatistics() const;

    /// Which hierarchy setScene chose: the renderer's (Scene::hierarchy) or the module's own tree.
    bool walksSceneHierarchy() const;
    /// The layout walked (Overlapping: the depth-only rule holds whatever the options say).
    HierarchyLayout walkedLayout() const;
    /// Why the renderer's hierarchy was not used or was walked as Overlapping ("" when neither).
    const std::string& hierarchyProblem() const;

private:
    struct Impl;
    CdtOptions _options;
    std::unique_ptr<Impl> _impl;
    DebugRecord* _debug = nullptr;
};
} // namespace osgVis::core
