// SPDX-License-Identifier: MIT
#include <osgVis/Q3Bsp>

#include <osg/NodeVisitor>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace osgVis
{
namespace
{
// Lumps of an IBSP 46 file and the sizes of their records.
enum Lump
{
    Planes = 2,
    Nodes = 3,
    Leafs = 4,
    LeafFaces = 5,
    Vertices = 10,
    MeshVertices = 11,
    Faces = 13,
    VisData = 16,
    LumpCount = 17
};
constexpr std::size_t PlaneSize = 16, NodeSize = 36, LeafSize = 48, FaceSize = 104, VertexSize = 44;
constexpr double PluginScale = 0.0254; // OSG's bsp plugin: metres from Quake units

enum FaceType
{
    PolygonFace = 1,
    PatchFace = 2,
    MeshFace = 3
};

class Reader
{
public:
    Reader(std::vector<char> bytes, std::string path) : _bytes(std::move(bytes)), _path(std::move(path)) {}

    std::int32_t i32(std::size_t at) const
    {
        need(at, 4);
        std::int32_t v;
        std::memcpy(&v, _bytes.data() + at, 4); // little-endian, as the format and x86 are
        return v;
    }
    float f32(std::size_t at) const
    {
        need(at, 4);
        float v;
        std::memcpy(&v, _bytes.data() + at, 4);
        return v;
    }
    std::uint8_t u8(std::size_t at) const
    {
        need(at, 1);
        return std::uint8_t(_bytes[at]);
    }
    // Offset and record count of a lump.
    std::pair<std::size_t, std::size_t> lump(int index, std::size_t recordSize) const
    {
        const std::int32_t offset = i32(8 + 8 * std::size_t(index)), length = i32(12 + 8 * std::size_t(index));
        if (offset < 0 || length < 0 || std::size_t(offset) + std::size_t(length) > _bytes.size() ||
            std::size_t(length) % recordSize != 0)
            fail("lump " + std::to_string(index) + " lies outside the file or is not whole records");
        return {std::size_t(offset), std::size_t(length) / recordSize};
    }
    [[noreturn]] void fail(const std::string& why) const
    {
        throw std::runtime_error("'" + _path + "' is no Quake 3 level osgVis can read: " + why);
    }
    std::size_t size() const { return _bytes.size(); }

private:
    void need(std::size_t at, std::size_t n) const
    {
        if (at + n > _bytes.size())
            fail("truncated");
    }
    std::vector<char> _bytes;
    std::string _path;
};

// The file's bytes, once its header says it is a Quake 3 level.
Reader openLevel(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot open '" + path + "'");
    Reader r(std::vector<char>(std::istreambuf_iterator<char>(in), {}), path);
    if (r.size() < 8 + 8 * LumpCount)
        r.fail("too short for a header");
    if (!(r.u8(0) == 'I' && r.u8(1) == 'B' && r.u8(2) == 'S' && r.u8(3) == 'P') || r.i32(4) != 46)
        r.fail("not IBSP version 46 (Quake 3)");
    return r;
}

// Appends every plane's normal and distance; returns how many planes the level has.
std::size_t readPlanes(const Reader& r, std::vector<core::Vec3>& normals, std::vector<double>& distances)
{
    const auto [planes, planeCount] = r.lump(Planes, PlaneSize);
    for (std::size_t i = 0; i < planeCount; ++i)
    {
        const std::size_t at = planes + i * PlaneSize;
        normals.emplace_back(r.f32(at), r.f32(at + 4), r.f32(at + 8));
        distances.push_back(r.f32(at + 12));
    }
    return planeCount;
}

// Appends every leaf's cluster to `leafClusters`; returns per face the clusters of the leaves that
// list it, sorted and without repeats.
std::vector<std::vector<int>> readFaceClusters(const Reader& r, std::size_t leafs, std::size_t leafCount,
                                               std::size_t faceCount, std::vector<int>& leafClusters)
{
    const auto [leafFaces, leafFaceCount] = r.lump(LeafFaces, 4);
    std::vector<std::vector<int>> faceClusters(faceCount);
    for (std::size_t i = 0; i < leafCount; ++i)
    {
        const std::size_t at = leafs + i * LeafSize;
        const int cluster = r.i32(at);
        leafClusters.push_back(cluster);
        const std::int32_t first = r.i32(at + 32), count = r.i32(at + 36);
        if (first < 0 || count < 0 || std::size_t(first) + std::size_t(count) > leafFaceCount)
            r.fail("a leaf lists faces it does not have");
        if (cluster < 0)
            continue;
        for (std::int32_t k = 0; k < count; ++k)
        {
            const std::int32_t face = r.i32(leafFaces + 4 * std::size_t(first + k));
            if (face < 0 || std::size_t(face) >= faceCount)
                r.fail("a leaf lists a face it does not have");
            faceClusters[std::size_t(face)].push_back(cluster);
        }
    }
    for (std::vector<int>& clusters : faceClusters)
    {
        std::sort(clusters.begin(), clusters.end());
        clusters.erase(std::unique(clusters.begin(), clusters.end()), clusters.end());
    }
    return faceClusters;
}

std::vector<int> readMeshVertices(const Reader& r)
{
    const auto [meshVertices, meshVertexCount] = r.lump(MeshVertices, 4);
    std::vector<int> offsets;
    for (std::size_t i = 0; i < meshVertexCount; ++i)
        offsets.push_back(r.i32(meshVertices + 4 * i));
    return offsets;
}

// The face of each drawable the plugin makes, in its order.
std::vector<int> pluginDrawableFaces(const Reader& r, std::size_t faces, std::size_t faceCount)
{
    std::vector<int> drawableFaces;
    for (const int type : {MeshFace, PolygonFace, PatchFace})
        for (std::size_t f = 0; f < faceCount; ++f)
        {
            const std::size_t at = faces + f * FaceSize;
            if (r.i32(at + 8) != type)
                continue;
            int pieces = 1;
            if (type == PatchFace)
                pieces = std::max(0, (r.i32(at + 96) - 1) / 2) * std::max(0, (r.i32(at + 100) - 1) / 2);
            for (int p = 0; p < pieces; ++p)
                drawableFaces.push_back(int(f));
        }
    return drawableFaces;
}

// The visdata lump: a bit per cluster pair, rows of `bytesPerCluster` bytes; nothing when it is shorter
// than its header.
void readVisibility(const Reader& r, int& clusterCount, int& bytesPerCluster, std::vector<std::uint8_t>& visibility)
{
    const auto [vis, visLength] = r.lump(VisData, 1);
    if (visLength < 8)
        return;
    clusterCount = r.i32(vis);
    bytesPerCluster = r.i32(vis + 4);
    if (clusterCount < 0 || bytesPerCluster < 0 ||
        8 + std::size_t(clusterCount) * std::size_t(bytesPerCluster) > visLength ||
        std::size_t(bytesPerCluster) * 8 < std::size_t(clusterCount))
        r.fail("the visibility lump does not hold a bit per cluster pair");
    for (std::size_t i = 0; i < std::size_t(clusterCount) * std::size_t(bytesPerCluster); ++i)
        visibility.push_back(r.u8(vis + 8 + i));
}
} // namespace

Q3Bsp Q3Bsp::read(const std::string& path)
{
    const Reader r = openLevel(path);

    Q3Bsp bsp;
    const std::size_t planeCount = readPlanes(r, bsp._planeNormals, bsp._planeDistances);
    const auto [leafs, leafCount] = r.lump(Leafs, LeafSize);
    const auto [nodes, nodeCount] = r.lump(Nodes, NodeSize);
    for (std::size_t i = 0; i < nodeCount; ++i)
    {
        const std::size_t at = nodes + i * NodeSize;
        Node node{r.i32(at), {r.i32(at + 4), r.i32(at + 8)}};
        if (node.plane < 0 || std::size_t(node.plane) >= planeCount)
            r.fail("a node names a plane it does not have");
        for (int child : node.children)
            if ((child >= 0 && std::size_t(child) >= nodeCount) || (child < 0 && std::size_t(-(child + 1)) >= leafCount))
                r.fail("a node names a child it does not have");
        bsp._nodes.push_back(node);
    }

    const auto [faces, faceCount] = r.lump(Faces, FaceSize);
    bsp._faceClusters = readFaceClusters(r, leafs, leafCount, faceCount, bsp._leafClusters);

    const auto [vertices, vertexCount] = r.lump(Vertices, VertexSize);
    (void)vertices;
    bsp._vertexCount = vertexCount;
    bsp._meshVertices = readMeshVertices(r);
    for (std::size_t f = 0; f < faceCount; ++f)
    {
        const std::size_t at = faces + f * FaceSize;
        bsp._faces.push_back({r.i32(at + 8), r.i32(at + 12), r.i32(at + 16), r.i32(at + 20), r.i32(at + 24)});
    }

    // The plugin's drawables, in its order.
    bsp._drawableFaces = pluginDrawableFaces(r, faces, faceCount);
    readVisibility(r, bsp._clusterCount, bsp._bytesPerCluster, bsp._visibility);
    return bsp;
}

int Q3Bsp::clusterAt(const core::Vec3& point) const
{
    if (_nodes.empty())
        return -1;
    const core::Vec3 quake(point.x / PluginScale, -point.y / PluginScale, point.z / PluginScale);
    int index = 0;
    for (std::size_t guard = 0; guard <= _nodes.size(); ++guard)
    {
        const Node& node = _nodes[std::size_t(index)];
        const double side = glm::dot(_planeNormals[std::size_t(node.plane)], quake) - _planeDistances[std::size_t(node.plane)];
        const int child = node.children[side >= 0.0 ? 0 : 1];
        if (child < 0)
            return _leafClusters[std::size_t(-(child + 1))];
        index = child;
    }
    return -1; // a cycle: not a tree
}

osg::Geode* Q3Bsp::pluginGeode(osg::Node& model) const
{
    struct Finder : osg::NodeVisitor
    {
        explicit Finder(std::size_t drawables) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), drawables(drawables) {}
        std::size_t drawables;
        osg::Geode* found = nullptr;
        void apply(osg::Geode& geode) override
        {
            if (!found && geode.getNumDrawables() == drawables)
                found = &geode;
        }
    } finder(_drawableFaces.size());
    model.accept(finder);
    return finder.found;
}

