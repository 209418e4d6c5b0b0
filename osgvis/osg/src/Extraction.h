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
// Flags the placeholder always visible, and lists the tile in out.oversizedTiles, when an object of
// ids [from, end) below it (its paths hold the paged node at `depth`) reaches outside its box.
void checkWithinStatedBound(ExtractedScene& out, core::ObjectId placeholder, std::size_t depth, core::ObjectId from);

// Warns about each of `scene`'s oversized tiles that `previous` (may be null) did not list.
void warnOversizedTiles(const ExtractedScene& scene, const ExtractedScene* previous);
} // namespace osgVis
