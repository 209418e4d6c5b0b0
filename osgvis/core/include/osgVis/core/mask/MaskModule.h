// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Online occlusion culling with occlusion masks after Wang, Agarwal & Har-Peled, "An On-line
/// Occlusion-Culling Algorithm for Fast Walkthrough in Urban Areas": no preprocessing, no stated
/// occluders. On a *critical frame* the module picks R occluders near the eye from a kd-tree by
/// coverage importance, rasterizes them in software into a conservative max-depth mask, builds the
/// mask's pyramid and marks every kd-tree node or object behind it with the time stamp
/// t_c + δ/V: hidden for every eye within δ of the critical eye, δ following from the image-space
/// shrinkage Δ and the occluders' minimum distance (docs/mask.md derives the bound at the frame
/// corners). Other frames only read the stamps. Objects may be inserted, moved and deleted
/// during the walk (sceneChanged / sceneReplaced).
///
/// A renderer's own hierarchy (Scene::hierarchy, visibility API §3.3) replaces the kd-tree: the
/// critical frame's marking walks the renderer's traversal (any layout: each box is tested on its
/// own), occluder selection goes nearest first over its nodes as recorded at setScene, and marks are
/// kept as ranges of the recorded subtrees. Objects inserted or moved afterwards are tested against
/// the mask every frame (the recorded boxes do not hold them); a traversal that strays from the
/// recorded one marks nothing where it strays.
///
/// Modes: "mask" shrinks each occluder group's projection on its own (conservative for every eye in
/// the δ-ball); "mask-approx" shrinks the fused union as the paper does (faster, bounded leaks:
/// approximate); "mask-distance" is "mask" with the plain distance measure for occluder selection.
#include <osgVis/core/mask/MaskKdTree.h>
#include <osgVis/core/mask/OcclusionMask.h>
#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <string>

namespace osgVis::core
{
enum class OccluderMeasure
{
    CoverageImportance, ///< φ(ξ) = min over sampled eyes of the δ-ball of coverage × mindist
    Distance,           ///< nearest first
};

enum class MaskShrink
{
    PerOccluder, ///< "mask": conservative
    FusedUnion,  ///< "mask-approx": the paper's variant, not conservative
};

struct MaskOptions
{
    MaskShrink shrink = MaskShrink::PerOccluder;
    OccluderMeasure measure = OccluderMeasure::CoverageImportance;
    double shrinkPixels = 2.0;        ///< Δ, in frame pixels (the viewport's)
    std::uint32_t maskDownscale = 4;  ///< mask = viewport / this (rounded up), at least 16×16
    std::uint32_t occluders = 64;     ///< R: occluder objects per critical frame
    /// At most this many of their polygons are rasterized, the largest by area-angle from the eye
    /// (0: all): R objects of a finely tessellated level (curved patches) bring thousands, and
    /// the rasterization cost with them. Fewer occluders only cull less.
    std::uint32_t maxOccluderPolygons = 512;
    double minOccluderDistance = 0.0; ///< D: occluders nearer than this to the eye are not used (world
                                      // units; the near plane's reach is always added)
    double maxEyeSpeed = 15.0;        ///< V, world units per second of walk time
    std::uint32_t stopObjects = 8;    ///< ρ: marking stops at nodes with fewer objects and tests them one by one
    enum class Tree { Auto, Planar, Full } tree = Tree::Auto; ///< Auto: Planar for flat (2.5-D) scenes
    std::uint32_t maxLeafObjects = 4;
    /// Walk the renderer's hierarchy (Scene::hierarchy) when it has one and it passes the checks of
    /// HierarchyIndex; false: always the module's own kd-tree.
    bool sceneHierarchy = true;
    /// Work a critical frame may do, in units of the module's deterministic work measure
    /// (docs/mask.md, "Budget"): rasterization counts one unit per occluder polygon and per 8 × 8
    /// mask tile its rectangle reaches, marking `boxTestWork` units per box tested against the mask.
    /// Rasterization takes at most 3/5 of it, the largest groups first while they fit; marking the rest, and
    /// where it runs out the boxes not yet decided stay visible. Visible sets stay reproducible,
    /// whatever the machine's load. On the machine it was calibrated on a unit is about 0.057 µs
    /// of one core, so 17 500 is about 1 ms; the frame's fixed part (selection, clipping, mask
    /// clearing, pyramid: 0.7-1 ms on real levels) comes on top. 0 (the default): no limit, since
    /// today's 1 ms costs a quarter of the occlusion efficacy on real levels (docs/mask.md).
    std::uint64_t workBudget = 0;
    std::uint32_t boxTestWork = 7; ///< units per box tested (calibrated against the tiles, docs/mask.md)
};

class MaskModule : public VisibilityModule
{
public:
    explicit MaskModule(const MaskOptions& options = {});
    ~MaskModule() override;
    const char* name() const override;
    bool approximate() const override { return _options.shrink == MaskShrink::FusedUnion; }
    void setScene(const Scene& scene) override;
    void sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes) override;
    void cull(const View& view, VisibleSet& visible) override;
    void setDebugRecord(DebugRecord* record) override;

