// SPDX-License-Identifier: MIT
#pragma once
// Turns one mode's pass and the oracle's reference into the metrics of DESIGN.md.
#include "BenchReport.h"
#include "ModePass.h"
#include "OracleReference.h"

#include <osgVis/core/scene/Scene.h>

namespace osgVis::bench
{
// Everything but the cross-mode ratios (speedup_vs_osg, fps_vs_exact).
ModeResult measureMode(const BenchMode& mode, const core::Scene& scene, const OracleReference& reference,
                       const PassResult& pass);
// Fills speedup_vs_osg and fps_vs_exact from the `osg` and `exact` rows, when those ran.
void relateToBaselines(std::vector<ModeResult>& results);
} // namespace osgVis::bench
