// SPDX-License-Identifier: MIT
#pragma once
// A planar occluder region while the builder works on it: a convex loop of welded vertex ids and
// what it was made of. The builder's later steps (coplanar unions, T-junction repair, neighbour
// links) all edit regions before they become OccluderPolygons.
#include "VertexWelder.h"

#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
struct OccluderRegion
{
    std::vector<std::uint32_t> loop; ///< welded ids, counter-clockwise around `normal`
    Vec3 normal;
    ObjectId owner = InvalidObject;
    bool oneSided = false;
    std::vector<ObjectId> parts; ///< every object it covers, when more than one (ascending)
};

struct RegionUnionOptions
{
    double sceneSize = 1.0;
    double turnTolerance = 1e-6;  ///< as the coplanar merge's: sine of a bend taken as straight
    double planeTolerance = 1e-6; ///< relative off-plane distance a loop may have (isConvexLoop)
    std::uint32_t maxCorners = 32;
};

/// Adds, for the regions of objects (not stated occluders) that lie in one plane and face the
/// same way (one-sided) or either way (two-sided), the convex pieces of their union
/// (PlanarUnion.h) that unite two or more of them. The regions themselves stay, with their links
/// to neighbours in other planes, which a piece's new outline would not have. New corners on
/// input edges are welded (tightly) into `welder`. The pieces come after the object regions and
/// before the stated occluders.
void unitePlanarRegions(std::vector<OccluderRegion>& regions, VertexWelder& welder, const RegionUnionOptions& options);

/// Repairs T-junctions: a welded vertex of some region that lies on an edge of another (within
/// 1e-10 of the edge's length, away from its ends), where that edge has no exact match, is
/// inserted into that edge, so both regions share the pieces of it.
void repairTJunctions(std::vector<OccluderRegion>& regions, const std::vector<Vec3>& positions, double sceneSize);
} // namespace osgVis::core