    const MaskOptions& options() const { return _options; }
    /// True when the last setScene took the scene's hierarchy; else why not ("" when it had none).
    bool walksSceneHierarchy() const;
    const std::string& hierarchyProblem() const;

    enum class CriticalReason
    {
        None,          ///< stamps of an earlier critical frame answered
        First,         ///< no mask yet
        StampExpired,  ///< walk time passed t_c + δ/V
        LeftRegion,    ///< the eye moved farther than δ from the critical eye (faster than V)
        Turned,        ///< the view turned: marks hold for the critical frame's orientation only
        OccluderGone,  ///< an occluder of the current mask was deleted or moved
        ViewChanged,   ///< projection or viewport changed
    };
    /// Figures of the last query (for the benchmark's per-step table and the tests).
    struct Statistics
    {
        CriticalReason critical = CriticalReason::None;
        double selectMs = 0.0, rasterizeMs = 0.0, pyramidMs = 0.0, markMs = 0.0; ///< critical frames
        std::uint32_t occluderObjects = 0, occluderPolygons = 0, groups = 0;
        std::size_t coveredPixels = 0;
        std::uint32_t maskWidth = 0, maskHeight = 0;
        std::uint32_t nodesTested = 0, nodesMarked = 0, objectsMarked = 0;
        std::uint32_t nodesStrayed = 0; ///< renderer's nodes unlike the recorded ones (nothing marked there)
        double delta = 0.0;         ///< least δ of the current marks (world units)
        double validUntil = 0.0;    ///< t_c + δ/V: every mark holds until then
        double criticalAfter = 0.0; ///< when half the hidden objects' stamps have run out
        std::uint32_t culled = 0; ///< objects this query removed
        std::uint64_t rasterWork = 0, markWork = 0; ///< work units spent (MaskOptions::workBudget)
        std::uint32_t groupsSkipped = 0; ///< occluder groups left out for the budget
        bool overBudget = false;         ///< the budget cut this critical frame's work short
    };
    Statistics lastStatistics() const;
    /// The mask of the last critical frame (for the debug view and the tests).
    const OcclusionMask& mask() const;

private:
    // Phases of cull.
    /// True while the marks of the alive critical frames hold for an eye at `eye` at walk time t
    /// (drops the expired frames first).
    bool aliveMarksHold(double t, const Vec3& eye);
    /// Whether this frame is critical, and why; forgets the marks that no longer hold.
    CriticalReason criticalReasonFor(const View& view);
    /// The critical frame: occluders, mask, marks, and when the next one comes. False when the
    /// projection allows no occlusion (the marks are forgotten).
    bool runCriticalFrame(const View& view, CriticalReason reason);
    /// The critical frame's occluder objects, the polygons to rasterize and the objects the marks
    /// rest on.
    void selectOccluders(const View& view);
    /// Groups the selected polygons and rasterizes them into a fresh mask, the largest groups first
    /// while the work budget lasts; what is left of the budget goes to marking.
    void rasterizeOccluders(double nearDepth, double shift, Statistics& stats);
    /// How long the marks just made hold, when the next critical frame comes, and the frame among
    /// the alive ones.
    void recordCriticalFrame(double t, const Vec3& eye);
    /// Clears the moving objects hidden for an eye at `eye`; returns how many it cleared.
    std::uint32_t cullMovingObjects(const Vec3& eye, VisibleSet& visible) const;
    /// True when the box lies behind the current mask (or out of its view) for every eye within
    /// `delta` of the critical eye (set on success); a box that is covered but not deep enough is
    /// halved up to `splits` times.
    bool objectBehindMask(const Aabb& box, int splits, double& delta) const;
    /// The least δ of the occluder groups whose rectangles reach the given mask rectangle.
    double tileDeltaOver(double x0, double y0, double x1, double y1) const;
    void fillTileDeltas(double shift);
    /// The critical frame's marking pass over the kd-tree, or over the renderer's traversal.
    void markHidden(Statistics& stats);
    struct MarkPass; ///< one run of markHidden
    /// Clears what the marks hide at walk time t; returns how many it cleared.
    std::uint32_t applyTreeMarks(double t, VisibleSet& visible);
    std::uint32_t applyHierarchyMarks(double t, VisibleSet& visible);
    struct Impl;
    MaskOptions _options;
    std::unique_ptr<Impl> _impl;
};
} // namespace osgVis::core