bool Q3Bsp::isPolygonFace(int face) const
{
    return face >= 0 && std::size_t(face) < _faces.size() && _faces[std::size_t(face)].type == PolygonFace;
}

std::vector<std::uint32_t> Q3Bsp::faceTriangles(int face) const
{
    std::vector<std::uint32_t> triangles;
    if (face < 0 || std::size_t(face) >= _faces.size())
        return triangles;
    const Face& f = _faces[std::size_t(face)];
    if (f.firstMeshVertex < 0 || f.meshVertexCount < 3 || f.meshVertexCount % 3 != 0 ||
        std::size_t(f.firstMeshVertex) + std::size_t(f.meshVertexCount) > _meshVertices.size())
        return triangles;
    for (int k = 0; k < f.meshVertexCount; ++k)
    {
        const long long index = (long long)f.firstVertex + _meshVertices[std::size_t(f.firstMeshVertex + k)];
        // Every index must stay within the face's own vertices.
        if (index < f.firstVertex || index >= (long long)f.firstVertex + f.vertexCount || index >= (long long)_vertexCount)
            return {};
        triangles.push_back(std::uint32_t(index));
    }
    return triangles;
}

bool Q3Bsp::clusterSees(int from, int to) const
{
    if (_visibility.empty())
        return true;
    if (from < 0 || to < 0 || from >= _clusterCount || to >= _clusterCount)
        return true;
    return (_visibility[std::size_t(from) * std::size_t(_bytesPerCluster) + std::size_t(to) / 8] >> (to % 8)) & 1u;
}
} // namespace osgVis
