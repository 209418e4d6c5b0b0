// SPDX-License-Identifier: MIT
#pragma once
// The exact visible set E(v) of every bench view, from the ID-buffer oracle rendering the real
// graph at the same matrices and resolution, translated into the adapter's object ids. Runs once,
// untimed, before the modes.
#include "BenchView.h"

#include <osgVis/SceneExtractor>
#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <vector>

namespace osgVis::bench
{
// One object's pixels in the oracle's exact ID image at the display resolution.
struct ObjectPixels
{
    core::ObjectId id = core::InvalidObject; // InvalidObject: unknown to the extraction
    std::uint32_t pixels = 0;
    // A clustered drawable's pixels stand for its clusters [id, id + clusters) (docs/clusters.md):
    // the ID buffer cannot tell them apart.
    std::uint32_t clusters = 1;
};

struct ViewReference
{
    core::VisibleSet exact;     // E(v) in scene ids
    core::VisibleSet inFrustum; // objects whose world bounds are not entirely outside the frustum
    // Objects the oracle saw that the extraction does not know: no mode can draw them as objects, so
    // they count as false-invisible for every mode.
    std::uint32_t unknownVisible = 0;
    // Every object with a pixel in the display-resolution image (empty unless OracleReference::
    // pixelCounts); objects found only by the supersampled render have none here.
    std::vector<ObjectPixels> pixels;
};

struct OracleReference
{
    std::vector<ViewReference> views;
    unsigned supersample = 1;
    bool pixelCounts = false; // the oracle counts pixels per object (IdBufferOracle::Result::pixels)
    std::vector<std::uint32_t> viewsWithSupersampleExtras; // views where the K× render found more
    std::uint64_t supersampleExtras = 0;                   // objects found only at K×, all views
};

// Needs a display (Xvfb). Warns on stderr about oracle objects the extraction does not know.
OracleReference computeOracleReference(osg::Node& root, const ExtractedScene& scene,
                                       const std::vector<BenchView>& views, unsigned width, unsigned height,
                                       unsigned supersample);

// Sets every view's inFrustum (objects whose world bounds are not entirely outside its frustum).
void addFrustumSets(OracleReference& reference, const core::Scene& scene, const std::vector<BenchView>& views);
} // namespace osgVis::bench
