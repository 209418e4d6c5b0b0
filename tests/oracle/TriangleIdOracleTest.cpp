// SPDX-License-Identifier: MIT
// Triangle IDs: the triangles seen in one view of a tiny scene, worked out by hand; the numbering is
// the extraction's (core::Scene::triangles); transparent triangles hide nothing, not even each other;
// and ids above 24 bits survive the render.
//
//   eye (0, -5, 0) looking +y, 90°:
//
//   y = 3    [L]      [M]      [R]   [F]        quads of one GL_QUADS drawable; F: the finite half of a
//                                               drawable whose other triangle has a NaN corner
//   y = 2          [away]  [both]                quads facing +y: one culled (CullFace on its geode),
//                                               one two-sided
//   y = -1..1      [ box ]                      12 triangles; only its -y face (4, 5) is seen
//          eye
#include "OracleTestScenes.h"

#include <osgVis/SceneExtractor>
#include <osgVis/oracle/CubeFaceViews.h>
#include <osgVis/oracle/TriangleIdOracle.h>

#include "IdColour.h"
#include "IdPassState.h"
#include "IdViewer.h"

#include <osg/CullFace>
#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

using namespace oracletest;
using osgVis::oracle::TriangleIdOracle;
using Indices = std::vector<std::uint32_t>;

namespace
{
constexpr unsigned Size = 128;

// Quads in the plane y = y0 over [x0, x1] × [z0, z1], counter-clockwise seen from -y (or from +y).
void addQuadY(osg::Vec3Array& v, float x0, float x1, float z0, float z1, float y0, bool facingMinusY)
{
    osg::Vec3 corners[4] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}};
    if (!facingMinusY)
        std::swap(corners[1], corners[3]);
    for (const osg::Vec3& c : corners)
        v.push_back(c);
}

osg::ref_ptr<osg::Geometry> quadsY(const std::vector<std::array<float, 4>>& spans, float y0, bool facingMinusY,
                                   const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const auto& s : spans)
        addQuadY(*v, s[0], s[1], s[2], s[3], y0, facingMinusY);
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(name);
    geometry->setVertexArray(v.get());
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, GLsizei(v->size())));
    return geometry;
}

// Two triangles, the first with a NaN corner (never drawn, never numbered), the second at y = 3.
osg::ref_ptr<osg::Geometry> halfNaN()
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const osg::Vec3& p : {osg::Vec3(5, 3, -1), osg::Vec3(nan, 3, -1), osg::Vec3(6, 3, 1), //
                               osg::Vec3(5, 3, -1), osg::Vec3(7, 3, -1), osg::Vec3(6, 3, 1)})
        v->push_back(p);
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName("half NaN");
    geometry->setVertexArray(v.get());
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 6));
    return geometry;
}

osg::ref_ptr<osg::Group> tinyScene()
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "box"))); // 0..11
    root->addChild(inGeode(quadsY({{-4, -2.5, -0.5, 0.5}, {-0.5, 0.5, -0.5, 0.5}, {2.5, 4, -0.5, 0.5}}, 3, true,
                                  "L M R")));                                                      // 12..17
    root->addChild(inGeode(halfNaN()));                                                            // 18
    osg::ref_ptr<osg::Geode> culled = inGeode(quadsY({{-5, -3, 2, 3}}, 2, false, "away, culled")); // 19, 20
    culled->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));
    root->addChild(culled.get());
    root->addChild(inGeode(quadsY({{3, 5, 2, 3}}, 2, false, "away, two-sided"))); // 21, 22
    return root;
}

struct View
{
    osg::Matrixd view, projection;
};

View lookingAlongY()
{
    return {osg::Matrixd::lookAt(osg::Vec3d(0, -5, 0), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1)),
            osgVis::oracle::cubeFaceProjection(0.1, 100.0)};
}
} // namespace

TEST(TriangleIdOracle, TinySceneShowsTheTrianglesWorkedOutByHand)
{
    osg::ref_ptr<osg::Group> root = tinyScene();
    TriangleIdOracle oracle(osgVis::oracle::enumerateObjects(*root), Size, Size);
    ASSERT_EQ(oracle.triangleCount(), 23u);
    EXPECT_EQ(oracle.firstTriangle(1), 12u);
    EXPECT_EQ(oracle.firstTriangle(2), 18u);
    EXPECT_EQ(oracle.firstTriangle(3), 19u);
    EXPECT_EQ(oracle.firstTriangle(5), 23u);
    const View v = lookingAlongY();
    // The box's -y face; L and R (M is behind the box); F; the two-sided quad, not the culled one.
    EXPECT_EQ(oracle.visible(v.view, v.projection), (Indices{4, 5, 12, 13, 16, 17, 18, 21, 22}));

    std::vector<std::uint8_t> seen(oracle.triangleCount(), 0);
    EXPECT_EQ(oracle.markVisible(v.view, v.projection, seen), 9u);
    EXPECT_EQ(oracle.markVisible(v.view, v.projection, seen), 0u); // accumulates: nothing new
}

