// SPDX-License-Identifier: MIT
#include "CoplanarMerger.h"

#include "BoundaryLoop.h"

#include <algorithm>
#include <numeric>

namespace osgVis::core
{
namespace
{
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// Union-find root with path halving.
int rootOf(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

bool hasRepeats(std::vector<std::uint32_t> ids)
{
    std::sort(ids.begin(), ids.end());
    return std::adjacent_find(ids.begin(), ids.end()) != ids.end();
}
} // namespace

CoplanarMerger::CoplanarMerger(const std::vector<Vec3>& positions, const CoplanarMergeOptions& options)
    : _positions(positions), _options(options)
{
}

std::array<std::uint32_t, 3> CoplanarMerger::faceVertices(int face) const
{
    return (*_triangles)[std::size_t(_triangleOfFace[face])].vertices;
}

bool CoplanarMerger::canAddFace(const std::array<VertexHandle, 3>& face) const
{
    // OpenMesh refuses (and reports on its error stream) faces that would make the connectivity
    // non-manifold; asking first keeps the log quiet, and a refused face stays a lone triangle.
    std::array<HalfedgeHandle, 3> edges;
    for (int i = 0; i < 3; ++i)
    {
        if (!_mesh.is_boundary(face[i]))
            return false; // vertex already closed all around
        edges[i] = _mesh.find_halfedge(face[i], face[(i + 1) % 3]);
        if (edges[i].is_valid() && !_mesh.is_boundary(edges[i]))
            return false; // edge already used in this direction
    }
    for (int i = 0; i < 3; ++i)
    {
        const HalfedgeHandle in = edges[i];
        const HalfedgeHandle out = edges[(i + 1) % 3];
        if (!in.is_valid() || !out.is_valid() || _mesh.next_halfedge_handle(in) == out)
            continue;
        // Both edges exist but are not consecutive around their shared vertex: OpenMesh must move
        // the faces between them into another gap of that vertex's fan, which has to exist.
        HalfedgeHandle gap = _mesh.opposite_halfedge_handle(out);
        bool found = false;
        for (int guard = 0; guard < 4096 && !found; ++guard)
        {
            gap = _mesh.opposite_halfedge_handle(_mesh.next_halfedge_handle(gap));
            if (_mesh.is_boundary(gap))
            {
                if (gap == in || _mesh.next_halfedge_handle(gap) == out)
                    return false;
                found = true;
            }
        }
        if (!found)
            return false;
    }
    return true;
}

bool CoplanarMerger::fitsRegion(int face, const MergeTriangle& seed) const
{
    const MergeTriangle& t = (*_triangles)[std::size_t(_triangleOfFace[face])];
    const Vec3& normal = seed.normal;
    if (glm::dot(t.normal, normal) <= 0.0 ||
        glm::length(glm::cross(t.normal, normal)) > _options.sinCoplanarAngle + t.normalSlack + seed.normalSlack)
        return false;
    Vec3 lo = _regionMin, hi = _regionMax;
    for (std::uint32_t v : t.vertices)
    {
        lo = glm::min(lo, _positions[v]);
        hi = glm::max(hi, _positions[v]);
    }
    const Vec3& seedPoint = _positions[seed.vertices[0]];
    const double limit = _options.planeTolerance * glm::length(hi - lo) + storageSlack(seedPoint);
    for (std::uint32_t v : t.vertices)
    {
        if (std::abs(glm::dot(normal, _positions[v] - seedPoint)) > limit + storageSlack(_positions[v]))
            return false;
    }
    return true;
}

bool CoplanarMerger::singleOutline(const std::vector<int>& region, int regionId, std::vector<std::uint32_t>& loop) const
{
    auto inRegion = [&](HalfedgeHandle h)
    {
        const FaceHandle f = _mesh.face_handle(h);
        return f.is_valid() && _regionOfFace[std::size_t(f.idx())] == regionId;
    };
    std::size_t boundaryCount = 0;
    HalfedgeHandle first;
    for (int face : region)
    {
        const HalfedgeHandle start = _mesh.halfedge_handle(FaceHandle(face));
        HalfedgeHandle h = start;
        do
        {
            if (!inRegion(_mesh.opposite_halfedge_handle(h)))
            {
                ++boundaryCount;
                if (!first.is_valid())
                    first = h;
            }
            h = _mesh.next_halfedge_handle(h);
        } while (h != start);
    }

    if (boundaryCount == 0)
        return false;

    // Walk the outline: from a boundary half-edge, turn around its end vertex through the region's
    // faces until the next boundary half-edge. One loop must use every boundary half-edge.
    loop.clear();
    HalfedgeHandle h = first;
    const std::size_t guardLimit = region.size() * 3 + 3;
    do
    {
        loop.push_back(_globalOfVertex[std::size_t(_mesh.from_vertex_handle(h).idx())]);
        HalfedgeHandle next = _mesh.next_halfedge_handle(h);
        std::size_t guard = 0;
        while (inRegion(_mesh.opposite_halfedge_handle(next)))
        {
            next = _mesh.next_halfedge_handle(_mesh.opposite_halfedge_handle(next));
            if (++guard > guardLimit)
                return false;
        }
        h = next;
    } while (h != first && loop.size() <= boundaryCount);
    return h == first && loop.size() == boundaryCount;
}

bool CoplanarMerger::joinAcross(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b,
                                std::uint32_t from, std::uint32_t to, const Vec3& normal,
                                std::vector<std::uint32_t>& joined) const
{
    const std::size_t na = a.size(), nb = b.size();
    std::size_t s = na, qe = nb;
    for (std::size_t i = 0; i < na && s == na; ++i)
    {
        if (a[i] == from && a[(i + 1) % na] == to)
            s = i;
    }
    for (std::size_t j = 0; j < nb && qe == nb; ++j)
    {
        if (b[j] == to && b[(j + 1) % nb] == from)
            qe = j;
    }
    if (s == na || qe == nb)
        return false;

    // The shared chain runs a[s] … a[e] in `a` and b[qe] … b[qs] (backwards) in `b`; widen it over
    // further shared edges on both ends.
    std::size_t e = (s + 1) % na, qs = (qe + 1) % nb, length = 1;
    const std::size_t maxLength = std::min(na, nb) - 2;
    while (length < maxLength && a[(s + na - 1) % na] == b[(qs + 1) % nb])
    {
        s = (s + na - 1) % na;
        qs = (qs + 1) % nb;
        ++length;
    }
    while (length < maxLength && a[(e + 1) % na] == b[(qe + nb - 1) % nb])
    {
        e = (e + 1) % na;
        qe = (qe + nb - 1) % nb;
        ++length;
    }

    joined.clear();
    for (std::size_t i = e;; i = (i + 1) % na)
    {
        joined.push_back(a[i]);
        if (i == s)
            break;
    }
    for (std::size_t j = (qs + 1) % nb; j != qe; j = (j + 1) % nb)
        joined.push_back(b[j]);
    if (hasRepeats(joined))
        return false; // the pieces also touch elsewhere: the union would pinch or enclose a hole

    // Only the two ends of the chain change their turn.
    const std::size_t n = joined.size();
    const std::size_t ends[2] = {na - length, 0}; // positions of a[s] and a[e] in `joined`
    for (std::size_t i : ends)
    {
        const Vec3& p = _positions[joined[(i + n - 1) % n]];
        const Vec3& c = _positions[joined[i]];
        const Vec3& q = _positions[joined[(i + 1) % n]];
        if (turnAt(p, c, q, normal, _options.turnTolerance) == Turn::Reflex)
            return false;
    }
    std::uint32_t corners = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        if (turnAt(_positions[joined[(i + n - 1) % n]], _positions[joined[i]], _positions[joined[(i + 1) % n]], normal,
                   _options.turnTolerance) != Turn::Straight)
            ++corners;
    }
    return corners <= _options.maxCorners;
}

void CoplanarMerger::mergePairwise(const std::vector<int>& region, const Vec3& normal, std::vector<MergedPolygon>& out)
{
    // Pieces start as the region's triangles; neighbouring pieces join across their longest shared
    // edges first, which pairs the halves of tessellated quads before the quads themselves.
    const int count = int(region.size());
    std::vector<std::vector<std::uint32_t>> pieces(region.size());
    std::vector<int> parent(region.size());
    std::iota(parent.begin(), parent.end(), 0);
    struct SharedEdge
    {
        double length2;
        int a, b;
        std::uint32_t from, to;
    };
    std::vector<SharedEdge> edges;
    for (int slot = 0; slot < count; ++slot)
    {
        const auto v = faceVertices(region[std::size_t(slot)]);
        pieces[std::size_t(slot)].assign(v.begin(), v.end());
    }
    auto slotOf = [&](int face) { return int(std::lower_bound(region.begin(), region.end(), face) - region.begin()); };
    for (int slot = 0; slot < count; ++slot)
    {
        const HalfedgeHandle start = _mesh.halfedge_handle(FaceHandle(region[std::size_t(slot)]));
        HalfedgeHandle h = start;
        do
        {
            const FaceHandle other = _mesh.opposite_face_handle(h);
            if (other.is_valid() && other.idx() > region[std::size_t(slot)] &&
                std::binary_search(region.begin(), region.end(), other.idx()))
            {
                const std::uint32_t from = _globalOfVertex[std::size_t(_mesh.from_vertex_handle(h).idx())];
                const std::uint32_t to = _globalOfVertex[std::size_t(_mesh.to_vertex_handle(h).idx())];
                const Vec3 d = _positions[to] - _positions[from];
                edges.push_back({glm::dot(d, d), slot, slotOf(other.idx()), from, to});
            }
            h = _mesh.next_halfedge_handle(h);
        } while (h != start);
    }
    std::stable_sort(edges.begin(), edges.end(),
                     [](const SharedEdge& x, const SharedEdge& y) { return x.length2 > y.length2; });

    // A join refused now may fit once a neighbour has filled a notch, so repeat a few rounds.
    std::vector<std::uint32_t> joined;
    for (int round = 0; round < 8; ++round)
    {
        bool changed = false;
        for (const SharedEdge& edge : edges)
        {
            const int a = rootOf(parent, edge.a);
            const int b = rootOf(parent, edge.b);
            if (a == b)
                continue;
            if (joinAcross(pieces[std::size_t(a)], pieces[std::size_t(b)], edge.from, edge.to, normal, joined))
            {
                pieces[std::size_t(a)].swap(joined);
                pieces[std::size_t(b)].clear();
                parent[std::size_t(b)] = a;
                changed = true;
            }
        }
        if (!changed)
            break;
    }

    for (int slot = 0; slot < count; ++slot)
    {
        if (rootOf(parent, slot) != slot)
            continue;
        const auto& piece = pieces[std::size_t(slot)];
        if (isConvexLoop(piece, _positions, normal, _options.turnTolerance, _options.planeTolerance,
                         _options.maxCorners))
        {
            std::vector<int> members;
            for (int member = 0; member < count; ++member)
                if (rootOf(parent, member) == slot)
                    members.push_back(region[std::size_t(member)]);
            out.push_back({piece, normal, faceTags(members)});
            continue;
        }
        // note: tolerances may let a chain of joins drift out of true; its triangles are then
        // emitted on their own rather than as a doubtful polygon.
        for (int member = 0; member < count; ++member)
        {
            if (rootOf(parent, member) == slot)
            {
                const auto v = faceVertices(region[std::size_t(member)]);
                out.push_back({{v.begin(), v.end()}, normal, faceTags({region[std::size_t(member)]})});
            }
        }
    }
}

void CoplanarMerger::connect(const std::vector<int>& triangles, std::vector<int>& refused)
{
    // Mesh vertices for the welded ids in use. An object's ids mostly form one dense range (it was
    // welded in one go), so a table over that range maps them; a scattered set is sorted instead.
    // Either way no scene-sized table per thread.
    std::uint32_t lo = ~std::uint32_t(0), hi = 0;
    for (int t : triangles)
    {
        for (std::uint32_t id : (*_triangles)[std::size_t(t)].vertices)
        {
            lo = std::min(lo, id);
            hi = std::max(hi, id);
        }
    }
    const bool dense = !triangles.empty() && std::size_t(hi - lo) < 8 * triangles.size() + 1024;
    _globalOfVertex.clear();
    if (dense)
    {
        _localOfOffset.assign(std::size_t(hi - lo) + 1, -1);
        for (int t : triangles)
        {
            for (std::uint32_t id : (*_triangles)[std::size_t(t)].vertices)
            {
                if (_localOfOffset[id - lo] < 0)
                {
                    _localOfOffset[id - lo] = int(_globalOfVertex.size());
                    _globalOfVertex.push_back(id);
                }
            }
        }
    }
    else
    {
        for (int t : triangles)
        {
            const auto& v = (*_triangles)[std::size_t(t)].vertices;
            _globalOfVertex.insert(_globalOfVertex.end(), v.begin(), v.end());
        }
        std::sort(_globalOfVertex.begin(), _globalOfVertex.end());
        _globalOfVertex.erase(std::unique(_globalOfVertex.begin(), _globalOfVertex.end()), _globalOfVertex.end());
    }
    auto localOf = [&](std::uint32_t id)
    {
        return dense ? _localOfOffset[id - lo]
                     : int(std::lower_bound(_globalOfVertex.begin(), _globalOfVertex.end(), id) -
                           _globalOfVertex.begin());
    };

    _mesh.clean_keep_reservation();
    for (std::size_t i = 0; i < _globalOfVertex.size(); ++i)
        _mesh.add_vertex();
    _triangleOfFace.clear();
    for (int t : triangles)
    {
        std::array<VertexHandle, 3> face;
        for (std::size_t i = 0; i < 3; ++i)
            face[i] = VertexHandle(localOf((*_triangles)[std::size_t(t)].vertices[i]));
        if (canAddFace(face) && _mesh.add_face(face.data(), 3).is_valid())
            _triangleOfFace.push_back(t);
        else
            refused.push_back(t);
    }
}

void CoplanarMerger::mergeConnected(std::vector<MergedPolygon>& out)
{
    const int faceCount = int(_mesh.n_faces());
    _regionOfFace.assign(std::size_t(faceCount), -1);
    std::vector<int> region, stack;
    std::vector<std::uint32_t> loop;
    for (int seed = 0; seed < faceCount; ++seed)
    {
        if (_regionOfFace[std::size_t(seed)] >= 0)
            continue;
        const MergeTriangle& seedTriangle = (*_triangles)[std::size_t(_triangleOfFace[std::size_t(seed)])];
        const Vec3 normal = seedTriangle.normal;
        _regionMin = _regionMax = _positions[seedTriangle.vertices[0]];
        for (std::uint32_t v : seedTriangle.vertices)
        {
            _regionMin = glm::min(_regionMin, _positions[v]);
            _regionMax = glm::max(_regionMax, _positions[v]);
        }

        // Flood fill across shared edges, comparing with the seed's plane so the region cannot
        // drift through a slow curve.
        region.clear();
        stack.assign(1, seed);
        _regionOfFace[std::size_t(seed)] = seed;
        while (!stack.empty())
        {
            const int face = stack.back();
            stack.pop_back();
            region.push_back(face);
            const HalfedgeHandle start = _mesh.halfedge_handle(FaceHandle(face));
            HalfedgeHandle h = start;
            do
            {
                const FaceHandle other = _mesh.opposite_face_handle(h);
                if (other.is_valid() && _regionOfFace[std::size_t(other.idx())] < 0 &&
                    fitsRegion(other.idx(), seedTriangle))
                {
                    _regionOfFace[std::size_t(other.idx())] = seed;
                    for (std::uint32_t v : faceVertices(other.idx()))
                    {
                        _regionMin = glm::min(_regionMin, _positions[v]);
                        _regionMax = glm::max(_regionMax, _positions[v]);
                    }
                    stack.push_back(other.idx());
                }
                h = _mesh.next_halfedge_handle(h);
            } while (h != start);
        }
        std::sort(region.begin(), region.end());

        if (singleOutline(region, seed, loop) && isConvexLoop(loop, _positions, normal, _options.turnTolerance,
                                                              _options.planeTolerance, _options.maxCorners))
            out.push_back({loop, normal, faceTags(region)});
        else
            mergePairwise(region, normal, out);
    }
}

void CoplanarMerger::merge(const std::vector<MergeTriangle>& triangles, std::vector<MergedPolygon>& out)
{
    // Faces OpenMesh cannot take next to the others (a second copy of a face, the back of a
    // two-sided wall, a third face on an edge) go to another layer, with connectivity of their
    // own; what no layer takes stays a lone triangle.
    constexpr int MaxLayers = 4;
    _triangles = &triangles;
    // Triangles facing one side of a fixed, generic direction connect first and the rest after,
    // so the back of a two-sided wall, whatever its input order, is refused whole into the next
    // layer rather than pairing triangle by triangle with the front.
    const Vec3 side(0.3017, 0.5123, 0.8039);
    std::vector<int> pending(triangles.size()), refused;
    std::iota(pending.begin(), pending.end(), 0);
    std::stable_partition(pending.begin(), pending.end(),
                          [&](int t) { return glm::dot(triangles[std::size_t(t)].normal, side) >= 0.0; });
    for (int layer = 0; layer < MaxLayers && !pending.empty(); ++layer)
    {
        refused.clear();
        connect(pending, refused);
        mergeConnected(out);
        pending.swap(refused);
    }
    for (int t : pending)
    {
        const MergeTriangle& triangle = triangles[std::size_t(t)];
        out.push_back({{triangle.vertices.begin(), triangle.vertices.end()}, triangle.normal, {triangle.tag}});
    }
    _triangles = nullptr;
}

std::vector<std::uint32_t> CoplanarMerger::faceTags(const std::vector<int>& faces) const
{
    std::vector<std::uint32_t> tags;
    tags.reserve(faces.size() < 4 ? faces.size() : 4);
    for (int face : faces)
        tags.push_back((*_triangles)[std::size_t(_triangleOfFace[std::size_t(face)])].tag);
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    return tags;
}
} // namespace osgVis::core
