// SPDX-License-Identifier: MIT
// The adversarial set exists, each scene has a short walk, and each holds the trap it is named for.
#include "SceneProbe.h"

#include <osgVis/gen/Generator.h>
#include <osgVis/gen/SceneStats.h>

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <gtest/gtest.h>

#include <cmath>

namespace gen = osgVis::gen;
using gen::test::drawablesOf;
using Kind = osgVis::core::WalkProjection::Kind;

TEST(GenAdversarial, EveryNamedSceneExistsWithAShortWalk)
{
    const std::vector<std::string> names = gen::adversarialSceneNames();
    for (const char* expected : {"thin-slit", "frame-edges", "off-centre", "ortho", "degenerate-occluders",
                                 "eye-on-occluder-plane", "geode-one-hidden", "moving-occluder"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    for (const std::string& name : names)
    {
        const gen::GeneratedScene scene = gen::adversarialScene(name);
        ASSERT_TRUE(scene.root.valid()) << name;
        EXPECT_GE(gen::sceneStats(*scene.root).objects, 2u) << name;
        EXPECT_GE(scene.walk.keys.size(), 2u) << name;
        EXPECT_LE(scene.walk.keys.size(), 20u) << name;
        EXPECT_GT(scene.walk.projection.zFar, scene.walk.projection.zNear) << name;
    }
}

TEST(GenAdversarial, UnknownNameThrowsNamingTheKnownOnes)
{
    try
    {
        gen::adversarialScene("no-such-scene");
        FAIL() << "expected std::invalid_argument";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("thin-slit"), std::string::npos);
    }
}

TEST(GenAdversarial, ProjectionsAreTheOnesNamed)
{
    EXPECT_EQ(gen::adversarialScene("off-centre").walk.projection.kind, Kind::Frustum);
    const osgVis::core::Walk offCentre = gen::adversarialScene("off-centre").walk;
    EXPECT_NE(offCentre.projection.left, -offCentre.projection.right);
    EXPECT_NE(offCentre.projection.bottom, -offCentre.projection.top);
    EXPECT_EQ(gen::adversarialScene("ortho").walk.projection.kind, Kind::Ortho);
    EXPECT_EQ(gen::adversarialScene("thin-slit").walk.projection.kind, Kind::Perspective);
}

TEST(GenAdversarial, ThinSlitIsTwoCentimetres)
{
    const gen::GeneratedScene scene = gen::adversarialScene("thin-slit");
    float left = -1e9f, right = 1e9f;
    for (const auto& d : drawablesOf(*scene.root))
    {
        if (d.name == "wall left")
            left = d.worldBounds.xMax();
        if (d.name == "wall right")
            right = d.worldBounds.xMin();
    }
    EXPECT_NEAR(right - left, 0.02f, 1e-5f);
}

TEST(GenAdversarial, DegenerateOccludersIncludeANaNVertex)
{
    const gen::GeneratedScene scene = gen::adversarialScene("degenerate-occluders");
    bool nan = false;
    int polygons = 0;
    for (const auto& d : drawablesOf(*scene.root))
    {
        const auto* vertices = dynamic_cast<const osg::Vec3Array*>(d.drawable->asGeometry()->getVertexArray());
        for (const osg::Vec3& v : *vertices)
            nan = nan || std::isnan(v.x());
        polygons += d.name != "target" ? 1 : 0;
    }
    EXPECT_TRUE(nan);
    EXPECT_EQ(polygons, 6);
}

TEST(GenAdversarial, EyeLiesExactlyOnAWallPlane)
{
    const gen::GeneratedScene scene = gen::adversarialScene("eye-on-occluder-plane");
    EXPECT_EQ(scene.walk.keys[0].eye.x, 0.0); // plane of the zero-thickness wall
    EXPECT_EQ(scene.walk.keys[1].eye.x, 3.0); // plane of the box wall's face
    EXPECT_EQ(scene.walk.keys[2].eye.z, 3.0); // plane of the box wall's top
}

TEST(GenAdversarial, GeodeOneHiddenIsOneGeodeOfManyDrawables)
{
    const gen::GeneratedScene scene = gen::adversarialScene("geode-one-hidden");
    ASSERT_EQ(scene.root->getNumChildren(), 1u);
    const osg::Geode* geode = scene.root->getChild(0)->asGeode();
    ASSERT_NE(geode, nullptr);
    EXPECT_GE(geode->getNumDrawables(), 8u);
    int hidden = 0;
    for (unsigned i = 0; i < geode->getNumDrawables(); ++i)
        hidden += geode->getDrawable(i)->getName() == "hidden" ? 1 : 0;
    EXPECT_EQ(hidden, 1);
}

TEST(GenAdversarial, MovingOccluderIsUnderADynamicTransform)
{
    const gen::GeneratedScene scene = gen::adversarialScene("moving-occluder");
    struct Finder : osg::NodeVisitor
    {
        Finder() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::MatrixTransform& t) override
        {
            dynamic = dynamic || t.getDataVariance() == osg::Object::DYNAMIC;
            traverse(t);
        }
        bool dynamic = false;
    } finder;
    scene.root->accept(finder);
    EXPECT_TRUE(finder.dynamic);
}
