// SPDX-License-Identifier: MIT
// Clusters of a large drawable: the leaves of a split of its triangles' centroids, the top-down
// build of a bounding volume hierarchy (each range cut across the longest axis of its centroids' box,
// at its spatial middle, or at the median where the middle would leave one side under a quarter,
// until it holds at most the cluster size), so every cluster is a compact box whatever the mesh's
// shape. std::partition and std::nth_element are deterministic, so a mesh always splits alike. Leaves come in
// the split's depth-first order, so neighbouring clusters are near each other and the visible ones
// often join into one index range. Why not meshoptimizer (docs/clusters.md): meshopt_buildMeshlets
// makes GPU meshlets (at most 512 triangles, 255 vertices in 0.18) while a CPU culler pays per
// object, so the size here is a culling trade-off of its own; and fixed runs of its Morton order
// (meshopt_spatialSortRemap) were tried first: a run across an octant boundary spans the mesh (the
// cluster test saw one cluster twice half the mesh's diagonal).
#include <osgVis/ClusterLayout>

#include <osg/TriangleIndexFunctor>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace osgVis
{
namespace
{
bool triangleMode(GLenum mode)
{
    switch (mode)
    {
    case GL_TRIANGLES:
    case GL_TRIANGLE_STRIP:
    case GL_TRIANGLE_FAN:
    case GL_QUADS:
    case GL_QUAD_STRIP:
    case GL_POLYGON:
        return true;
    default:
        return false;
    }
}

struct IndexCollector
{
    std::vector<std::uint32_t>* out = nullptr;
    void operator()(unsigned a, unsigned b, unsigned c)
    {
        out->push_back(a);
        out->push_back(b);
        out->push_back(c);
    }
};

// Positions as floats (what meshoptimizer takes); false for vertex arrays without xyz positions.
bool floatPositions(const osg::Array& array, std::vector<float>& out)
{
    if (const auto* v3 = dynamic_cast<const osg::Vec3Array*>(&array))
    {
        out.resize(v3->size() * 3);
        for (std::size_t i = 0; i < v3->size(); ++i)
            for (int k = 0; k < 3; ++k)
                out[3 * i + k] = (*v3)[i][k];
        return true;
    }
    if (const auto* v3d = dynamic_cast<const osg::Vec3dArray*>(&array))
    {
        out.resize(v3d->size() * 3);
        for (std::size_t i = 0; i < v3d->size(); ++i)
            for (int k = 0; k < 3; ++k)
                out[3 * i + k] = float((*v3d)[i][k]);
        return true;
    }
    return false;
}

// Whether `geometry` may be split at all: a vertex array, a cluster size, no per-primitive bindings,
// and only triangle primitive sets, none instanced.
bool clusterableGeometry(const osg::Geometry& geometry, std::uint32_t clusterTriangles)
{
    const osg::Array* vertices = geometry.getVertexArray();
    if (!vertices || clusterTriangles == 0 || geometry.containsDeprecatedData() || geometry.getNumPrimitiveSets() == 0)
        return false;
    for (unsigned i = 0; i < geometry.getNumPrimitiveSets(); ++i)
    {
        const osg::PrimitiveSet* set = geometry.getPrimitiveSet(i);
        if (!set || !triangleMode(set->getMode()) || set->getNumInstances() != 0)
            return false;
    }
    return true;
}

// The geometry's triangles, three indices each; false when there are too few for two clusters (or
// too many for 32-bit indices) or one has an index past the vertices or a non-finite vertex.
bool triangleIndices(const osg::Geometry& geometry, const std::vector<float>& positions, std::uint32_t clusterTriangles,
                     std::vector<std::uint32_t>& indices)
{
    const std::size_t vertexCount = positions.size() / 3;
    osg::TriangleIndexFunctor<IndexCollector> functor;
    functor.out = &indices;
    geometry.accept(functor);
    const std::size_t triangles = indices.size() / 3;
    if (triangles < 2 * std::size_t(clusterTriangles) || triangles > 0xffffffffu / 3)
        return false;
    for (std::uint32_t index : indices)
        if (index >= vertexCount || !std::isfinite(positions[3 * index]) || !std::isfinite(positions[3 * index + 1]) ||
            !std::isfinite(positions[3 * index + 2]))
            return false;
    return true;
}

std::vector<float> triangleCentroids(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices)
{
    const std::size_t triangles = indices.size() / 3;
    std::vector<float> centroids(triangles * 3);
    for (std::size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k)
            centroids[3 * t + k] = (positions[3 * indices[3 * t] + k] + positions[3 * indices[3 * t + 1] + k] +
                                    positions[3 * indices[3 * t + 2] + k]) /
                                   3.0f;
    return centroids;
}

// Splits the triangles order[begin, end) in two across the longest axis of their centroids' box,
// reordering them; returns where the upper half begins.
std::size_t splitRange(std::vector<std::uint32_t>& order, const std::vector<float>& centroids, std::size_t begin,
                       std::size_t end)
{
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (std::size_t i = begin; i < end; ++i)
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = std::min(lo[k], centroids[3 * order[i] + k]);
            hi[k] = std::max(hi[k], centroids[3 * order[i] + k]);
        }
    const int axis = (hi[0] - lo[0] >= hi[1] - lo[1] && hi[0] - lo[0] >= hi[2] - lo[2]) ? 0
                     : (hi[1] - lo[1] >= hi[2] - lo[2])                                 ? 1
                                                                                        : 2;
    // The spatial middle of the longest axis keeps apart what a gap separates (a wall and what
    // stands behind it); where it would leave less than a quarter on one side, the median.
    const float cut = 0.5f * (lo[axis] + hi[axis]);
    std::size_t middle = std::size_t(std::partition(order.begin() + long(begin), order.begin() + long(end),
                                                    [&](std::uint32_t t) { return centroids[3 * t + axis] < cut; }) -
                                     order.begin());
    // note: at least one triangle a side, or a range of 2 or 3 alike triangles (cluster sizes of 1
    // or 2) would split into itself and nothing, for ever
    const std::size_t quarter = std::max<std::size_t>(1, (end - begin) / 4);
    if (middle < begin + quarter || middle > end - quarter)
    {
        middle = begin + (end - begin) / 2;
        // note: ties broken by triangle index, so the split is the same on every run and platform
        std::nth_element(order.begin() + long(begin), order.begin() + long(middle), order.begin() + long(end),
                         [&](std::uint32_t a, std::uint32_t b)
                         {
                             const float ca = centroids[3 * a + axis], cb = centroids[3 * b + axis];
                             return ca < cb || (ca == cb && a < b);
                         });
    }
    return middle;
}

// The split, on an explicit stack (depth-first, lower half first): order[] ends up holding the
// triangles leaf by leaf; returns the leaves' ranges of it.
std::vector<std::pair<std::size_t, std::size_t>>
splitIntoLeaves(std::vector<std::uint32_t>& order, const std::vector<float>& centroids, std::uint32_t clusterTriangles)
{
    std::vector<std::pair<std::size_t, std::size_t>> leaves, stack{{0, order.size()}};
    while (!stack.empty())
    {
        const auto [begin, end] = stack.back();
        stack.pop_back();
        if (end - begin <= clusterTriangles)
        {
            leaves.push_back({begin, end});
            continue;
        }
        const std::size_t middle = splitRange(order, centroids, begin, end);
        stack.push_back({middle, end});
        stack.push_back({begin, middle});
    }
    return leaves;
}

// The private drawing geometry: the user's arrays, `indices` as its one primitive set.
osg::ref_ptr<osg::Geometry> drawingGeometry(const osg::Geometry& geometry, osg::DrawElementsUInt* indices)
{
    // note: the private geometry shares the user's arrays; configuring its vertex buffer objects gives
    // those arrays a VertexBufferObject where they had none. The user's own Geometry draws as before:
    // OSG uses an array's buffer object only for a geometry that enables VBOs itself.
    osg::ref_ptr<osg::Geometry> draw = new osg::Geometry;
    auto* source = const_cast<osg::Geometry*>(&geometry);
    draw->setVertexArray(source->getVertexArray());
    draw->setNormalArray(source->getNormalArray());
    draw->setColorArray(source->getColorArray());
    draw->setSecondaryColorArray(source->getSecondaryColorArray());
    draw->setFogCoordArray(source->getFogCoordArray());
    for (unsigned unit = 0; unit < source->getNumTexCoordArrays(); ++unit)
        draw->setTexCoordArray(unit, source->getTexCoordArray(unit));
    for (unsigned index = 0; index < source->getNumVertexAttribArrays(); ++index)
        draw->setVertexAttribArray(index, source->getVertexAttribArray(index));
    draw->addPrimitiveSet(indices);
    draw->setUseDisplayList(false);
    draw->setUseVertexArrayObject(false);
    draw->setUseVertexBufferObjects(true);
    return draw;
}
} // namespace

