// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Modules composed in sequence: each stage only refines the previous stage's answer.
#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <string>
#include <vector>

namespace osgVis::core
{
struct StageTiming
{
    std::string module;
    double milliseconds = 0.0;
    std::size_t visibleAfter = 0;
};

class ModuleChain
{
public:
    /// A module added after setScene receives the scene at once.
    void add(std::unique_ptr<VisibilityModule> module);
    bool empty() const { return _modules.empty(); }
    std::size_t size() const { return _modules.size(); }
    VisibilityModule& module(std::size_t i) { return *_modules[i]; }
    /// Stage names joined with commas: "frustum,octree".
    std::string name() const;
    bool approximate() const;

    /// Hands every stage (and every stage added later) the model's baked data; before setScene.
    void setBakedData(std::shared_ptr<const BakedData> baked);
    void setScene(const Scene& scene);
    /// Forwards to every stage; also remembers Removed objects (never reported again until an
    /// Inserted change names them).
    void sceneChanged(const SceneChange& change);
    /// The scene was re-extracted into `scene` with stable ids (VisibilityModule::sceneReplaced);
    /// Removed objects are remembered as with sceneChanged.
    void sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes);
    /// Starts from every object of the scene (less those reported Removed) and lets each stage refine;
    /// finally re-adds objects flagged OBJECT_ALWAYS_VISIBLE, and those flagged OBJECT_SLIVERS or
    /// OBJECT_UNOCCLUDABLE that are not outside the view frustum (every one, for regions). Never culls a visible object unless one
    /// of the stages is approximate.
    void cull(const View& view, VisibleSet& visible);
    const std::vector<StageTiming>& lastTimings() const { return _timings; }

    /// True when every stage answers region queries (and there is at least one).
    bool supportsRegions() const;
    /// The region query of every stage in turn, from the same start and with the same end as cull:
    /// objects some view of `region` may see. Requires supportsRegions().
    void cullRegion(const ViewRegion& region, VisibleSet& visible);
    /// The most passes of any stage (VisibilityModule::regionPasses).
    std::uint32_t regionPasses() const;
    /// cullRegion with each stage at `pass` (or its own last pass, when it has fewer).
    void cullRegionPass(const ViewRegion& region, VisibleSet& visible, std::uint32_t pass);

private:
    /// Every object less those reported Removed, then `refine` per stage, then always-visible ones
    /// and those with slivers inside `frustum` (null: all of them).
    template <class Refine> void runStages(VisibleSet& visible, const Frustum* frustum, Refine refine);
    void rememberRemoved(const SceneChange& change);
    std::vector<std::unique_ptr<VisibilityModule>> _modules;
    std::shared_ptr<const BakedData> _baked;
    std::vector<StageTiming> _timings;
    const Scene* _scene = nullptr;
    std::vector<bool> _removed; ///< per object: reported Removed and not re-inserted since
};
} // namespace osgVis::core
