// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Occluders of the object-space methods: convex planar polygons taken from the scene's own opaque
/// geometry (coplanar neighbouring triangles merged) and from stated occluders, with their
/// neighbours across shared edges so that connected polygons can fuse.
#include <osgVis/core/geometry/Plane.h>
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
constexpr std::uint32_t NoNeighbour = ~std::uint32_t(0);

struct OccluderPolygon
{
    std::vector<Vec3> vertices;            ///< world space, convex, counter-clockwise around plane.normal
    Plane plane;                           ///< unit normal
    double area = 0.0;
    Vec3 centroid{0.0};
    std::vector<std::uint32_t> neighbours; ///< per edge i (vertices[i] → vertices[i+1]): index of the
                                           // polygon sharing exactly that edge, or NoNeighbour
    bool oneSided = false;                 ///< hides only from the side plane.normal points to (face culling)
    ObjectId owner = InvalidObject;        ///< object it comes from (the first of `parts`); InvalidObject
                                           // for a stated occluder
    /// Every object it covers part of, ascending, when it unites faces of several (coplanar faces
    /// of neighbouring objects); empty when it comes from `owner` alone. Such a polygon stands for
    /// all of them: it may occlude only while every one is static and drawn (or hidden).
    std::vector<ObjectId> parts;
    /// A section through the inside of a closed solid object (convexSolidSections), not a drawn
    /// face: it hides only from eyes outside that object's bounds, since a sightline from outside
    /// reaches it only through the object's surface.
    bool insideSolid = false;
};
} // namespace osgVis::core
