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
// The conservative module chain with the highest frame rate and no false-invisible object, or null
// when none ran: what the demo and the report call the best mode for the scene.
const ModeResult* bestCullingMode(const std::vector<ModeResult>& modes);
// The mode results use as their baseline: `osg` when it ran, else the first mode.
const ModeResult* baselineMode(const std::vector<ModeResult>& modes);
// One line: the best mode against the baseline (fps, drawn triangles, cull ms, false-invisible), or
// empty when there is no best mode.
std::string bestModeSummary(const BenchReport& report);
} // namespace osgVis::bench
