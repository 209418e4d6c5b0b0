// SPDX-License-Identifier: MIT
#pragma once
// Internal: the extraction extractScene, reextractScene and updatePagedScene run, and the warning about loaded
// tiles that reach outside their paged node's stated bound, which each new tile gets once.
#include <osgVis/SceneExtractor>

namespace osgVis
{
// extractScene without its warnings.
osg::ref_ptr<ExtractedScene> extractSceneQuietly(osg::Node& root, const ExtractionOptions& options);

// Appends to `out` what a full extraction from prefix.front() finds below `child`, reached through
// `prefix` (the root .. child's parent).
void extractBelow(ExtractedScene& out, const osg::NodePath& prefix, osg::Node& child, const ExtractionOptions& options);

// Paged nodes (PagedLOD, ProxyNode): whether the node states its bound (a user centre and radius),
// whether that bound covers the children still to load, and the file of a child.
bool boundStated(const osg::Group& node);
bool boundCoversAllChildren(const osg::Group& node);
std::string tileFile(const osg::Group& node, unsigned child);
// How many children the node names files for (PagedLOD, ProxyNode; 0 for other groups).
unsigned pagedFileCount(const osg::Group& node);
// Sets out.scene.tiles from the objects' paths (null when no paged node was met, or when two paged
// nodes load the same file, which no key could tell apart): what a bake on the whole database
// records and what maps it onto a scene with some tiles loaded (docs/paging.md).
void assignTileKeys(ExtractedScene& out);
// Flags the placeholder always visible, and lists the tile in out.oversizedTiles, when an object of
// ids [from, end) below it (its paths hold the paged node at `depth`) reaches outside its box.
void checkWithinStatedBound(ExtractedScene& out, core::ObjectId placeholder, std::size_t depth, core::ObjectId from);

// Warns about each of `scene`'s oversized tiles that `previous` (may be null) did not list.
void warnOversizedTiles(const ExtractedScene& scene, const ExtractedScene* previous);
} // namespace osgVis
