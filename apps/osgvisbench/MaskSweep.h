#pragma once
// The Δ sweep of the mask modules (--mask-deltas): every mode with a mask stage re-run cull-only
// over the bench's views once per image-space shrinkage Δ, with the module's own statistics per
// frame: how often a frame is critical and why, what each step of a critical frame costs (select,
// rasterize, pyramid, mark: the paper's per-step timing) and what fraction of the scene is drawn.
// No GL: the chain runs on the extracted scene, as the cull-only sweeps do.
#include "BenchMode.h"
#include "BenchReport.h"

#include <osgVis/core/MaskModule.h>
#include <osgVis/core/ModuleChain.h>
#include <osgVis/core/Scene.h>
#include <osgVis/core/Walk.h>

#include <optional>
#include <string>
#include <vector>

namespace osgVis::bench
{
// The options of a registered mask mode ("mask", "mask-approx", "mask-distance": whatever the
// registry builds as a core::MaskModule) with shrinkage Δ = shrinkPixels; nullopt for any other
// module name.
std::optional<core::MaskOptions> maskModeOptions(const std::string& moduleName, double shrinkPixels);
// Whether a module chain (comma form) has a mask stage.
bool hasMaskStage(const std::string& chain);
// `chain` (comma form) with every mask stage built with shrinkage Δ; other stages as registered.
// `maskStage` receives the last mask stage (owned by the chain). Throws core::UnknownModeError.
core::ModuleChain createMaskChain(const std::string& chain, double shrinkPixels, core::MaskModule*& maskStage);

// One fresh chain per (mask mode, Δ) over `walk`'s views (the rendered pass's views: same keys,
// projection and viewport). Modes without a mask stage are skipped. Progress goes to stderr.
std::vector<MaskSweepRow> runMaskSweep(const core::Scene& scene, const core::Walk& walk,
                                       const std::vector<BenchMode>& modes, const std::vector<double>& deltas);
} // namespace osgVis::bench
