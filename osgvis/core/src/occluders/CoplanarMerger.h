// SPDX-License-Identifier: MIT
#pragma once
// Merges the triangles of one object into convex polygons: triangles that share an edge (found
// through OpenMesh half-edge connectivity) and lie in one plane grow into a region; a region whose
// outline is convex becomes one polygon, any other is cut into convex pieces by joining
// neighbouring pieces while their union stays convex.
#include <osgVis/core/geometry/Math.h>

#include <OpenMesh/Core/Mesh/PolyConnectivity.hh>

#include <array>
#include <cstdint>
#include <vector>

namespace osgVis::core
{
struct MergeTriangle
{
    std::array<std::uint32_t, 3> vertices; // welded ids, counter-clockwise around `normal`
    Vec3 normal;                           // unit
    double normalSlack = 0.0;              // sine by which float storage may have turned `normal`
    std::uint32_t tag = 0;                 // caller's label (the object it comes from), kept per polygon
};

struct MergedPolygon
{
    std::vector<std::uint32_t> loop; // welded ids along triangle edges, straight-line vertices kept
    Vec3 normal;                     // unit normal of the triangles it came from
    std::vector<std::uint32_t> tags; // the distinct tags of those triangles, ascending
};

struct CoplanarMergeOptions
{
    double sinCoplanarAngle = 1e-5; // sine of the largest angle between normals taken as one plane
    double planeTolerance = 1e-6;   // off-plane distance allowed, relative to the region size
    double turnTolerance = 1e-6;    // sine of the largest bend of an outline still taken as straight
    std::uint32_t maxCorners = 32;
};

class CoplanarMerger
{
public:
    CoplanarMerger(const std::vector<Vec3>& positions, const CoplanarMergeOptions& options);

    // Appends convex polygons that together cover `triangles` exactly, each triangle in one.
    void merge(const std::vector<MergeTriangle>& triangles, std::vector<MergedPolygon>& out);

private:
    // Builds the mesh from `triangles` (indices into *_triangles); faces it cannot take go to `refused`.
    void connect(const std::vector<int>& triangles, std::vector<int>& refused);
    // Grows coplanar regions over the current mesh and emits their convex pieces.
    void mergeConnected(std::vector<MergedPolygon>& out);
    bool canAddFace(const std::array<OpenMesh::VertexHandle, 3>& face) const;
    bool fitsRegion(int face, const MergeTriangle& seed) const;
    bool singleOutline(const std::vector<int>& region, int regionId, std::vector<std::uint32_t>& loop) const;
    void mergePairwise(const std::vector<int>& region, const Vec3& normal, std::vector<MergedPolygon>& out);
    bool joinAcross(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b, std::uint32_t from,
                    std::uint32_t to, const Vec3& normal, std::vector<std::uint32_t>& joined) const;
    std::array<std::uint32_t, 3> faceVertices(int face) const;
    // Tags of the triangles behind mesh faces (or of one triangle), sorted and unique.
    std::vector<std::uint32_t> faceTags(const std::vector<int>& faces) const;

    const std::vector<Vec3>& _positions;
    CoplanarMergeOptions _options;
    OpenMesh::PolyConnectivity _mesh;
    const std::vector<MergeTriangle>* _triangles = nullptr;
    std::vector<std::uint32_t> _globalOfVertex; // mesh vertex → welded id
    std::vector<int> _localOfOffset;            // welded id − smallest id → mesh vertex (dense objects)
    std::vector<int> _triangleOfFace;           // mesh face → index into *_triangles
    std::vector<int> _regionOfFace;             // mesh face → region id, -1 while unassigned
    Vec3 _regionMin{0.0}, _regionMax{0.0};
};
} // namespace osgVis::core
