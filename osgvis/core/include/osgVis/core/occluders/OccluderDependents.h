// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Per object, the occluder polygons resting on it: those it owns and the coplanar unions it is a
/// part of. When an object moves or goes, exactly these stop standing for what is drawn.
#include <osgVis/core/occluders/OccluderPolygon.h>
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
class OccluderDependents
{
public:
    /// Indexes `polygons` over objects [0, objectCount); no polygon is disabled.
    void build(const std::vector<OccluderPolygon>& polygons, std::size_t objectCount);
    /// Marks every polygon resting on `id` disabled (objects beyond those indexed have none).
    void disableAll(ObjectId id);
    bool disabled(std::uint32_t polygon) const { return _disabled[polygon] != 0; }

private:
    std::vector<std::uint32_t> _first; // per object: its polygons are _polygons[_first[id], _first[id + 1])
    std::vector<std::uint32_t> _polygons;
    std::vector<std::uint8_t> _disabled; // per polygon
};

/// True when both lists state the same occluders (owners and vertices, in order): polygons built
/// from one stand for the other.
bool sameOccluderCandidates(const std::vector<OccluderCandidate>& a, const std::vector<OccluderCandidate>& b);
} // namespace osgVis::core
