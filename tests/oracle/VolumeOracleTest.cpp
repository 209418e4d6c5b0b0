// SPDX-License-Identifier: MIT
// The volume oracle on a wall with a hole, seen from a box of eyes in front of it:
//
//        z                      side view (x = 0)            top view (z = 0)
//        ^
//   wall |  ######   ######     y = 0 … 0.01: the wall, a 0.5 m square hole at the origin
//        |  ######   ######     A (0, 2, 0): straight behind the hole, every central eye sees it
//        |        [ ]           C (-1.42, 1.03, -1.42): seen through the hole only from near the
//        |  ######   ######         box's corner (1, -1, 1), so of the sampled eyes only that corner
//        +----------------> x   B (8, 1, 0): behind the wall from everywhere in the box
//                               away / both: quads at y = 3 facing +y, behind the hole; `away` has
//   eyes: x, z in [-1, 1], y in [-3, -1]      face culling on, so no eye sees it; `both` is two-sided
#include "OracleTestScenes.h"

#include <osgVis/oracle/CubeFaceViews.h>
#include <osgVis/oracle/RayCast.h>
#include <osgVis/oracle/VolumeOracle.h>

#include <osg/CullFace>
#include <osg/Geometry>

#include <gtest/gtest.h>

#include <algorithm>

using namespace oracletest;
using osgVis::oracle::VolumeOracle;
using osgVis::oracle::VolumeOracleSettings;
using osgVis::oracle::VolumeVisibility;
using Names = std::vector<std::string>;

namespace
{
const osg::BoundingBoxd eyeBox(-1, -3, -1, 1, -1, 1);
const osg::Vec3d seeingCorner(1, -1, 1);

// A quad in the plane y = y0 facing +y (counter-clockwise seen from +y).
osg::ref_ptr<osg::Geometry> quadFacingPlusY(float x0, float x1, float z0, float z1, float y0, const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const osg::Vec3& p :
         {osg::Vec3(x0, y0, z0), osg::Vec3(x0, y0, z1), osg::Vec3(x1, y0, z1), osg::Vec3(x1, y0, z0)})
        v->push_back(p);
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(name);
    geometry->setVertexArray(v.get());
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    return geometry;
}

osg::ref_ptr<osg::Group> wallWithHole()
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> wall = new osg::Geode;
    const float h = 0.25f, t = 0.005f; // half the hole, half the wall's thickness
    wall->addDrawable(makeBox({-5.125f, t, 0}, {5 - h / 2, t, 10}, "wall left"));
    wall->addDrawable(makeBox({5.125f, t, 0}, {5 - h / 2, t, 10}, "wall right"));
    wall->addDrawable(makeBox({0, t, -5.125f}, {h, t, 5 - h / 2}, "wall below"));
    wall->addDrawable(makeBox({0, t, 5.125f}, {h, t, 5 - h / 2}, "wall above"));
    root->addChild(wall.get());
    root->addChild(inGeode(makeBox({0, 2, 0}, {0.2f, 0.2f, 0.2f}, "A")));
    root->addChild(inGeode(makeBox({8, 1, 0}, {0.3f, 0.3f, 0.3f}, "B")));
    root->addChild(inGeode(makeBox({-1.42f, 1.03f, -1.42f}, {0.03f, 0.03f, 0.03f}, "C")));
    osg::ref_ptr<osg::Geode> away = inGeode(quadFacingPlusY(-0.3f, 0.3f, 0.3f, 0.6f, 3, "away"));
    away->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));
    root->addChild(away.get());
    root->addChild(inGeode(quadFacingPlusY(-0.3f, 0.3f, -0.6f, -0.3f, 3, "both")));
    return root;
}

std::uint32_t indexOf(const VolumeOracle& oracle, const std::string& name)
{
    for (std::uint32_t i = 0; i < oracle.objects().size(); ++i)
        if (oracle.objects()[i].drawable->getName() == name)
            return i;
    return ~0u;
}

bool contains(const std::vector<std::uint32_t>& sorted, std::uint32_t value)
{
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

VolumeOracleSettings fastSettings()
{
    VolumeOracleSettings settings;
    settings.faceSize = 128;
    settings.perEyeTriangles = true;
    return settings;
}
} // namespace

TEST(VolumeOracle, WallWithHoleKeepsWhatSomeEyeSeesAndNothingElse)
{
    osg::ref_ptr<osg::Group> root = wallWithHole();
    VolumeOracle oracle(root.get(), fastSettings());
    const VolumeVisibility seen = oracle.visibleFrom(eyeBox);
    ASSERT_EQ(seen.eyes.size(), 8u + 6u + 48u);
    EXPECT_EQ(namesOf(drawablesOf(oracle), seen.objects),
              (Names{"A", "C", "both", "wall above", "wall below", "wall left", "wall right"}));

    // The union is exactly the union of the eyes' sets; C comes from the one corner alone.
    std::vector<std::uint32_t> union_;
    const std::uint32_t c = indexOf(oracle, "C");
    for (const VolumeVisibility::Eye& eye : seen.eyes)
    {
        union_.insert(union_.end(), eye.objects.begin(), eye.objects.end());
        EXPECT_EQ(contains(eye.objects, c), eye.position == seeingCorner)
            << "eye " << eye.position.x() << "," << eye.position.y() << "," << eye.position.z();
    }
    std::sort(union_.begin(), union_.end());
    union_.erase(std::unique(union_.begin(), union_.end()), union_.end());
    EXPECT_EQ(union_, seen.objects);
}

