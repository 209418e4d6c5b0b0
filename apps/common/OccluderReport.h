// SPDX-License-Identifier: MIT
#pragma once
// Which objects of a model may stand in as occluders and why the others may not (transparent,
// alpha test, polygon mode, no depth write, under LOD/Switch, dynamic, degenerate, too small), how
// many occluder polygons the object-space methods get, and how many objects have bounds far larger
// than what they draw: the model's side of "why does it not cull" (osgvisbench --explain, the
// viewer's e key).
#include <osgVis/SceneExtractor>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::apps
{
struct OccluderReport
{
    std::size_t objects = 0;
    std::uint64_t triangles = 0;
    std::vector<std::pair<std::string, std::size_t>> notOccluders; // reason, objects; most first
    std::size_t occluderObjects = 0;  // objects that yield at least one occluder polygon
    std::size_t occluderPolygons = 0; // what the object-space occluder builder makes of the scene
    std::size_t hugeBounds = 0;       // objects whose bounds span more than half the model's diagonal
};

// `scene` must keep its triangles.
OccluderReport reportOccluders(const ExtractedScene& scene);
void writeOccluderReport(std::ostream& out, const OccluderReport& report);
} // namespace osgVis::apps
