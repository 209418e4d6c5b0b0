// SPDX-License-Identifier: MIT
// The forest kind: the three layouts' sizes, determinism, closed surfaces (every part a watertight,
// outward-facing mesh), trees split into many objects, the view volumes and a walk that stays clear
// of every part.
#include "SceneProbe.h"

#include <osgVis/gen/Forest.h>
#include <osgVis/gen/Generator.h>
#include <osgVis/gen/SceneStats.h>

#include <osg/Geometry>
#include <osg/TriangleFunctor>

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <tuple>

namespace gen = osgVis::gen;
using gen::test::drawablesOf;

namespace
{
gen::GeneratedScene makeForest(gen::ForestLayout layout, std::uint64_t triangles = 0, std::uint32_t seed = 1)
{
    gen::GenerateOptions options;
    options.kind = gen::SceneKind::Forest;
    options.forestLayout = layout;
    options.triangles = triangles ? triangles : gen::defaultTriangles(gen::SceneKind::Forest, layout);
    options.seed = seed;
    return gen::generate(options);
}

osg::BoundingBox sceneBounds(osg::Node& root)
{
    osg::BoundingBox box;
    for (const auto& d : drawablesOf(root))
        box.expandBy(d.worldBounds);
    return box;
}

struct TriangleList
{
    std::vector<std::array<osg::Vec3, 3>>* out = nullptr;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c) { out->push_back({a, b, c}); }
};

std::vector<std::array<osg::Vec3, 3>> trianglesOf(const osg::Drawable& drawable)
{
    std::vector<std::array<osg::Vec3, 3>> triangles;
    osg::TriangleFunctor<TriangleList> functor;
    functor.out = &triangles;
    const_cast<osg::Drawable&>(drawable).accept(functor);
    return triangles;
}

using Point = std::tuple<float, float, float>;

Point key(const osg::Vec3& v)
{
    return {v.x(), v.y(), v.z()};
}

struct Closure
{
    std::size_t edges = 0, unpaired = 0; // unpaired: a directed edge whose reverse is not used exactly once
    double volume = 0.0;                 // signed, positive when the triangles face outward
};

// Vertices are welded by exact coordinates: a cap's rim repeats its tube's vertices bit for bit, and a
// closed surface uses every directed edge once and its reverse once.
Closure closureOf(const osg::Drawable& drawable)
{
    std::map<std::pair<Point, Point>, int> directed;
    Closure closure;
    for (const auto& t : trianglesOf(drawable))
    {
        for (int i = 0; i < 3; ++i)
            ++directed[{key(t[i]), key(t[(i + 1) % 3])}];
        closure.volume += double((t[0] ^ t[1]) * t[2]) / 6.0;
    }
    for (const auto& [edge, count] : directed)
    {
        ++closure.edges;
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            ++closure.unpaired;
    }
    return closure;
}
} // namespace

TEST(GenForest, LayoutsHaveThePapersTriangleCounts)
{
    const std::pair<gen::ForestLayout, double> layouts[] = {
        {gen::ForestLayout::Single, 12000.0}, {gen::ForestLayout::Line, 72000.0}, {gen::ForestLayout::Dense, 385000.0}};
    for (const auto& [layout, wanted] : layouts)
    {
        const gen::SceneStats stats = gen::sceneStats(*makeForest(layout).root);
        EXPECT_NEAR(double(stats.triangles), wanted, 0.1 * wanted) << gen::forestLayoutName(layout);
        std::cout << gen::forestLayoutName(layout) << ": " << stats.triangles << " triangles, " << stats.objects
                  << " objects" << std::endl;
    }
}

