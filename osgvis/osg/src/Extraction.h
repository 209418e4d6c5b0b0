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

// Node types whose cull traversal draws exactly their drawables, nothing else, entering every child
// whose mask is valid (see ChildRange::closed).
bool plainNodeType(const osg::Node& node);
// A drawable without cull callback, or with only osgVis's own that chains none.
bool plainCullCallback(const osg::Drawable& drawable);

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

// A drawable's bounds in the root frame (`world`: its local → root matrix) and its triangle count;
// with `triangles`, its triangles there appended (counter-clockwise seen from their drawn front).
struct DrawablePlacement
{
    core::Aabb bounds;
    bool nonFinite = false;    ///< a vertex is not finite there: the object is always visible
    std::uint32_t counted = 0; ///< triangles drawn
    std::uint32_t stored = 0;  ///< triangles appended (those with a non-finite corner are not)
};
DrawablePlacement placeDrawable(osg::Drawable& drawable, const osg::Matrixd& world, bool clockwiseFront,
                                std::vector<core::Triangle>* triangles);
// True when a triangle the drawable draws is a sliver (core::isSliverTriangle).
bool hasSlivers(osg::Drawable& drawable);

// `previous` with the objects below the `moved` transforms placed again (world matrix, bounds,
// triangles), reported Moved and replacing it: a frame whose only change is matrices costs what moved,
// not a re-extraction (docs/changes.md). Null where it cannot: clustered drawables, paged nodes,
// stand-alone occluders, cells or portals in the scene, or a triangle that turned non-finite.
osg::ref_ptr<ExtractedScene> moveObjects(const ExtractedScene& previous, const std::vector<const osg::Node*>& moved,
                                         const ExtractionOptions& options);

// Warns about each of `scene`'s oversized tiles that `previous` (may be null) did not list.
void warnOversizedTiles(const ExtractedScene& scene, const ExtractedScene* previous);
} // namespace osgVis
