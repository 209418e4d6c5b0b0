// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Occluders inside closed convex objects (trunks, branches, leaf clumps, boxes): a convex object
/// whose triangles close up with one orientation hides, from any eye outside it, everything that
/// any polygon inside it hides, since a sightline from outside reaches the inside only through the
/// surface. Its sections through its centroid perpendicular to the three axes are such polygons,
/// far larger than any of its faces (the way Umbra builds occluders from a solid's inside, and
/// the "planar sections" of docs/occluders.md). Derivation: docs/multifocal.md, "Solid sections".
#include <osgVis/core/occluders/OccluderPolygon.h>

namespace osgVis::core
{
struct SolidSectionOptions
{
    /// Objects with more triangles are not examined (the convexity test is quadratic).
    std::uint32_t maxTriangles = 4096;
    /// Vertices may stand this far (relative to the object's size) outside a face's plane and the
    /// object still counts as convex.
    double convexTolerance = 1e-6;
};

/// For every object eligible as an occluder (static, opaque, drawn side) whose triangles form a
/// closed (every edge used once in each direction), convex mesh oriented all outwards (then it
/// must not be OBJECT_CULL_FRONT) or all inwards (then not OBJECT_CULL_BACK): up to three
/// sections, two-sided, insideSolid, owner = the object, shrunk a little towards their centroid so
/// that rounding keeps them inside. Deterministic, in object order.
std::vector<OccluderPolygon> convexSolidSections(const Scene& scene, const SolidSectionOptions& options = {});
} // namespace osgVis::core
