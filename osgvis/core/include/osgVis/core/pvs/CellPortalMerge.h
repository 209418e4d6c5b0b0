// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Joining the range files of one cell-portal bake (each baked source cells A..B of the same
/// subdivision, PvsFile::sourceRange) into one `.pvs` content.
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/pvs/ViewCellMerge.h>

#include <vector>

namespace osgVis::core
{
/// The sources of all `ranges` in one file with the graph they share (and the first input's model
/// path), its statistics counted afresh: byte for byte the file one whole bake writes. An input
/// without sourceRange counts as holding every source. When the inputs do not hold every source,
/// the result is itself a range file if their sources are contiguous (an error otherwise, and
/// always with requireAllCells). Throws PvsFormatError naming the inputs at fault for no input, an
/// input without cell-portal data or with view cells, other models, other bakes (method, options,
/// near distance, subdivision), or a source cell in two inputs.
PvsFile mergeCellPortalPvs(const std::vector<PvsFile>& ranges, const ViewCellMergeOptions& options = {});
} // namespace osgVis::core
