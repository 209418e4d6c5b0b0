// SPDX-License-Identifier: MIT
// The three benchmark scene kinds: determinism, the triangle budget, and walks that stay in the open.
#include "SceneProbe.h"

#include <osgVis/gen/Generator.h>
#include <osgVis/gen/SceneStats.h>

#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <osgDB/Registry>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

namespace gen = osgVis::gen;
using gen::test::drawablesOf;

namespace
{
gen::GeneratedScene make(gen::SceneKind kind, std::uint64_t triangles, std::uint32_t seed = 1)
{
    gen::GenerateOptions options;
    options.kind = kind;
    options.triangles = triangles;
    options.seed = seed;
    return gen::generate(options);
}

// The scene exactly as osgvisgen writes it.
std::string osgbBytes(osg::Node& root)
{
    osgDB::ReaderWriter* writer = osgDB::Registry::instance()->getReaderWriterForExtension("osgb");
    EXPECT_NE(writer, nullptr);
    std::ostringstream out;
    EXPECT_TRUE(writer->writeNode(root, out).success());
    return out.str();
}

osg::BoundingBox sceneBounds(osg::Node& root)
{
    osg::BoundingBox box;
    for (const auto& d : drawablesOf(root))
        box.expandBy(d.worldBounds);
    return box;
}

osg::Vec3 eyeOf(const osgVis::core::WalkKey& key)
{
    return {float(key.eye.x), float(key.eye.y), float(key.eye.z)};
}

// Drawables a walk must never pass through, by kind.
const char* solidName(gen::SceneKind kind)
{
    switch (kind)
    {
    case gen::SceneKind::Office:
    case gen::SceneKind::Floor:
        return "wall";
    case gen::SceneKind::City:
        return "building";
    case gen::SceneKind::Tetra:
        return "tetra";
    case gen::SceneKind::Forest:
        return "trunk";
    }
    return "";
}

class GenKind : public ::testing::TestWithParam<gen::SceneKind>
{
};
} // namespace

TEST_P(GenKind, SameSeedGivesIdenticalBytes)
{
    const gen::GeneratedScene a = make(GetParam(), 20000, 7);
    const gen::GeneratedScene b = make(GetParam(), 20000, 7);
    EXPECT_EQ(gen::sceneStats(*a.root).triangles, gen::sceneStats(*b.root).triangles);
    EXPECT_EQ(osgbBytes(*a.root), osgbBytes(*b.root));
    std::ostringstream walkA, walkB;
    a.walk.write(walkA);
    b.walk.write(walkB);
    EXPECT_EQ(walkA.str(), walkB.str());
}

TEST_P(GenKind, DifferentSeedsGiveDifferentScenes)
{
    const gen::GeneratedScene a = make(GetParam(), 20000, 1);
    const gen::GeneratedScene b = make(GetParam(), 20000, 2);
    EXPECT_NE(osgbBytes(*a.root), osgbBytes(*b.root));
}

TEST_P(GenKind, TriangleCountIsWithinTenPercentOfTheBudget)
{
    for (std::uint64_t budget : {std::uint64_t(1000), std::uint64_t(2000), std::uint64_t(20000), std::uint64_t(200000)})
    {
        const gen::GeneratedScene scene = make(GetParam(), budget);
        const double triangles = double(gen::sceneStats(*scene.root).triangles);
        EXPECT_NEAR(triangles, double(budget), 0.1 * double(budget))
            << gen::sceneKindName(GetParam()) << " at " << budget;
    }
}

TEST_P(GenKind, WalkIsLongSmoothAndInsideTheScene)
{
    const gen::GeneratedScene scene = make(GetParam(), 20000);
    const osgVis::core::Walk& walk = scene.walk;
    ASSERT_GE(walk.keys.size(), 200u);
    EXPECT_EQ(walk.projection.kind, osgVis::core::WalkProjection::Kind::Perspective);
    EXPECT_DOUBLE_EQ(walk.projection.fovY, 60.0);
    EXPECT_DOUBLE_EQ(walk.projection.zNear, 0.1);
    EXPECT_EQ(walk.width, 1280u);
    EXPECT_EQ(walk.height, 1024u);

    const osg::BoundingBox bounds = sceneBounds(*scene.root);
    for (std::size_t i = 0; i < walk.keys.size(); ++i)
    {
        const osg::Vec3 eye = eyeOf(walk.keys[i]);
        EXPECT_NEAR(walk.keys[i].time, 0.1 * double(i), 1e-9);
        EXPECT_TRUE(bounds.contains(eye)) << "view " << i;
        // The far plane reaches every corner of the scene from every eye.
        for (unsigned c = 0; c < 8; ++c)
            EXPECT_LT((bounds.corner(c) - eye).length(), walk.projection.zFar);
        if (i > 0)
        {
            // No jumps: the eye moves at most a bit more than speed × time step.
            const double step = (eye - eyeOf(walk.keys[i - 1])).length();
            EXPECT_LT(step, 1.2) << "view " << i;
        }
    }
}

