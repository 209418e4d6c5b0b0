// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Mode `multifocal`: visibility from volumes of viewpoints (Marsden & Guibas, §6). The eye's view
/// cell gives the answer, so every view of an eye in the cell keeps everything visible from
/// anywhere in it. With baked view cells registered for the scene (a `.pvs` file of
/// `osgvispvs --method multifocal`, read by the .pvs plugin) the cell is the baked one holding the
/// eye, and an eye outside every cell, or a view whose depth margin the bake does not hold, keeps
/// everything. Without, cells form a grid (MultifocalModuleOptions::cellSize) whose PVS are
/// computed by computeVolumePvs as the eye enters them and kept while it stays, for the views whose
/// depth margin they hold (a near-plane reach no farther, a near plane no nearer than half the one
/// computed for, as many depth bits: docs/multifocal.md, "Depth ties"); another view has its cell
/// computed again, for it and the views before. Region queries (cullRegion, and with it
/// AsyncVisibility) take the union of the baked cells' PVS when the region's box lies inside baked
/// cells and the bake's margin holds for it, else compute the PVS of the region's own box.
/// Orthographic views keep everything.
#include <osgVis/core/module/VisibilityModule.h>
#include <osgVis/core/multifocal/VolumeVisibility.h>
#include <osgVis/core/pvs/ViewCellPvs.h>

#include <memory>

namespace osgVis::core
{
/// The module's volume options: those of a bake, less the triangle tests. At run time only objects
/// count, and on a 4 × 4 × 2 m cell of the 500 k city the triangle tests cost 60 % of the time for
/// 3 % fewer objects (148 against 152).
inline MultifocalOptions moduleVolumeOptions()
{
    MultifocalOptions options;
    options.triangles = false;
    return options;
}

struct MultifocalModuleOptions
{
    MultifocalOptions volume = moduleVolumeOptions();
    /// Edge lengths of the grid's cells; a zero component means 1/100 of the scene's diagonal.
    Vec3 cellSize{0.0};
    /// A corner of one of the grid's cells (say, eye height minus half a cell above the ground).
    Vec3 cellOrigin{0.0};
    /// Cell answers kept (least recently used ones go).
    std::size_t cachedCells = 64;
};

/// View cells baked for a model (sceneFingerprint and object count) and the near-plane reach the
/// bake assumed: a view reaching farther keeps everything.
struct BakedViewCells
{
    std::uint64_t fingerprint = 0;
    std::uint32_t objectCount = 0;
    double nearDistance = 0.0;
    ViewCellPvs cells;
};

/// Process-wide store by fingerprint: the `.pvs` reader registers what it trusted, so that any
/// MultifocalModule later given that scene uses it. Thread-safe.
void registerBakedViewCells(std::shared_ptr<const BakedViewCells> cells);
std::shared_ptr<const BakedViewCells> findBakedViewCells(std::uint64_t fingerprint);

class MultifocalModule : public VisibilityModule
{
public:
    explicit MultifocalModule(const MultifocalModuleOptions& options = {});
    ~MultifocalModule() override;
    const char* name() const override { return "multifocal"; }

    /// The BakedViewCells among the model's baked data: used instead of the process-wide store's
    /// when they were baked for the scene.
    void setBakedData(const BakedData& baked) override;
    void setScene(const Scene& scene) override;
    void cull(const View& view, VisibleSet& visible) override;
    bool supportsRegions() const override { return true; }
    void cullRegion(const ViewRegion& region, VisibleSet& visible) override;
    /// Two passes (§6's progressive answer): first three planes a face and the 2000 best
    /// occluders (about half the time on the 500 k city), then the full options.
    std::uint32_t regionPasses() const override { return 2; }
    void cullRegionPass(const ViewRegion& region, VisibleSet& visible, std::uint32_t pass) override;

    /// The grid cell holding `eye` (closed box; the lower one on a boundary).
    Aabb cellOf(const Vec3& eye) const;
    /// Cell PVS computed so far by cull (not counting region queries).
    std::size_t cellsComputed() const;
    /// The baked cells the last setScene found registered for its scene, or null.
    std::shared_ptr<const BakedViewCells> bakedCells() const;
    /// Views that kept everything because no baked cell held the eye or their near plane reached
    /// farther than the bake assumed.
    std::size_t viewsOutsideBakedCells() const;

private:
    struct Impl;
    std::unique_ptr<Impl> _impl;
};
} // namespace osgVis::core
