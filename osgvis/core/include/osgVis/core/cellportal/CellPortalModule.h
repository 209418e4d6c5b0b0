// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Cell-and-portal visibility after Teller & Séquin, "Visibility Preprocessing for Interactive
/// Walkthroughs" / "Visibility Computations in Polyhedral Three-Dimensional Environments". Baked
/// data (a `.pvs` file, or a bake made on the spot in setScene when none is registered for the
/// scene's fingerprint) gives each cell its stab tree and PVS; at run time the eye's cell is found,
/// its stab tree walked with a small LP per portal sequence (eye-to-cell), and only PVS objects
/// that a sightline through the eye can reach are kept (eye-to-object).
/// Modes: "cellportal" (eye-to-object) and, for the paper's progressive table, "cellportal-cells"
/// (objects in cells visible from the eye's cell), "cellportal-pvs" (the eye cell's PVS) and
/// "cellportal-eyecells" (objects in cells the eye sees).
#include <osgVis/core/cellportal/CellPortalBake.h>
#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <string>

namespace osgVis::core
{
enum class CellPortalStage
{
    CellToCell,
    CellToObject,
    EyeToCell,
    EyeToObject
};

class CellPortalModule : public VisibilityModule
{
public:
    explicit CellPortalModule(CellPortalStage stage = CellPortalStage::EyeToObject, const BakeOptions& bake = {});
    ~CellPortalModule() override;
    const char* name() const override;
    void setScene(const Scene& scene) override;
    void cull(const View& view, VisibleSet& visible) override;
    /// Regions: the union of the PVS of every cell the region's eye box meets (the cell-to-object
    /// stage; no stab tree is walked, as sightlines through a box of eyes are not one LP).
    bool supportsRegions() const override { return true; }
    void cullRegion(const ViewRegion& region, VisibleSet& visible) override;
    void setDebugRecord(DebugRecord* record) override;

    /// Use these data for the next setScene instead of looking them up (they must be baked for that
    /// scene: a fingerprint mismatch makes the module bake afresh).
    void setBakedData(std::shared_ptr<const CellPortalData> data);
    /// The CellPortalData among the model's baked data (none: look them up again).
    void setBakedData(const BakedData& baked) override { setBakedData(baked.get<CellPortalData>()); }
    std::shared_ptr<const CellPortalData> bakedData() const;
    /// True when the last setScene baked on the spot (no registered data matched the scene).
    bool bakedOnTheSpot() const;
    /// True when the last setScene took data baked on the whole paged database the scene loads part
    /// of (CellPortalData::tiles), mapped to its objects by tile.
    bool usesTiledBake() const;
    /// Why such data did not serve the last scene (empty when none was tried or it did).
    const std::string& tiledBakeRefusal() const;

private:
    struct Impl;
    std::unique_ptr<Impl> _impl;
};

/// Process-wide store of baked data by scene fingerprint: the `.pvs` reader registers what it loaded
/// so that any CellPortalModule later given that scene uses it. Data baked on a whole paged database
/// are also stored by its root file's objects (findBakedCellPortalDataOfDatabase), so that a scene
/// with any of its tiles loaded finds them. Thread-safe.
void registerBakedCellPortalData(std::shared_ptr<const CellPortalData> data);
std::shared_ptr<const CellPortalData> findBakedCellPortalData(std::uint64_t fingerprint);
/// A bake of a whole paged database registered for the root file whose objects have this
/// SceneTiles::rootFingerprint (null when none).
std::shared_ptr<const CellPortalData> findBakedCellPortalDataOfDatabase(std::uint64_t rootFingerprint);
} // namespace osgVis::core