TEST(VolumeOracle, TheCornerOnlyObjectIsConfirmedByRayCasting)
{
    // The ray caster shares nothing with the renders: from the corner it finds C in a cube face,
    // from the face centre next to it (1, -2, 0) in none.
    osg::ref_ptr<osg::Group> root = wallWithHole();
    const std::vector<osgVis::oracle::OracleObject> objects = osgVis::oracle::enumerateObjects(*root);
    std::uint32_t c = 0;
    while (objects[c].drawable->getName() != "C")
        ++c;
    const osgVis::oracle::RayCaster rays(objects);
    const auto sees = [&](const osg::Vec3d& eye)
    {
        for (const osg::Matrixd& view : osgVis::oracle::cubeFaceViews(eye))
        {
            const std::vector<std::uint32_t> visible =
                rays.visible(view, osgVis::oracle::cubeFaceProjection(0.01, 50.0), 128, 128);
            if (contains(visible, c))
                return true;
        }
        return false;
    };
    EXPECT_TRUE(sees(seeingCorner));
    EXPECT_FALSE(sees({1, -2, 0}));
    EXPECT_FALSE(sees({0.8, -1, 0.8})); // 20 cm in from the corner: the hole no longer lines up
}

TEST(VolumeOracle, TrianglesSeenAreThoseOfTheObjectsSeen)
{
    osg::ref_ptr<osg::Group> root = wallWithHole();
    VolumeOracle oracle(root.get(), fastSettings());
    const VolumeVisibility seen = oracle.visibleFrom(eyeBox);
    ASSERT_EQ(oracle.triangleCount(), 4u * 12u + 3u * 12u + 2u * 2u);
    std::vector<std::uint32_t> firstOf;
    for (std::uint32_t i = 0; i <= oracle.objects().size(); ++i)
        firstOf.push_back(oracle.firstTriangle(i));
    std::vector<std::uint32_t> objectsOfTriangles;
    for (std::uint32_t t : seen.triangles)
        objectsOfTriangles.push_back(
            std::uint32_t(std::upper_bound(firstOf.begin(), firstOf.end(), t) - firstOf.begin()) - 1);
    objectsOfTriangles.erase(std::unique(objectsOfTriangles.begin(), objectsOfTriangles.end()),
                             objectsOfTriangles.end());
    EXPECT_EQ(objectsOfTriangles, seen.objects);

    // A is seen from the front only: its -y face (triangles 4, 5) and, from off-centre eyes, the
    // faces towards them, never its back (+y: 6, 7).
    const std::uint32_t a = firstOf[indexOf(oracle, "A")];
    EXPECT_TRUE(contains(seen.triangles, a + 4) && contains(seen.triangles, a + 5));
    EXPECT_FALSE(contains(seen.triangles, a + 6) || contains(seen.triangles, a + 7));
    // The two-sided quad shows both its triangles; the culled one none.
    const std::uint32_t both = firstOf[indexOf(oracle, "both")], away = firstOf[indexOf(oracle, "away")];
    EXPECT_TRUE(contains(seen.triangles, both) && contains(seen.triangles, both + 1));
    EXPECT_FALSE(contains(seen.triangles, away) || contains(seen.triangles, away + 1));

    // Each eye's triangles lie in the union, and the union is theirs.
    std::vector<std::uint8_t> fromEyes(oracle.triangleCount(), 0);
    for (const VolumeVisibility::Eye& eye : seen.eyes)
        for (std::uint32_t t : eye.triangles)
            fromEyes[t] = 1;
    std::vector<std::uint32_t> union_;
    for (std::uint32_t t = 0; t < fromEyes.size(); ++t)
        if (fromEyes[t])
            union_.push_back(t);
    EXPECT_EQ(union_, seen.triangles);
}

TEST(VolumeOracle, ClipPlanesFollowTheBoxAndTheScene)
{
    osg::ref_ptr<osg::Group> root = wallWithHole();
    VolumeOracleSettings settings = fastSettings();
    settings.faceSize = 16;
    settings.interiorEyes = 0;
    settings.triangles = false;
    VolumeOracle oracle(root.get(), settings);
    const VolumeVisibility seen = oracle.visibleFrom(eyeBox);
    EXPECT_EQ(seen.eyes.size(), 14u);
    EXPECT_EQ(oracle.triangleCount(), 0u);
    EXPECT_TRUE(seen.triangles.empty());
    const osg::BoundingSphere scene = root->getBound();
    EXPECT_DOUBLE_EQ(seen.zNear, std::min(1e-3 * 2.0 * scene.radius(), 0.25 * 2.0));
    // Far enough for the scene's farthest point from the farthest eye.
    for (unsigned c = 0; c < 8; ++c)
        EXPECT_GT(seen.zFar, (eyeBox.corner(c) - osg::Vec3d(scene.center())).length() + scene.radius());
    EXPECT_THROW(oracle.visibleFrom(osg::BoundingBoxd()), std::invalid_argument);
}