TEST(TriangleIdOracle, NumbersTrianglesAsTheExtractionStoresThem)
{
    osg::ref_ptr<osg::Group> root = tinyScene();
    // A drawable under two transforms is two objects with a range each.
    osg::ref_ptr<osg::Geode> shared = inGeode(makeBox({0, 0, 0}, {0.2f, 0.2f, 0.2f}, "shared"));
    for (double x : {-3.0, 3.0})
    {
        osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(osg::Matrixd::translate(x, 6, 0));
        placed->addChild(shared.get());
        root->addChild(placed.get());
    }
    const std::vector<osgVis::oracle::OracleObject> objects = osgVis::oracle::enumerateObjects(*root);
    TriangleIdOracle oracle(objects, 16, 16);
    const osg::ref_ptr<osgVis::ExtractedScene> extracted = osgVis::extractScene(*root);
    ASSERT_EQ(extracted->scene.objects.size(), objects.size());
    ASSERT_EQ(extracted->scene.triangles.size(), oracle.triangleCount());
    for (std::uint32_t i = 0; i < objects.size(); ++i)
    {
        ASSERT_EQ(extracted->find(objects[i].drawable.get(), objects[i].path), i);
        const osgVis::core::SceneObject& object = extracted->scene.objects[i];
        EXPECT_EQ(object.firstTriangle, oracle.firstTriangle(i)) << object.name;
        EXPECT_EQ(object.triangleCount, oracle.firstTriangle(i + 1) - oracle.firstTriangle(i)) << object.name;
    }
}

TEST(TriangleIdOracle, TransparentTrianglesHideNothingNotEvenEachOther)
{
    // A transparent drawable with two triangles covering the same pixels (the far one first), in front
    // of an opaque box: all three faces that cover the middle pixel are seen.
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (float y : {2.0f, 1.0f})
        for (const osg::Vec3& p : {osg::Vec3(-1, y, -1), osg::Vec3(1, y, -1), osg::Vec3(0, y, 1)})
            v->push_back(p);
    osg::ref_ptr<osg::Geometry> panes = new osg::Geometry;
    panes->setVertexArray(v.get());
    panes->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 6));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(inGeode(makeBox({0, 5, 0}, {2, 1, 2}, "behind")));
    osg::ref_ptr<osg::Geode> glass = inGeode(panes.get());
    makeTransparent(*glass);
    root->addChild(glass.get());

    TriangleIdOracle oracle(osgVis::oracle::enumerateObjects(*root), Size, Size);
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, -3, 0), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1));
    // The box's -y face (4, 5) and both panes (12, 13).
    EXPECT_EQ(oracle.visible(view, osgVis::oracle::cubeFaceProjection(0.1, 100.0)), (Indices{4, 5, 12, 13}));
    // Again, from a fresh start: the panes removed in the last call are back.
    EXPECT_EQ(oracle.visible(view, osgVis::oracle::cubeFaceProjection(0.1, 100.0)), (Indices{4, 5, 12, 13}));
}

TEST(TriangleIdOracle, IdsAboveTwentyFourBitsSurviveTheRender)
{
    // No need for 16 M triangles: one triangle drawing a colour whose alpha byte is set, through the
    // triangle pass's state and an offscreen viewer, comes back whole.
    const std::uint32_t index = 0x9abcdef0u;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const osg::Vec3& p : {osg::Vec3(-1, 0, -1), osg::Vec3(1, 0, -1), osg::Vec3(0, 0, 1)})
        v->push_back(p);
    osg::ref_ptr<osg::Vec4ubArray> colours = new osg::Vec4ubArray;
    colours->insert(colours->end(), 3, osgVis::oracle::triangleIdColour(index));
    osg::ref_ptr<osg::Geometry> triangle = new osg::Geometry;
    triangle->setVertexArray(v.get());
    triangle->setColorArray(colours.get(), osg::Array::BIND_PER_VERTEX);
    triangle->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->setStateSet(osgVis::oracle::createIdPassState(osgVis::oracle::IdSource::VertexColour).root.get());
    root->addChild(triangle.get());

    osgVis::oracle::IdViewer viewer(32, 32, root.get());
    viewer.drawFrame(osg::Matrixd::lookAt(osg::Vec3d(0, -3, 0), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1)),
                     osgVis::oracle::cubeFaceProjection(0.1, 10.0));
    const unsigned char* centre = viewer.image().data(16, 16);
    EXPECT_EQ(osgVis::oracle::triangleIdPlusOneOfPixel(centre), index + 1);
    EXPECT_EQ(osgVis::oracle::triangleIdPlusOneOfPixel(viewer.image().data(0, 31)), 0u); // background
}