TEST(GenForest, BudgetOnlyChangesTheTessellation)
{
    for (std::uint64_t budget : {std::uint64_t(24000), std::uint64_t(100000), std::uint64_t(1000000)})
    {
        const gen::GeneratedScene scene = makeForest(gen::ForestLayout::Dense, budget);
        const gen::SceneStats stats = gen::sceneStats(*scene.root);
        EXPECT_NEAR(double(stats.triangles), double(budget), 0.1 * double(budget));
        EXPECT_EQ(stats.objects, gen::sceneStats(*makeForest(gen::ForestLayout::Dense).root).objects);
    }
    EXPECT_THROW(makeForest(gen::ForestLayout::Dense, gen::minTrianglesFor(gen::SceneKind::Forest) - 1),
                 std::invalid_argument);
    EXPECT_EQ(gen::minTrianglesFor(gen::SceneKind::Forest, gen::ForestLayout::Single), gen::minTriangles);
}

TEST(GenForest, SameSeedSameSceneOtherSeedOtherTrees)
{
    for (gen::ForestLayout layout : {gen::ForestLayout::Single, gen::ForestLayout::Line, gen::ForestLayout::Dense})
    {
        const gen::GeneratedScene a = makeForest(layout, 0, 5), b = makeForest(layout, 0, 5);
        EXPECT_EQ(gen::sceneStats(*a.root).triangles, gen::sceneStats(*b.root).triangles);
        const osg::BoundingBox boxA = sceneBounds(*a.root), boxB = sceneBounds(*b.root);
        EXPECT_EQ(boxA._min, boxB._min);
        EXPECT_EQ(boxA._max, boxB._max);
        EXPECT_EQ(a.walk.keys.size(), b.walk.keys.size());
        const osg::BoundingBox other = sceneBounds(*makeForest(layout, 0, 6).root);
        EXPECT_NE(other._max, boxA._max) << gen::forestLayoutName(layout);
    }
}

TEST(GenForest, EveryPartIsAClosedOutwardSurface)
{
    // The coarsest meshing (prisms and octahedra) and the paper's.
    for (std::uint64_t budget : {std::uint64_t(4500), std::uint64_t(72000)})
    {
        const gen::GeneratedScene scene = makeForest(gen::ForestLayout::Line, budget);
        std::size_t parts = 0;
        for (const auto& d : drawablesOf(*scene.root))
        {
            const Closure closure = closureOf(*d.drawable);
            ASSERT_GT(closure.edges, 0u) << d.name;
            EXPECT_EQ(closure.unpaired, 0u) << d.name << " " << parts << " at " << budget << " triangles";
            EXPECT_GT(closure.volume, 0.0) << d.name << " " << parts << " faces inward";
            ++parts;
        }
        EXPECT_GT(parts, 6u * 20u);
    }
}

TEST(GenForest, TreesAreSplitIntoTrunkBranchesAndLeafClumps)
{
    const gen::GeneratedScene scene = makeForest(gen::ForestLayout::Line);
    std::map<std::string, std::size_t> byName;
    for (const auto& d : drawablesOf(*scene.root))
    {
        ++byName[d.name];
        const osg::Geometry* geometry = d.drawable->asGeometry();
        ASSERT_NE(geometry, nullptr);
        ASSERT_NE(geometry->getNormalArray(), nullptr);
        EXPECT_EQ(geometry->getNormalArray()->getNumElements(), geometry->getVertexArray()->getNumElements());
    }
    EXPECT_EQ(byName.size(), 3u);
    EXPECT_EQ(byName["trunk"], 6u);
    // 4–6 branches a tree, 2–4 twigs a branch; a clump at the trunk's top and every branch's and twig's tip.
    EXPECT_GE(byName["branch"], 6u * (4 + 4 * 2));
    EXPECT_LE(byName["branch"], 6u * (6 + 6 * 4));
    EXPECT_EQ(byName["leaves"], byName["branch"] + byName["trunk"]);
}

