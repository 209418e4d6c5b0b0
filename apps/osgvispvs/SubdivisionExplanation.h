// SPDX-License-Identifier: MIT
#pragma once
// osgvispvs --explain: what the cell subdivision found in the model, and what the model would have
// to state for (more) cells to come out.
#include <osgVis/core/cellportal/CellSubdivision.h>

#include <ostream>

namespace osgVis::pvstool
{
void explainSubdivision(const core::Scene& scene, const core::SubdivisionOptions& options, std::ostream& out);
} // namespace osgVis::pvstool
