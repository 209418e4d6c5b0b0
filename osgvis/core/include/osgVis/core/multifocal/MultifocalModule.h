// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Mode `multifocal`: visibility from volumes of viewpoints (Marsden & Guibas, §6). The eye's view
/// cell gives the answer — its PVS, computed by computeVolumePvs for the cell, kept while the eye
/// stays in it — so every view of an eye in the cell keeps everything visible from anywhere in it.
/// Cells form a grid (MultifocalModuleOptions::cellSize); region queries (cullRegion, and with it
/// AsyncVisibility) compute the PVS of the region's own box. Orthographic views keep everything.
#include <osgVis/core/module/VisibilityModule.h>
#include <osgVis/core/multifocal/VolumeVisibility.h>

#include <memory>

namespace osgVis::core
{
struct MultifocalModuleOptions
{
    MultifocalOptions volume;
    /// Edge lengths of the grid's cells; a zero component means 1/100 of the scene's diagonal.
    Vec3 cellSize{0.0};
    /// A corner of one of the grid's cells (say, eye height minus half a cell above the ground).
    Vec3 cellOrigin{0.0};
    /// Cell answers kept (least recently used ones go).
    std::size_t cachedCells = 64;
};

class MultifocalModule : public VisibilityModule
{
public:
    explicit MultifocalModule(const MultifocalModuleOptions& options = {});
    ~MultifocalModule() override;
    const char* name() const override { return "multifocal"; }

    void setScene(const Scene& scene) override;
    void cull(const View& view, VisibleSet& visible) override;
    bool supportsRegions() const override { return true; }
    void cullRegion(const ViewRegion& region, VisibleSet& visible) override;
    /// Two passes (§6's progressive answer): first coarse planes (64 pixels, one per face, no
    /// triangle tests, the 2000 best occluders), then the full options.
    std::uint32_t regionPasses() const override { return 2; }
    void cullRegionPass(const ViewRegion& region, VisibleSet& visible, std::uint32_t pass) override;

    /// The grid cell holding `eye` (closed box; the lower one on a boundary).
    Aabb cellOf(const Vec3& eye) const;
    /// Cell PVS computed so far by cull (not counting region queries).
    std::size_t cellsComputed() const;

private:
    struct Impl;
    std::unique_ptr<Impl> _impl;
};
} // namespace osgVis::core