TEST(GenForest, ViewVolumesSitTwoTreeHeightsOutsideTheTrees)
{
    for (gen::ForestLayout layout : {gen::ForestLayout::Single, gen::ForestLayout::Line, gen::ForestLayout::Dense})
    {
        const gen::GeneratedScene scene = makeForest(layout);
        const osg::BoundingBox bounds = sceneBounds(*scene.root);
        const osg::BoundingBoxd volume = gen::forestViewVolume(layout);
        const osg::Vec3d size = volume._max - volume._min;
        EXPECT_NEAR(size.x(), size.y(), 1e-12);
        EXPECT_NEAR(size.x(), size.z(), 1e-12);
        const double height = size.x() / 0.02;
        EXPECT_NEAR(height, bounds.zMax(), 0.15 * bounds.zMax()) << gen::forestLayoutName(layout);
        EXPECT_NEAR(volume.center().z(), 0.5 * height, 1e-9);
        // West of every trunk by two heights, so outside every part.
        std::vector<osg::BoundingBox> trunks;
        for (const auto& d : drawablesOf(*scene.root))
        {
            EXPECT_FALSE(d.worldBounds.intersects(osg::BoundingBox(volume._min, volume._max)));
            if (d.name == "trunk")
                trunks.push_back(d.worldBounds);
        }
        double westmost = trunks.front().center().x();
        for (const osg::BoundingBox& t : trunks)
            westmost = std::min(westmost, double(t.center().x()));
        EXPECT_NEAR(westmost - volume.center().x(), 2.0 * height, 1e-3);
        EXPECT_GE(volume.center().y(), bounds.yMin());
        EXPECT_LE(volume.center().y(), bounds.yMax());
    }
    EXPECT_EQ(gen::forestViewVolume(gen::ForestLayout::Line)._min,
              gen::forestViewVolume(gen::ForestLayout::Line, 1)._min);
    EXPECT_NE(gen::forestViewVolume(gen::ForestLayout::Single, 1)._min,
              gen::forestViewVolume(gen::ForestLayout::Single, 2)._min);
}

TEST(GenForest, WalkStaysAtEyeHeightClearOfEveryPart)
{
    for (gen::ForestLayout layout : {gen::ForestLayout::Single, gen::ForestLayout::Line, gen::ForestLayout::Dense})
    {
        const gen::GeneratedScene scene = makeForest(layout, 0, 3);
        ASSERT_GE(scene.walk.keys.size(), 200u);
        const std::vector<gen::test::DrawableInstance> parts = drawablesOf(*scene.root);
        const osg::BoundingBox bounds = sceneBounds(*scene.root);
        for (std::size_t i = 0; i < scene.walk.keys.size(); ++i)
        {
            const auto& key = scene.walk.keys[i];
            const osg::Vec3 eye(float(key.eye.x), float(key.eye.y), float(key.eye.z));
            EXPECT_NEAR(eye.z(), 1.7f, 1e-4f);
            for (const auto& part : parts)
                ASSERT_FALSE(part.worldBounds.contains(eye)) << "view " << i << " inside a " << part.name;
            for (unsigned c = 0; c < 8; ++c)
                EXPECT_LT((bounds.corner(c) - eye).length(), scene.walk.projection.zFar);
        }
    }
}

TEST(GenForest, LayoutNamesParse)
{
    EXPECT_EQ(gen::parseSceneKind("forest"), gen::SceneKind::Forest);
    EXPECT_STREQ(gen::sceneKindName(gen::SceneKind::Forest), "forest");
    for (const std::string& name : gen::forestLayoutNames())
        EXPECT_EQ(gen::forestLayoutName(gen::parseForestLayout(name)), name);
    EXPECT_EQ(gen::forestTreeCount(gen::ForestLayout::Single), 1u);
    EXPECT_EQ(gen::forestTreeCount(gen::ForestLayout::Line), 6u);
    EXPECT_EQ(gen::forestTreeCount(gen::ForestLayout::Dense), 32u);
    EXPECT_THROW(gen::parseForestLayout("jungle"), std::invalid_argument);
}
