// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Joining the range files of one view-cell bake (each baked the cells A..B of the same model with
/// the same method and options, say on several machines) into one `.pvs` content.
#include <osgVis/core/pvs/PvsFormat.h>

#include <string>
#include <vector>

namespace osgVis::core
{
struct ViewCellMergeOptions
{
    /// Refuse a result that lacks any cell 0..totalCells-1 of the bake.
    bool requireAllCells = false;
    /// What messages call each input, e.g. its file name; where missing, "input 1", "input 2", ...
    std::vector<std::string> inputNames;
};

/// The view cells of all `ranges` in ascending absolute index, with the model, build identity and
/// total cell count they share (and the first input's model path). Throws PvsFormatError naming the
/// inputs at fault when there is no input, an input holds no view cells or holds cell-portal data,
/// the inputs were baked for other models (fingerprints, object count) or in other bakes (method,
/// options, near distance, total cells), a cell comes twice, or, with requireAllCells, one is
/// missing.
PvsFile mergeViewCellPvs(const std::vector<PvsFile>& ranges, const ViewCellMergeOptions& options = {});
} // namespace osgVis::core
