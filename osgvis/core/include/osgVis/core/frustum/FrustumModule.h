// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Hierarchical view-frustum culling over a kd-tree: the baseline every occlusion module must beat.
#include <osgVis/core/spatial/KdTree.h>
#include <osgVis/core/module/ChangedObjects.h>
#include <osgVis/core/module/VisibilityModule.h>

namespace osgVis::core
{
class FrustumModule : public VisibilityModule
{
public:
    const char* name() const override { return "frustum"; }
    void setScene(const Scene& scene) override;
    /// Moved and inserted objects are tested on their own until a quarter of the objects changed
    /// (then the tree is rebuilt): time that grows with the change, not the scene.
    void sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes) override;
    /// Never culls a visible object: keeps every object whose bounds are not entirely outside one
    /// frustum plane.
    void cull(const View& view, VisibleSet& visible) override;
    /// A region looks in every direction: the frustum stage keeps everything (the renderer
    /// intersects the region's answer with each view's frustum).
    bool supportsRegions() const override { return true; }
    void cullRegion(const ViewRegion&, VisibleSet&) override {}

private:
    KdTree _tree;
    ChangedObjects _changed; ///< since the tree was built: left out of its answer
    std::vector<std::uint32_t> _stack; ///< reused per query: no allocation after warm-up
};
} // namespace osgVis::core
