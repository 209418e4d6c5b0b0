// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Renderer-independent scene model: the objects a visibility module culls, the triangles they are
/// made of, occluder candidates, and cells/portals where a modeller stated them.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/geometry/ConvexPolygon.h>
#include <osgVis/core/geometry/WingedEdgeMesh.h>
#include <osgVis/core/scene/NamedAttributes.h>
#include <osgVis/core/scene/SceneTiles.h>
#include <osgVis/core/scene/TraversalHierarchy.h>

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace osgVis::core
{
constexpr ObjectId InvalidObject = ~ObjectId(0);

/// World space, counter-clockwise seen from the side the renderer treats as front.
struct Triangle
{
    Vec3f a, b, c;
};

/// A sliver: three distinct corners on one line up to their float storage (height below 10⁻⁶ of
/// the longest edge plus eight float epsilons of the largest coordinate magnitude), whose pixels
/// the rasterizer may give any depth (docs/occluders.md, "Sliver triangles"). A triangle with a
/// repeated corner is none: it draws nothing.
bool isSliverTriangle(const Triangle& triangle);
/// True when one of the `count` triangles at `triangles` is a sliver: their object is OBJECT_SLIVERS.
bool hasSliverTriangle(const Triangle* triangles, std::size_t count);

enum ObjectFlags : std::uint32_t
{
    OBJECT_NONE = 0,
    /// Moves or changes: never an occluder, never culled by precomputed data.
    OBJECT_DYNAMIC = 1u << 0,
    /// Stated occluder (osgVis::Occluder marker above it): its polygons are occluder candidates.
    OBJECT_OCCLUDER = 1u << 1,
    /// Blended / transparent: draws but never occludes.
    OBJECT_TRANSPARENT = 1u << 2,
    /// Bounds unknown or not finite (NaN/inf geometry): no module may cull it; ModuleChain keeps it.
    OBJECT_ALWAYS_VISIBLE = 1u << 3,
    /// Drawn, but its triangles may not stand in as automatic occluders: alpha test or discard,
    /// lines/points polygon mode, no depth write, or placed under a node that may not draw it
    /// every frame (LOD, Switch, Sequence, ...).
    OBJECT_NO_AUTO_OCCLUDER = 1u << 4,
    /// Face culling in its drawn state: back faces (counter-clockwise triangles are front faces,
    /// triangles are stored so) or front faces are not drawn, so they hide nothing from that side.
    OBJECT_CULL_BACK = 1u << 5,
    OBJECT_CULL_FRONT = 1u << 6,
    /// Has a sliver triangle (three distinct corners on one line up to float storage, e.g.
    /// collinear corners in a fan): the rasterizer may give its pixels any depth, so it can
    /// show through whatever stands in front (docs/occluders.md, "Sliver triangles"). No module's
    /// occlusion may hide it; ModuleChain keeps it wherever the view frustum may hold it.
    OBJECT_SLIVERS = 1u << 7,
    /// Drawn without a depth test that nearer geometry could fail (depth test off, a depth function
    /// other than LESS, LEQUAL or EQUAL, a depth range other than [0, 1]: markers, labels, x-ray
    /// highlights): no occlusion may hide it, whatever stands in front; ModuleChain keeps it wherever
    /// the view frustum may hold it.
    OBJECT_UNOCCLUDABLE = 1u << 8,
};

/// Every ObjectFlags bit. The C interface checks its OSGVIS_OBJECT_* list against this one
/// (static_asserts in src/visapi/RendererCalls.cpp): a flag added above goes in here and in
/// osgVis/visapi.h too.
constexpr std::uint32_t OBJECT_ALL_FLAGS = OBJECT_DYNAMIC | OBJECT_OCCLUDER | OBJECT_TRANSPARENT |
                                           OBJECT_ALWAYS_VISIBLE | OBJECT_NO_AUTO_OCCLUDER | OBJECT_CULL_BACK |
                                           OBJECT_CULL_FRONT | OBJECT_SLIVERS | OBJECT_UNOCCLUDABLE;

struct SceneObject
{
    ObjectId id = InvalidObject; ///< equals the object's index in Scene::objects
    Aabb bounds;                 ///< world space
    std::uint32_t triangleCount = 0;
    std::uint32_t firstTriangle = 0; ///< into Scene::triangles; triangleCount entries (may be 0 if not kept)
    std::uint32_t flags = OBJECT_NONE;
    std::string name; ///< for reports and debugging only
    /// For a cluster of a drawable the renderer split into several objects (docs/clusters.md): a
    /// label its clusters share (the adapter uses the drawable's first cluster id), so occluder
    /// polygons are still built over the whole drawable and name the clusters they lie on
    /// (OccluderPolygon::parts). InvalidObject for an object that is not a cluster.
    ObjectId group = InvalidObject;
};

/// A polygon that may hide what lies behind it (world space). `owner` is the object it belongs to,
/// or InvalidObject for a stand-alone occluder stated by a marker node.
struct OccluderCandidate
{
    ConvexPolygon polygon;
    ObjectId owner = InvalidObject;
};

struct Cell
{
    std::uint32_t id = 0;
    Aabb bounds;
    std::string name;
};

struct Portal
{
    ConvexPolygon polygon;
    std::uint32_t cellA = 0, cellB = 0;
};

/// A box of space a model proves solid (docs/cellportal.md, "Solid space"): a convex solid of the
/// model (a Quake 3 brush, say) that only its faces let a sightline into. Bit 2*axis (low face) or
/// 2*axis+1 (high face) of `opaqueFaces` says the face is drawn opaque, from both sides, wherever
/// it faces open space that eyes can reach (SolidSpace::eyePoints); a face without its bit (never
/// drawn, sky, translucent) lets sightlines in.
struct SolidBox
{
    Aabb box;
    std::uint8_t opaqueFaces = 0;
};

/// What a model states about solid space, for cells and portals made from it (subdivideCells with
/// SubdivisionOptions::fromSolids). Empty when the model states nothing: then nothing is solid.
struct SolidSpace
{
    std::vector<SolidBox> boxes;
    /// Points in space an eye can reach (a level's spawn points): only open space connected to one
    /// of them, and not to the outside of the model's bounds, counts as where drawn faces are kept
    /// (a level compiler drops faces that face the outside). With none, no face is trusted.
    std::vector<Vec3> eyePoints;
    /// Bounds of other solids the model has but that prove nothing here (not boxes, or of
    /// uncertain kind): a level compiler may have dropped the parts of faces they cover, so no face
    /// of a box is trusted where it meets one of them.
    std::vector<Aabb> unproven;

    bool empty() const { return boxes.empty(); }
};

struct Scene
{
    std::vector<SceneObject> objects;
    std::vector<Triangle> triangles; ///< may be empty when the source keeps no triangles
    std::vector<OccluderCandidate> occluders;
    std::vector<Cell> cells;
    std::vector<Portal> portals;
    /// Solid space the model proves (for cells and portals from it; the per-frame modules ignore it).
    SolidSpace solids;
    /// The renderer's own hierarchy over the objects, when it hands one to the modules (may be null).
    std::shared_ptr<const TraversalHierarchy> hierarchy;
    /// Connectivity a renderer supplied, per object (checked, not trusted: WingedEdgeMesh::closed).
    std::unordered_map<ObjectId, WingedEdgeMesh> meshes;
    NamedAttributes attributes;
    /// For a paged database: the tile each object came from (null for a scene that pages nothing).
    std::shared_ptr<const SceneTiles> tiles;

    Aabb bounds() const;
    std::uint64_t totalTriangles() const;
    /// Indices [first, end) into `triangles` of an object's triangles, clipped to what `triangles`
    /// holds (empty when the source kept none).
    std::pair<std::size_t, std::size_t> trianglesOf(const SceneObject& object) const;
    /// Adds an object with the next id; returns that id.
    ObjectId addObject(const Aabb& bounds, std::uint32_t triangleCount, std::uint32_t flags = OBJECT_NONE,
                       std::string name = {});
};
} // namespace osgVis::core
