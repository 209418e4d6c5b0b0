// SPDX-License-Identifier: MIT
#pragma once
// One bake as the unit runners see it, whatever the method: the cells, an estimate of each cell's
// cost, the range file of any unit, whether a file read back is that unit's result, joining the
// units' files into the output, and the closing report. Every rank of an MPI bake builds the same
// job from the same command line and model (deterministically), so a unit means the same anywhere.
#include "BakeUnits.h"
#include "PvsToolOptions.h"

#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/pvs/ViewCellMerge.h>
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace osgVis::pvstool
{
// What the closing report says about this run beside the baked data.
struct BakeRunFigures
{
    double seconds = 0.0;           ///< this run's wall-clock time
    double joinSeconds = 0.0;       ///< of which reading the units' files, joining and writing the output
    std::uint32_t unitsBaked = 0;   ///< by this run
    std::uint32_t unitsResumed = 0; ///< found finished in the state folder
    int ranks = 1;
};

class BakeJob
{
public:
    virtual ~BakeJob() = default;
    /// Cells of the whole layout, and the range this command bakes (--cells, --shard, or all).
    virtual std::uint32_t cellCount() const = 0;
    virtual std::pair<std::uint32_t, std::uint32_t> cellsToBake() const = 0;
    /// Units when --unit-cells is not given: enough to balance many ranks, few enough that the
    /// state folder stays small (a cell-portal unit file repeats the subdivision).
    virtual std::uint32_t defaultUnitCount() const = 0;
    virtual std::vector<double> cellCosts() const = 0;
    /// The range file of cells [first, end), baked on the calling thread's task arena. Thread-safe.
    virtual core::PvsFile bakeUnit(std::uint32_t first, std::uint32_t end) const = 0;
    /// Why `file` (read back from the state folder or received from a rank) is not this bake's
    /// result for `unit`; empty when it is.
    virtual std::string mismatch(const core::PvsFile& file, const BakeUnit& unit) const = 0;
    /// The output from every unit's file (ascending cells), named for `pvsFile`.
    virtual core::PvsFile join(std::vector<core::PvsFile>&& units, const std::string& pvsFile) const = 0;
    /// Prints the statistics (and writes --json) for the written output.
    virtual void report(const core::PvsFile& output, const BakeRunFigures& run) const = 0;
};

/// The cell-portal bake (subdivision and stab trees) and the multifocal view-cell bake of `scene`
/// for the command line `o`. Throw ToolError for what the command cannot bake (bad cells, ranges).
std::unique_ptr<BakeJob> makeCellPortalJob(const PvsToolOptions& o, const core::Scene& scene);
std::unique_ptr<BakeJob> makeViewCellJob(const PvsToolOptions& o, const core::Scene& scene);

/// Empty when `file` was baked for the same model and bake as `identity` (fingerprints, object
/// count, method, options, near distance), else what differs; shared by both jobs.
std::string bakeIdentityMismatch(const core::PvsFile& file, const core::PvsFile& identity);
/// The output from the units' range files: `merge` (mergeCellPortalPvs or mergeViewCellPvs), every
/// cell required when the command bakes them all, the model named relative to `pvsFile`.
core::PvsFile joinUnitFiles(core::PvsFile (*merge)(const std::vector<core::PvsFile>&, const core::ViewCellMergeOptions&),
                            const std::vector<core::PvsFile>& units, bool allCells, const std::string& modelFile,
                            const std::string& pvsFile);
/// The range [first, end) the command asks for within `total` cells (--cells or --shard), checked.
std::pair<std::uint32_t, std::uint32_t> requestedCells(const PvsToolOptions& o, std::uint32_t total, const char* what);
} // namespace osgVis::pvstool
