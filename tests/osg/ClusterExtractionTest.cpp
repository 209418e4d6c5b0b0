// SPDX-License-Identifier: MIT
// Clusters at extraction (docs/clusters.md): a large drawable becomes one object per cluster, with
// exactly its triangles among them, consecutive ids per instance, find/idsOf over the clusters,
// occluder polygons built over the whole drawable and naming their clusters; drawables that must
// stay whole (small, draw callback, lines, explicit bound, option off) stay one object.
#include "ClusterScenes.h"

#include <osgVis/SceneExtractor>

#include <osgVis/core/occluders/OccluderBuilder.h>

#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/TriangleFunctor>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

using namespace osgVis::test;

namespace
{
osgVis::ExtractionOptions clusterOptions(std::uint32_t threshold = 1000, std::uint32_t size = 128)
{
    osgVis::ExtractionOptions options;
    options.clusterThreshold = threshold;
    options.clusterTriangles = size;
    return options;
}

// A wall of 24 × 24 cells and a row of patches of every primitive kind behind it.
std::vector<Patch> wallAndRow()
{
    std::vector<Patch> patches{{{-12, 10, 0}, {24, 0, 0}, {0, 0, 12}, 24, {0.8f, 0.8f, 0.8f, 1}, PatchKind::Triangles}};
    const PatchKind kinds[] = {PatchKind::Triangles, PatchKind::TrianglesShort, PatchKind::Strips, PatchKind::Quads,
                               PatchKind::Fans,      PatchKind::QuadStrips,     PatchKind::ArrayTriangles};
    for (int i = 0; i < 8; ++i)
        patches.push_back({{-10.f + 2.5f * i, 25, 0}, {1, 0, 0}, {0, 0, 2}, 12, {0.3f, 0.4f, 1, 1}, kinds[i % 7]});
    return patches;
}

unsigned totalTriangles(const std::vector<Patch>& patches)
{
    unsigned n = 0;
    for (const Patch& p : patches)
        n += patchTriangles(p);
    return n;
}

struct CountTriangles
{
    unsigned count = 0;
    void operator()(const osg::Vec3&, const osg::Vec3&, const osg::Vec3&) { ++count; }
};

bool inside(const osgVis::core::Aabb& box, const osgVis::core::Vec3f& p)
{
    return p.x >= box.min.x && p.y >= box.min.y && p.z >= box.min.z && p.x <= box.max.x && p.y <= box.max.y &&
           p.z <= box.max.z;
}
} // namespace

