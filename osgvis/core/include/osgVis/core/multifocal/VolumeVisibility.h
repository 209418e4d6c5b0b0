// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A potentially visible set for a *volume* of viewpoints, after Marsden & Guibas, "The multifocal
/// z-buffer" (no cells, portals or stated occluders needed): everything visible from any point of
/// an axial box V is kept. Correspondence planes parallel to V's faces carry multifocal z-buffers;
/// the scene's own opaque polygons are occluders and occludees at once (§4.5); an object or
/// triangle is culled only when one plane proves every ray from V to it blocked. Derivations and
/// the placement rule: docs/multifocal.md.
#include <osgVis/core/occluders/OccluderPolygon.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::core
{
struct MultifocalOptions
{
    /// Pixels along the longer side of each plane's window (square pixels; the paper uses 100).
    int planeResolution = 100;
    /// Planes per face of V, at depths taken from the occluders beyond that face.
    int planesPerDirection = 7;
    /// A plane's window spans rays leaving V's face up to this angle from its normal (radians).
    double maxWindowAngle = 1.0471975511965976; // 60°
    /// Occluders whose area-angle seen from V's centre is below this are not inserted (distant).
    double minAreaAngle = 1e-6;
    /// At most this many occluders are inserted per plane (the best by area-angle).
    std::uint32_t maxOccludersPerPlane = 50000;
    /// No occluder nearer to V than this is used: a near plane at that distance could clip it. The
    /// farthest reach of the near plane (a corner of its rectangle) of a view served.
    double nearDistance = 0.0;
    /// The nearest near plane, along its view axis, of a view served, and the bits of its depth
    /// buffer: what a hidden point must lie behind its occluder by, lest the two tie in depth
    /// (depthGapPerDistance2). 0: nearDistance / 8, which a view reaching nearDistance has when its
    /// widest ray (to a corner of the near rectangle) is at most 82.8° off its axis.
    double minNearDistance = 0.0;
    std::uint32_t depthBits = 24;
    /// Test the triangles of objects whose bounds are not hidden: an object all of whose
    /// triangles are hidden is culled, and the statistics count hidden triangles.
    bool triangles = true;
    /// Coverage-map pieces kept per pixel (the lowest goes beyond it).
    std::uint32_t maxFragmentsPerPixel = 8;

    /// The options as `key=value` pairs: what a `.pvs` file records, so that ranges baked with
    /// other options are refused when merged.
    std::string canonical() const;
};

struct VolumeStatistics
{
    std::uint32_t planes = 0;
    std::uint64_t occludersInserted = 0;
    std::uint64_t objectsCulled = 0;
    std::uint64_t trianglesTested = 0;
    std::uint64_t trianglesCulled = 0;     ///< hidden, in culled objects or on their own
    std::uint64_t trianglesBackFacing = 0; ///< facing away from every point of V
    std::uint64_t trianglesBackFacingNotCulled = 0;
};

struct VolumePvs
{
    VisibleSet objects;                        ///< capacity = object count: the PVS
    std::vector<std::uint8_t> hiddenTriangles; ///< per Scene::triangles entry, 1 = culled; empty unless triangles
    VolumeStatistics statistics;
};

/// The nearest near plane of a view `options` serves: minNearDistance, else nearDistance / 8.
double nearestNearPlane(const MultifocalOptions& options);
/// The gap in h, per squared distance from V, that a point must lie behind its occluder for the
/// views `options` serves to draw the occluder in front (eight steps of their depth buffer at
/// nearestNearPlane: docs/multifocal.md, "Depth ties"); 0 when no near plane is known.
double depthGapPerDistance2(const MultifocalOptions& options);

/// The occluders a volume PVS uses: the scene's polygons (buildOccluderPolygons) and the sections
/// through its closed convex objects (convexSolidSections).
std::vector<OccluderPolygon> volumeOccluders(const Scene& scene);

/// The PVS of `volume` (non-empty, finite). `occluders` come from volumeOccluders(scene) (or any
/// subset); a section inside a solid is used only when V lies outside its object's bounds.
/// Objects DYNAMIC or ALWAYS_VISIBLE are always kept. Deterministic: the answer
/// depends only on the arguments. Throws std::invalid_argument for an empty or non-finite volume.
VolumePvs computeVolumePvs(const Scene& scene, const std::vector<OccluderPolygon>& occluders, const Aabb& volume,
                           const MultifocalOptions& options = {});
} // namespace osgVis::core