ClusterLayout::~ClusterLayout() = default;

std::size_t ClusterLayout::memoryBytes() const
{
    return _indices->size() * sizeof(GLuint) + _clusters.size() * sizeof(Cluster) +
           _clusterOfTriangle.size() * sizeof(std::uint32_t) + sizeof(*this) + sizeof(osg::Geometry);
}

osg::ref_ptr<ClusterLayout> ClusterLayout::build(const osg::Geometry& geometry, std::uint32_t clusterTriangles)
{
    if (!clusterableGeometry(geometry, clusterTriangles))
        return nullptr;
    std::vector<float> positions;
    if (!floatPositions(*geometry.getVertexArray(), positions))
        return nullptr;
    std::vector<std::uint32_t> indices;
    if (!triangleIndices(geometry, positions, clusterTriangles, indices))
        return nullptr;
    const std::size_t triangles = indices.size() / 3;

    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    const std::vector<std::pair<std::size_t, std::size_t>> leaves =
        splitIntoLeaves(order, triangleCentroids(positions, indices), clusterTriangles);

    osg::ref_ptr<ClusterLayout> layout = new ClusterLayout;
    layout->_indices = new osg::DrawElementsUInt(GL_TRIANGLES, indices.size());
    osg::DrawElementsUInt& sorted = *layout->_indices;
    layout->_clusterOfTriangle.resize(triangles);
    layout->_clusters.resize(leaves.size());
    for (std::size_t c = 0; c < leaves.size(); ++c)
    {
        const auto [begin, end] = leaves[c];
        layout->_clusters[c] = {std::uint32_t(3 * begin), std::uint32_t(3 * (end - begin))};
        for (std::size_t place = begin; place < end; ++place)
        {
            const std::uint32_t t = order[place];
            for (int k = 0; k < 3; ++k)
                sorted[3 * place + k] = indices[3 * t + k];
            layout->_clusterOfTriangle[t] = std::uint32_t(c);
        }
    }
    layout->_geometry = drawingGeometry(geometry, layout->_indices.get());
    return layout;
}
} // namespace osgVis
