// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Where the correspondence planes of one face of V go (Marsden & Guibas, §4.5: several planes,
/// the PVS passed from one to the next): at depths where the occluders beyond that face are, and
/// with a window that spans the footprints of what is to be tested there.
#include "CorrespondencePlane.h"

#include <vector>

namespace osgVis::core
{
/// V's face at `axis`, `direction` (+1: its max side) and the depth of x beyond it.
struct VolumeFace
{
    int axis = 0, direction = 1;
    double coordinate = 0.0;
    double depth(const Vec3& x) const { return direction * (x[axis] - coordinate); }
};

struct DepthSample
{
    double depth = 0.0;  ///< of an occluder's centroid beyond the face
    double weight = 0.0; ///< its area-angle from V
};

/// Depths (>= minDepth) of `count` planes: the weighted quantiles of the samples at the first
/// `count` dyadic fractions (1/2, 1/4, 3/4, 1/8, ...), ascending, repeated ones removed.
std::vector<double> planeDepths(std::vector<DepthSample> samples, int count, double minDepth);

/// The plane at `depth` beyond `face`, with a window that holds the footprints of `occludees`
/// (boxes wholly beyond the face) as far as the angle limit allows, and `resolution` pixels along
/// its longer side. width == 0 when no window is left.
CorrespondencePlane placePlane(const VolumeFace& face, const Aabb& volume, double depth,
                               const std::vector<Aabb>& occludees, double maxAngle, int resolution);
} // namespace osgVis::core