TEST_P(GenKind, WalkNeverEntersSolidObjects)
{
    const std::pair<std::uint64_t, std::uint32_t> cases[] = {{20000, 1}, {20000, 2}, {20000, 3}, {200000, 4}};
    for (const auto& [budget, seed] : cases)
    {
        const gen::GeneratedScene scene = make(GetParam(), budget, seed);
        std::vector<osg::BoundingBox> solids;
        for (const auto& d : drawablesOf(*scene.root))
            if (d.name == solidName(GetParam()))
                solids.push_back(d.worldBounds);
        ASSERT_FALSE(solids.empty());
        for (std::size_t i = 0; i < scene.walk.keys.size(); ++i)
        {
            const osg::Vec3 eye = eyeOf(scene.walk.keys[i]);
            // Halfway to the previous view too: a wall is about as thick as one office step.
            const osg::Vec3 between = i > 0 ? (eye + eyeOf(scene.walk.keys[i - 1])) * 0.5f : eye;
            for (const osg::BoundingBox& box : solids)
                ASSERT_FALSE(box.contains(eye) || box.contains(between))
                    << "seed " << seed << " view " << i << " is inside a " << solidName(GetParam());
        }
    }
}

TEST_P(GenKind, EveryDrawableHasNormalsAndAColour)
{
    const gen::GeneratedScene scene = make(GetParam(), 20000);
    for (const auto& d : drawablesOf(*scene.root))
    {
        const osg::Geometry* geometry = d.drawable->asGeometry();
        ASSERT_NE(geometry, nullptr);
        ASSERT_NE(geometry->getNormalArray(), nullptr);
        EXPECT_EQ(geometry->getNormalArray()->getNumElements(), geometry->getVertexArray()->getNumElements());
        ASSERT_NE(geometry->getColorArray(), nullptr);
        EXPECT_EQ(geometry->getColorArray()->getBinding(), osg::Array::BIND_OVERALL);
    }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, GenKind,
                         ::testing::Values(gen::SceneKind::Office, gen::SceneKind::City, gen::SceneKind::Tetra),
                         [](const auto& info) { return std::string(gen::sceneKindName(info.param)); });

TEST(GenOffice, PlacesFurnitureByTransformsSharingDrawables)
{
    const gen::GeneratedScene scene = make(gen::SceneKind::Office, 20000);
    std::map<const osg::Drawable*, int> instances;
    for (const auto& d : drawablesOf(*scene.root))
        ++instances[d.drawable];
    int shared = 0;
    for (const auto& entry : instances)
        shared += entry.second > 1 ? 1 : 0;
    EXPECT_GE(shared, 1);

    struct TransformCounter : osg::NodeVisitor
    {
        TransformCounter() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::MatrixTransform& t) override
        {
            ++count;
            traverse(t);
        }
        int count = 0;
    } transforms;
    scene.root->accept(transforms);
    EXPECT_GT(transforms.count, 10);
}

TEST(GenOffice, WalkEntersRoomsAndUsesCorridors)
{
    const gen::GeneratedScene scene = make(gen::SceneKind::Office, 200000);
    std::vector<osg::BoundingBox> rooms, corridors;
    for (const auto& d : drawablesOf(*scene.root))
    {
        if (d.name == "floor")
            rooms.push_back(d.worldBounds);
        if (d.name == "corridor floor")
            corridors.push_back(d.worldBounds);
    }
    auto over = [](const std::vector<osg::BoundingBox>& floors, const osg::Vec3& eye)
    {
        for (const osg::BoundingBox& f : floors)
            if (eye.x() > f.xMin() && eye.x() < f.xMax() && eye.y() > f.yMin() && eye.y() < f.yMax())
                return true;
        return false;
    };
    std::size_t inRooms = 0, inCorridors = 0;
    for (const auto& key : scene.walk.keys)
    {
        inRooms += over(rooms, eyeOf(key)) ? 1 : 0;
        inCorridors += over(corridors, eyeOf(key)) ? 1 : 0;
    }
    EXPECT_GT(inRooms, 100u);
    EXPECT_GT(inCorridors, 100u);
}

TEST(GenOffice, LargeBudgetsStackStoreys)
{
    const gen::GeneratedScene small = make(gen::SceneKind::Office, 20000);
    const gen::GeneratedScene large = make(gen::SceneKind::Office, 2000000);
    EXPECT_LT(sceneBounds(*small.root).zMax(), 3.5f);
    EXPECT_GT(sceneBounds(*large.root).zMax(), 3.5f);
    EXPECT_NEAR(double(gen::sceneStats(*large.root).triangles), 2e6, 2e5);
}

TEST(GenScene, WalksSurviveTheWalkFormat)
{
    for (gen::SceneKind kind : {gen::SceneKind::Office, gen::SceneKind::City, gen::SceneKind::Tetra})
    {
        const osgVis::core::Walk walk = make(kind, 2000).walk;
        std::stringstream text;
        walk.write(text);
        const osgVis::core::Walk back = osgVis::core::Walk::parse(text, "generated");
        ASSERT_EQ(back.keys.size(), walk.keys.size());
        EXPECT_NEAR(back.keys.back().eye.x, walk.keys.back().eye.x, 1e-6);
        EXPECT_DOUBLE_EQ(back.projection.zFar, walk.projection.zFar);
    }
}

TEST(GenScene, KindNamesParseAndBadInputThrows)
{
    EXPECT_EQ(gen::parseSceneKind("office"), gen::SceneKind::Office);
    EXPECT_EQ(gen::parseSceneKind("city"), gen::SceneKind::City);
    EXPECT_EQ(gen::parseSceneKind("tetra"), gen::SceneKind::Tetra);
    EXPECT_THROW(gen::parseSceneKind("castle"), std::invalid_argument);
    EXPECT_THROW(make(gen::SceneKind::City, 999), std::invalid_argument);
    EXPECT_THROW(make(gen::SceneKind::City, gen::maxTriangles + 1), std::invalid_argument);
}