TEST(Clusters, LargeDrawableOfEveryPrimitiveKindBecomesClustersHoldingExactlyItsTriangles)
{
    const std::vector<Patch> patches = wallAndRow();
    osg::ref_ptr<osg::Geometry> mesh = makePatchedMesh(patches);
    osg::TriangleFunctor<CountTriangles> counter;
    mesh->accept(counter);
    ASSERT_EQ(counter.count, totalTriangles(patches)); // the scene builder itself

    osg::ref_ptr<osg::Geode> root = new osg::Geode;
    root->addDrawable(mesh);
    const osg::ref_ptr<osgVis::ExtractedScene> whole = osgVis::extractScene(*root, clusterOptions(0));
    ASSERT_EQ(whole->scene.objects.size(), 1u);
    const osg::ref_ptr<osgVis::ExtractedScene> split = osgVis::extractScene(*root, clusterOptions());
    const std::size_t expected = split->scene.objects.size();
    ASSERT_GE(expected, (totalTriangles(patches) + 127) / 128);
    EXPECT_EQ(split->clusteredDrawables, 1u);

    const std::vector<osgVis::core::ObjectId>& ids = split->idsOf(mesh.get());
    std::vector<osgVis::core::ObjectId> all(expected);
    std::iota(all.begin(), all.end(), 0u);
    EXPECT_EQ(ids, all);
    EXPECT_EQ(split->find(mesh.get(), split->refs[0].path), 0u);

    osgVis::core::Aabb unionOfClusters;
    std::uint64_t triangles = 0;
    for (osgVis::core::ObjectId id : ids)
    {
        const osgVis::core::SceneObject& object = split->scene.objects[id];
        const osgVis::ObjectRef& ref = split->refs[id];
        ASSERT_TRUE(ref.clusters);
        EXPECT_EQ(ref.cluster, id);
        EXPECT_EQ(object.group, 0u);
        EXPECT_GE(object.triangleCount, 16u);
        EXPECT_LE(object.triangleCount, 128u);
        EXPECT_EQ(object.triangleCount * 3, ref.clusters->clusters()[id].indexCount);
        triangles += object.triangleCount;
        for (std::uint32_t t = object.firstTriangle; t < object.firstTriangle + object.triangleCount; ++t)
        {
            const osgVis::core::Triangle& tri = split->scene.triangles[t];
            EXPECT_TRUE(inside(object.bounds, tri.a) && inside(object.bounds, tri.b) && inside(object.bounds, tri.c));
        }
        unionOfClusters.expand(object.bounds);
    }
    EXPECT_EQ(triangles, totalTriangles(patches));
    EXPECT_EQ(split->scene.triangles.size(), whole->scene.triangles.size());
    EXPECT_EQ(unionOfClusters.min, whole->scene.objects[0].bounds.min);
    EXPECT_EQ(unionOfClusters.max, whole->scene.objects[0].bounds.max);

    // The cluster of each triangle in TriangleFunctor order agrees with the cluster sizes.
    const osgVis::ClusterLayout& layout = *split->refs[0].clusters;
    std::vector<std::uint32_t> perCluster(layout.size(), 0);
    ASSERT_EQ(layout.clusterOfTriangle().size(), totalTriangles(patches));
    for (std::uint32_t c : layout.clusterOfTriangle())
        ++perCluster[c];
    for (std::size_t c = 0; c < layout.size(); ++c)
        EXPECT_EQ(perCluster[c] * 3, layout.clusters()[c].indexCount);

    // Spatially coherent: the wall's clusters are small pieces of it, not strips across the mesh.
    const osgVis::core::Vec3 extent = whole->scene.objects[0].bounds.extent();
    double largest = 0.0;
    for (const osgVis::core::SceneObject& object : split->scene.objects)
        largest = std::max(largest, glm::length(object.bounds.extent()));
    EXPECT_LT(largest, 0.5 * glm::length(extent));
}

TEST(Clusters, InstancesShareOneLayoutWithConsecutiveIdsEach)
{
    osg::ref_ptr<osg::Geometry> mesh = makePatchedMesh(wallAndRow());
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(mesh);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    for (int i = 0; i < 2; ++i)
    {
        osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform(osg::Matrix::translate(100.0 * i, 0, 0));
        t->addChild(geode);
        root->addChild(t);
    }
    const osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(*root, clusterOptions());
    const std::size_t n = scene->refs[0].clusters->size();
    ASSERT_EQ(scene->scene.objects.size(), 2 * n);
    EXPECT_EQ(scene->idsOf(mesh.get()).size(), 2 * n);
    EXPECT_EQ(scene->refs[n].clusters, scene->refs[0].clusters);
    EXPECT_EQ(scene->find(mesh.get(), scene->refs[n].path), n);
    EXPECT_EQ(scene->refs[n].cluster, 0u);
    EXPECT_EQ(scene->scene.objects[n].group, n);
    EXPECT_EQ(scene->clusteredDrawables, 1u);
    EXPECT_GT(scene->scene.objects[n].bounds.min.x, 50.0);
}

