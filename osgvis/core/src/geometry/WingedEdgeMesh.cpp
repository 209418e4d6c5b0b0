// SPDX-License-Identifier: MIT
// Luka §3.3 (winged-edge data a renderer may supply): the closedness check that a silhouette rests
// on, and the silhouette itself (edges between a front-facing and a back-facing face).
#include <osgVis/core/geometry/WingedEdgeMesh.h>

#include <algorithm>
#include <sstream>

namespace osgVis::core
{
namespace
{
struct HalfEdge
{
    std::uint32_t low, high; // vertex indices, low < high
    bool forward;            // the face uses low → high
    std::uint32_t face;
    bool operator<(const HalfEdge& o) const
    {
        return low != o.low ? low < o.low : high != o.high ? high < o.high : forward < o.forward;
    }
};
} // namespace

WingedEdgeMesh::WingedEdgeMesh(std::vector<Vec3f> positions, std::vector<std::uint32_t> indices)
    : _positions(std::move(positions)), _indices(std::move(indices))
{
    std::ostringstream why;
    if (_indices.empty() || _indices.size() % 3 != 0)
    {
        why << (_indices.empty() ? "no triangles" : "the index count is not a multiple of 3");
        _problem = why.str();
        return;
    }
    std::vector<HalfEdge> half;
    half.reserve(_indices.size());
    const auto faces = std::uint32_t(_indices.size() / 3);
    for (std::uint32_t f = 0; f < faces; ++f)
    {
        const std::uint32_t* v = &_indices[3 * std::size_t(f)];
        for (int i = 0; i < 3; ++i)
            if (v[i] >= _positions.size())
            {
                why << "face " << f << " uses vertex " << v[i] << " of " << _positions.size();
                _problem = why.str();
                return;
            }
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
        {
            why << "face " << f << " repeats a vertex";
            _problem = why.str();
            return;
        }
        for (int i = 0; i < 3; ++i)
        {
            const std::uint32_t a = v[i], b = v[(i + 1) % 3];
            half.push_back({std::min(a, b), std::max(a, b), a < b, f});
        }
    }
    std::sort(half.begin(), half.end());
    // Closed and consistently oriented: each undirected edge exactly twice, once in each direction.
    for (std::size_t i = 0; i < half.size();)
    {
        std::size_t j = i;
        while (j < half.size() && half[j].low == half[i].low && half[j].high == half[i].high)
            ++j;
        if (j - i != 2 || half[i].forward == half[i + 1].forward)
        {
            why << "edge " << half[i].low << "-" << half[i].high << " is used by " << (j - i) << " face"
                << (j - i == 1 ? "" : "s") << (j - i == 2 ? " in the same direction" : "");
            _problem = why.str();
            _edges.clear();
            return;
        }
        // half[i] has forward false (sorted), so it is the face using high → low.
        _edges.push_back({half[i].low, half[i].high, half[i + 1].face, half[i].face});
        i = j;
    }
    _problem.clear();
}

bool WingedEdgeMesh::facesEye(std::uint32_t face, const Vec3& eye) const
{
    const Vec3 a(_positions[_indices[3 * std::size_t(face)]]);
    const Vec3 b(_positions[_indices[3 * std::size_t(face) + 1]]);
    const Vec3 c(_positions[_indices[3 * std::size_t(face) + 2]]);
    return glm::dot(glm::cross(b - a, c - a), eye - a) > 0.0;
}

void WingedEdgeMesh::silhouette(const Vec3& eye, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const
{
    if (!closed())
        return;
    for (const Edge& e : _edges)
        if (facesEye(e.facesAB, eye) != facesEye(e.facesBA, eye))
            out.emplace_back(e.a, e.b);
}
} // namespace osgVis::core
