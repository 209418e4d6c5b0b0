// SPDX-License-Identifier: MIT
#pragma once
// The Δ sweep of the mask modules (--mask-deltas): every mode with a mask stage re-run cull-only
// over the bench's views once per image-space shrinkage Δ, with the module's own statistics per
// frame: how often a frame is critical and why, what each step of a critical frame costs (select,
// rasterize, pyramid, mark: the paper's per-step timing) and what fraction of the scene is drawn.
// No GL: the chain runs on the extracted scene, as the cull-only sweeps do. The observer may walk
// the same path several times slower (--mask-slowdown), so that consecutive frames are close and
// the masks' temporal coherence shows.
#include "BenchMode.h"
#include "BenchOptions.h"
#include "BenchReport.h"

#include <osgVis/core/mask/MaskModule.h>
#include <osgVis/core/module/ModuleChain.h>
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/Walk.h>

#include <optional>
#include <string>
#include <vector>

namespace osgVis::bench
{
// The observer `slowdown` times slower along `walk`'s path: between consecutive keys a and b,
// slowdown − 1 frames with the eye moved linearly from a's eye towards b's and a's orientation
// kept (only translation happens between keys; a turn at a key stays a real turn). Every segment
// lasts slowdown times its key interval, its frames spaced by that interval (0.1 s for a generated
// walk that is not subsampled): the frame rate stays, the speed is divided by slowdown. Slowdown 1
// returns the walk unchanged. Throws std::invalid_argument for slowdown 0 and, for slowdown > 1,
// std::length_error past MaxMaskSweepFrames (BenchOptions.h).
core::Walk slowedWalk(const core::Walk& walk, unsigned slowdown);

// The observer's top speed over `walk`: max |Δeye| / Δt over consecutive keys (pairs with Δt ≤ 0
// skipped), times 1.01 against rounding, at least 1e-6. A real application knows its camera's top
// speed; the sweep gives the module this one, so stamps last exactly as long as the walk allows.
double observedMaxEyeSpeed(const core::Walk& walk);

// The options of a registered mask mode ("mask", "mask-approx", "mask-distance": whatever the
// registry builds as a core::MaskModule) with shrinkage Δ = shrinkPixels and, where given, the
// observer's top speed V = maxEyeSpeed; nullopt for any other module name.
std::optional<core::MaskOptions> maskModeOptions(const std::string& moduleName, double shrinkPixels,
                                                 std::optional<double> maxEyeSpeed = std::nullopt);
// Whether a module chain (comma form) has a mask stage.
bool hasMaskStage(const std::string& chain);
// `chain` (comma form) with every mask stage built with shrinkage Δ (and V where given); other
// stages as registered. `maskStage` receives the last mask stage (owned by the chain). Throws
// core::UnknownModeError.
core::ModuleChain createMaskChain(const std::string& chain, double shrinkPixels, core::MaskModule*& maskStage,
                                  std::optional<double> maxEyeSpeed = std::nullopt);

// One fresh chain per (mask mode, Δ) over the frames of slowedWalk(walk, slowdown), `walk` being
// the rendered pass's views (same keys, projection and viewport), with every mask stage's V set to
// observedMaxEyeSpeed of those frames (also for slowdown 1). Modes without a mask stage are
// skipped. Progress, the slowdown and V go to stderr.
std::vector<MaskSweepRow> runMaskSweep(const core::Scene& scene, const core::Walk& walk,
                                       const std::vector<BenchMode>& modes, const std::vector<double>& deltas,
                                       unsigned slowdown = 1);
} // namespace osgVis::bench