TEST(Clusters, DrawablesThatMustStayWholeStayOneObject)
{
    const auto objectsOf = [](osg::Drawable* d)
    {
        osg::ref_ptr<osg::Geode> root = new osg::Geode;
        root->addDrawable(d);
        return osgVis::extractScene(*root, clusterOptions())->scene.objects.size();
    };
    struct OwnDraw : osg::Drawable::DrawCallback
    {
    };
    osg::ref_ptr<osg::Geometry> withCallback = makePatchedMesh(wallAndRow());
    withCallback->setDrawCallback(new OwnDraw);
    EXPECT_EQ(objectsOf(withCallback.get()), 1u);

    osg::ref_ptr<osg::Geometry> withLines = makePatchedMesh(wallAndRow());
    withLines->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, 2));
    EXPECT_EQ(objectsOf(withLines.get()), 1u);

    osg::ref_ptr<osg::Geometry> withBound = makePatchedMesh(wallAndRow());
    withBound->setInitialBound(osg::BoundingBox(-100, -100, -100, 100, 100, 100));
    EXPECT_EQ(objectsOf(withBound.get()), 1u);

    osg::ref_ptr<osg::Geometry> small = makePatchedMesh({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20}}); // 800 triangles
    EXPECT_EQ(objectsOf(small.get()), 1u);

    osg::ref_ptr<osg::Geometry> plain = makePatchedMesh(wallAndRow());
    EXPECT_GT(objectsOf(plain.get()), 1u);
}

TEST(Clusters, OccluderPolygonsSpanClustersAndNameThem)
{
    // The wall alone, in clusters of 64: its one plane merges across cluster borders.
    osg::ref_ptr<osg::Geometry> wall =
        makePatchedMesh({{{-12, 10, 0}, {24, 0, 0}, {0, 0, 12}, 24, {1, 1, 1, 1}, PatchKind::Triangles}});
    osg::ref_ptr<osg::Geode> root = new osg::Geode;
    root->addDrawable(wall);
    const osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(*root, clusterOptions(1000, 64));
    const std::size_t clusters = scene->scene.objects.size();
    ASSERT_GE(clusters, 18u);
    const std::vector<osgVis::core::OccluderPolygon> polygons = osgVis::core::buildOccluderPolygons(scene->scene);
    ASSERT_FALSE(polygons.empty());
    double largest = 0.0;
    std::set<osgVis::core::ObjectId> named;
    for (const osgVis::core::OccluderPolygon& p : polygons)
    {
        EXPECT_TRUE(std::is_sorted(p.parts.begin(), p.parts.end()));
        if (!p.parts.empty())
        {
            EXPECT_EQ(p.owner, p.parts.front());
        }
        named.insert(p.owner);
        named.insert(p.parts.begin(), p.parts.end());
        if (p.area > largest)
            largest = p.area;
    }
    // One polygon covers the whole wall (24 × 12), so it names every cluster.
    EXPECT_NEAR(largest, 288.0, 1e-6);
    const auto whole = std::find_if(polygons.begin(), polygons.end(),
                                    [](const osgVis::core::OccluderPolygon& p) { return std::abs(p.area - 288.0) < 1e-6; });
    EXPECT_EQ(whole->parts.size(), clusters);
    EXPECT_EQ(named.size(), clusters);
}

// Cluster sizes of 1 or 2 with triangles whose centroids coincide: a range of 2 or 3 alike triangles
// once split into itself and nothing, for ever. Every cut now leaves a triangle on each side.
TEST(Clusters, AlikeTrianglesSplitDownToClustersOfOne)
{
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    for (int copy = 0; copy < 12; ++copy)
        for (const osg::Vec3& corner : {osg::Vec3(0, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(0, 1, 0)})
            vertices->push_back(corner);
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setVertexArray(vertices);
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(vertices->size())));
    for (const std::uint32_t size : {1u, 2u})
    {
        osg::ref_ptr<osgVis::ClusterLayout> layout = osgVis::ClusterLayout::build(*geometry, size);
        ASSERT_TRUE(layout) << size;
        EXPECT_GE(layout->size(), 12u / size / 2) << size;
        std::size_t triangles = 0;
        for (const osgVis::ClusterLayout::Cluster& cluster : layout->clusters())
        {
            EXPECT_LE(cluster.indexCount / 3, size);
            triangles += cluster.indexCount / 3;
        }
        EXPECT_EQ(triangles, 12u) << size;
    }
}
