// SPDX-License-Identifier: MIT
#pragma once
// A scene written as a paged database (docs/paging.md): its drawables cut into tiles on a grid, one
// .osgb file per tile, and a root file holding one osg::PagedLOD per tile that states the tile's
// bounding sphere (a user-defined centre and radius) and, as user values, its bounding box, and
// loads it within a range. Stock osgviewer pages it with OSG's DatabasePager.
#include <osg/Node>

#include <cstdint>
#include <string>

namespace osgVis::gen
{
struct PagedOptions
{
    unsigned tiles = 256;  ///< at most this many grid cells (as square as that allows) over the scene's two widest axes; empty ones are left out
    double range = 0.0;    ///< a tile loads while the eye is nearer its centre than this; 0: any distance
};

struct PagedSummary
{
    std::size_t tiles = 0;      ///< tile files written
    std::size_t drawables = 0;  ///< drawable instances placed in them
    std::uint64_t bytes = 0;    ///< of all files, the root's included
    std::string rootPath;       ///< DIR/root.osgb
    std::string culledPath;     ///< DIR/culled.osgt: root.osgb under an osgVis::VisibilityGroup ("octree")
};

// Writes `scene` into the existing directory `dir` as DIR/root.osgb and DIR/tile_NNNN.osgb, and
// DIR/culled.osgt, which holds root.osgb (a ProxyNode) under an osgVis::VisibilityGroup. Each
// drawable instance goes whole into the tile of its bound's centre, in a geode of its own under one
// transform holding its path's matrix and the merged state sets of its path (node masks, data
// variance and marker nodes are not kept). Throws
// std::runtime_error naming the file that could not be written.
PagedSummary writePagedScene(osg::Node& scene, const std::string& dir, const PagedOptions& options = {});
} // namespace osgVis::gen
