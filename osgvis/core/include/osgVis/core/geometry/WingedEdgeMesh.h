// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A renderer's mesh connectivity as edges with the two faces beside each (winged-edge data, Luka
/// §3.3), and the silhouette it yields for an eye. Connectivity from a renderer is not trusted: the
/// mesh is checked to be closed (every edge used by exactly two faces, once in each direction, no
/// index out of range, no face repeating a vertex); a silhouette is answered only for a closed one,
/// since an open or inconsistent mesh has boundary edges no front/back test sees.
#include <osgVis/core/geometry/Math.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::core
{
class WingedEdgeMesh
{
public:
    struct Edge
    {
        std::uint32_t a = 0, b = 0;       ///< vertex indices, a < b
        std::uint32_t facesAB = 0, facesBA = 0; ///< the face using a→b, the face using b→a
    };

    WingedEdgeMesh() = default;
    /// `indices` holds 3 per triangle, counter-clockwise seen from the front.
    WingedEdgeMesh(std::vector<Vec3f> positions, std::vector<std::uint32_t> indices);

    bool closed() const { return _problem.empty() && !_indices.empty(); }
    /// Why the mesh is not closed ("" when it is).
    const std::string& problem() const { return _problem; }
    const std::vector<Vec3f>& positions() const { return _positions; }
    const std::vector<std::uint32_t>& indices() const { return _indices; }
    /// The edges (only when closed()).
    const std::vector<Edge>& edges() const { return _edges; }
    /// Appends the edges between a face turned to `eye` and one turned away (none unless closed()).
    void silhouette(const Vec3& eye, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const;

private:
    bool facesEye(std::uint32_t face, const Vec3& eye) const;
    std::vector<Vec3f> _positions;
    std::vector<std::uint32_t> _indices;
    std::vector<Edge> _edges;
    std::string _problem = "no triangles";
};
} // namespace osgVis::core
