// SPDX-License-Identifier: MIT
#pragma once
// Occluder selection of the mask method: a priority queue over kd-tree nodes (or the nodes of the
// renderer's hierarchy as recorded), nearest first from the eye, gathers candidate occluder
// objects inside the view; the best R by the chosen measure
// become the critical frame's occluders.
//
// Coverage importance (our reading of the paper's φ): φ(ξ) = min over sampled eyes s of
// coverage_s(ξ) × mindist_s(ξ), where coverage is the fraction of the frame the object's box covers
// and mindist its distance from s; the samples are the eye and the six points δ away along the
// axes, so an occluder is valued by what it still does anywhere in the region the mask must serve.
// Multiplying by the distance prefers occluders that keep δ (and so the stamps' lifetime) large.
#include "MaskProjection.h"

#include <osgVis/core/mask/MaskKdTree.h>
#include <osgVis/core/mask/MaskModule.h>
#include <osgVis/core/spatial/HierarchyIndex.h>

#include <vector>

namespace osgVis::core
{
struct MaskSelectionInput
{
    const MaskKdTree* tree = nullptr;
    const HierarchyIndex* hierarchy = nullptr; // when set: its recorded nodes instead of `tree`
    const std::vector<SceneObject>* objects = nullptr;
    const std::vector<std::uint8_t>* usable = nullptr; // per object: may be an occluder now
    const View* view = nullptr;
    const MaskProjection* projection = nullptr;
    Vec3 eye{0.0};
    double minDistance = 0.0;  // D
    double sampleRadius = 0.0; // δ of the previous critical frame, for the φ samples
    std::uint32_t count = 64;  // R
    OccluderMeasure measure = OccluderMeasure::CoverageImportance;
};

// Buffers of the selection, kept between critical frames so a warm one allocates nothing.
struct MaskSelectionScratch
{
    struct Entry
    {
        double distance;
        std::uint32_t node;
        // A min-heap by distance (ties by node id) under std::push_heap's max-heap order.
        bool operator<(const Entry& o) const { return distance > o.distance || (distance == o.distance && node > o.node); }
    };
    std::vector<Entry> queue;
    std::vector<std::pair<double, ObjectId>> candidates;
};

// Object ids into `chosen`, best first. Deterministic.
void selectMaskOccluders(const MaskSelectionInput& input, MaskSelectionScratch& scratch, std::vector<ObjectId>& chosen);
} // namespace osgVis::core
