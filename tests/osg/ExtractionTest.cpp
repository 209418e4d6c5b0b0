// SPDX-License-Identifier: MIT
// Scene extraction: exact objects, bounds, flags and marker data from small hand-built graphs.
#include "TestScenes.h"

#include <osgVis/Cell>
#include <osgVis/CullVisitor>
#include <osgVis/Occluder>
#include <osgVis/Portal>
#include <osgVis/SceneExtractor>
#include <osgVis/VisibilityGroup>

#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/BlendFunc>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/FrontFace>
#include <osg/Geode>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/PolygonMode>
#include <osg/Program>
#include <osg/Switch>

#include <gtest/gtest.h>

#include <limits>

using osgVis::test::makeBox;

namespace
{
void expectBounds(const osgVis::core::Aabb& box, const osg::Vec3d& min, const osg::Vec3d& max)
{
    EXPECT_DOUBLE_EQ(box.min.x, min.x());
    EXPECT_DOUBLE_EQ(box.min.y, min.y());
    EXPECT_DOUBLE_EQ(box.min.z, min.z());
    EXPECT_DOUBLE_EQ(box.max.x, max.x());
    EXPECT_DOUBLE_EQ(box.max.y, max.y());
    EXPECT_DOUBLE_EQ(box.max.z, max.z());
}
} // namespace

TEST(Extraction, GeodeDrawablesAreObjectsWithExactBounds)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (int i = 0; i < 4; ++i)
        geode->addDrawable(makeBox(osg::Vec3(i * 3.f, 0, 0), osg::Vec3(i * 3.f + 1, 2, 3)));

    const auto extracted = osgVis::extractScene(*geode);
    const osgVis::core::Scene& scene = extracted->scene;
    ASSERT_EQ(scene.objects.size(), 4u);
    ASSERT_EQ(extracted->refs.size(), 4u);
    EXPECT_EQ(scene.triangles.size(), 48u);
    for (unsigned i = 0; i < 4; ++i)
    {
        const osgVis::core::SceneObject& object = scene.objects[i];
        EXPECT_EQ(object.id, i);
        EXPECT_EQ(object.triangleCount, 12u);
        EXPECT_EQ(object.firstTriangle, 12u * i);
        EXPECT_EQ(object.flags, osgVis::core::OBJECT_NONE);
        expectBounds(object.bounds, osg::Vec3d(i * 3.0, 0, 0), osg::Vec3d(i * 3.0 + 1, 2, 3));
        EXPECT_EQ(extracted->refs[i].drawable.get(), geode->getDrawable(i));
        EXPECT_EQ(extracted->refs[i].path, (osg::NodePath{geode.get(), geode->getDrawable(i)}));
        EXPECT_EQ(extracted->find(geode->getDrawable(i), extracted->refs[i].path), i);
    }
}

TEST(Extraction, SliverTrianglesAreFlagged)
{
    // A face drawn as a fan over its corner list: the plugin's fans of Quake 3 faces keep straight-line
    // corners, so some fan triangles have three distinct but collinear corners (OpenArena oa_dm1).
    auto fan = [](const std::vector<osg::Vec3>& corners)
    {
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setVertexArray(new osg::Vec3Array(corners.begin(), corners.end()));
        geometry->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_FAN, 0, GLsizei(corners.size())));
        return geometry;
    };
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(fan({{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}}));                // a quad
    geode->addDrawable(fan({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}}));     // (0, 1, 2) collinear
    geode->addDrawable(fan({{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {2, 0, 1}, {0, 0, 1}}));     // a repeated corner only
    geode->addDrawable(fan({{0, 0, 0}, {1, 0, 1e-4f}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}})); // thin on purpose
    // Meant to be collinear, a thousand units out: float storage leaves them 1e-4 off the line.
    geode->addDrawable(fan({{1000, 0, 0}, {1001, 0, 1e-4f}, {1002, 0, 0}, {1002, 0, 1}, {1000, 0, 1}}));
    const auto extracted = osgVis::extractScene(*geode);
    ASSERT_EQ(extracted->scene.objects.size(), 5u);
    EXPECT_FALSE(extracted->scene.objects[0].flags & osgVis::core::OBJECT_SLIVERS);
    EXPECT_TRUE(extracted->scene.objects[1].flags & osgVis::core::OBJECT_SLIVERS);
    EXPECT_FALSE(extracted->scene.objects[2].flags & osgVis::core::OBJECT_SLIVERS);
    EXPECT_FALSE(extracted->scene.objects[3].flags & osgVis::core::OBJECT_SLIVERS);
    EXPECT_TRUE(extracted->scene.objects[4].flags & osgVis::core::OBJECT_SLIVERS);
}

TEST(Extraction, TrianglesCanBeLeftOut)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    osgVis::ExtractionOptions options;
    options.keepTriangles = false;
    const auto extracted = osgVis::extractScene(*geode, options);
    ASSERT_EQ(extracted->scene.objects.size(), 1u);
    EXPECT_TRUE(extracted->scene.triangles.empty());
    EXPECT_EQ(extracted->scene.objects[0].triangleCount, 12u);
}

TEST(Extraction, TransformsMoveBounds)
{
    osg::ref_ptr<osg::MatrixTransform> outer = new osg::MatrixTransform(osg::Matrix::translate(10, 0, 0));
    osg::ref_ptr<osg::MatrixTransform> inner = new osg::MatrixTransform(osg::Matrix::scale(2, 3, 4));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    outer->addChild(inner);
    inner->addChild(geode);

    const auto extracted = osgVis::extractScene(*outer);
    ASSERT_EQ(extracted->scene.objects.size(), 1u);
    // Row vectors: the scale (inner) applies first, then the translation (outer).
    expectBounds(extracted->scene.objects[0].bounds, osg::Vec3d(10, 0, 0), osg::Vec3d(12, 3, 4));
    const osgVis::core::Triangle& t = extracted->scene.triangles.front();
    for (const auto& v : {t.a, t.b, t.c})
        EXPECT_GE(v.x, 10.f);
}

TEST(Extraction, AbsoluteTransformRestartsTheMatrixAndIsNeverCulled)
{
    osg::ref_ptr<osg::MatrixTransform> outer = new osg::MatrixTransform(osg::Matrix::translate(100, 0, 0));
    osg::ref_ptr<osg::MatrixTransform> absolute = new osg::MatrixTransform(osg::Matrix::translate(0, 5, 0));
    absolute->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    outer->addChild(absolute);
    absolute->addChild(geode);

    const auto extracted = osgVis::extractScene(*outer);
    ASSERT_EQ(extracted->scene.objects.size(), 1u);
    expectBounds(extracted->scene.objects[0].bounds, osg::Vec3d(0, 5, 0), osg::Vec3d(1, 6, 1));
    EXPECT_TRUE(extracted->scene.objects[0].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE);
}

TEST(Extraction, SharedDrawableIsOneObjectPerPath)
{
    osg::ref_ptr<osg::Geode> shared = new osg::Geode;
    osg::ref_ptr<osg::Geometry> box = makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1));
    shared->addDrawable(box);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::MatrixTransform> left = new osg::MatrixTransform(osg::Matrix::translate(-5, 0, 0));
    osg::ref_ptr<osg::MatrixTransform> right = new osg::MatrixTransform(osg::Matrix::translate(5, 0, 0));
    left->addChild(shared);
    right->addChild(shared);
    root->addChild(left);
    root->addChild(right);

    const auto extracted = osgVis::extractScene(*root);
    ASSERT_EQ(extracted->scene.objects.size(), 2u);
    expectBounds(extracted->scene.objects[0].bounds, osg::Vec3d(-5, 0, 0), osg::Vec3d(-4, 1, 1));
    expectBounds(extracted->scene.objects[1].bounds, osg::Vec3d(5, 0, 0), osg::Vec3d(6, 1, 1));
    EXPECT_EQ(extracted->idsOf(box.get()), (std::vector<osgVis::core::ObjectId>{0, 1}));

    const osg::NodePath viaLeft{root.get(), left.get(), shared.get(), box.get()};
    const osg::NodePath viaRight{root.get(), right.get(), shared.get(), box.get()};
    EXPECT_EQ(extracted->find(box.get(), viaLeft), 0u);
    EXPECT_EQ(extracted->find(box.get(), viaRight), 1u);
    EXPECT_EQ(extracted->find(box.get(), osg::NodePath{root.get(), shared.get(), box.get()}),
              osgVis::core::InvalidObject);

    // A cull visitor's path starts above the extraction root.
    osg::ref_ptr<osg::Group> above = new osg::Group;
    osg::NodePath fromAbove{above.get()};
    fromAbove.insert(fromAbove.end(), viaRight.begin(), viaRight.end());
    EXPECT_EQ(extracted->find(box.get(), fromAbove, 1), 1u);
    EXPECT_EQ(extracted->find(box.get(), fromAbove, 0), osgVis::core::InvalidObject);

    osg::ref_ptr<osg::Geometry> stranger = makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1));
    EXPECT_TRUE(extracted->idsOf(stranger.get()).empty());
}

TEST(Extraction, NonFiniteVertexIsAlwaysVisibleNeverACrash)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> bad = makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1));
    auto* vertices = static_cast<osg::Vec3Array*>(bad->getVertexArray());
    (*vertices)[7] = osg::Vec3(std::numeric_limits<float>::quiet_NaN(), 0, 0);
    (*vertices)[6] = osg::Vec3(0, std::numeric_limits<float>::infinity(), 0);
    geode->addDrawable(bad);
    geode->addDrawable(makeBox(osg::Vec3(2, 0, 0), osg::Vec3(3, 1, 1)));

    const auto extracted = osgVis::extractScene(*geode);
    ASSERT_EQ(extracted->scene.objects.size(), 2u);
    EXPECT_TRUE(extracted->scene.objects[0].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE);
    EXPECT_FALSE(extracted->scene.objects[1].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE);
    for (const osgVis::core::Triangle& t : extracted->scene.triangles)
        for (const auto& v : {t.a, t.b, t.c})
            EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

// Two faces sharing one vertex array of a whole "level" (as OSG's bsp plugin builds Quake 3 maps):
// each object's bounds are those of the vertices its primitives draw, not of the array.
//
//   y  3 +-------+               vertex array: 0..3 the left quad, 4..7 the right one,
//        | left  |    +-------+  8 a far-away vertex no primitive uses
//      0 +-------+    | right |
//        0       2    5       8 x
TEST(Extraction, SharedVertexArrayBoundsFollowTheDrawnVertices)
{
    osg::ref_ptr<osg::Vec3Array> level = new osg::Vec3Array;
    for (const osg::Vec3& v : {osg::Vec3(0, 0, 0), osg::Vec3(2, 0, 0), osg::Vec3(2, 3, 0), osg::Vec3(0, 3, 0),
                               osg::Vec3(5, -1, 1), osg::Vec3(8, -1, 1), osg::Vec3(8, 2, 1), osg::Vec3(5, 2, 1),
                               osg::Vec3(1000, 1000, 1000)})
        level->push_back(v);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> left = new osg::Geometry, right = new osg::Geometry, none = new osg::Geometry;
    for (osg::Geometry* g : {left.get(), right.get(), none.get()})
    {
        g->setVertexArray(level.get());
        geode->addDrawable(g);
    }
    const GLushort leftIndices[] = {0, 1, 2, 0, 2, 3};
    left->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 6, leftIndices));
    right->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 4, 4));
    // no primitive set: draws nothing; its bounds fall back to the whole array (never too small)

    const auto extracted = osgVis::extractScene(*geode);
    ASSERT_EQ(extracted->scene.objects.size(), 3u);
    expectBounds(extracted->scene.objects[0].bounds, osg::Vec3d(0, 0, 0), osg::Vec3d(2, 3, 0));
    expectBounds(extracted->scene.objects[1].bounds, osg::Vec3d(5, -1, 1), osg::Vec3d(8, 2, 1));
    expectBounds(extracted->scene.objects[2].bounds, osg::Vec3d(0, -1, 0), osg::Vec3d(1000, 1000, 1000));
    EXPECT_EQ(extracted->scene.objects[0].triangleCount, 2u);
    EXPECT_EQ(extracted->scene.objects[1].triangleCount, 2u);
    EXPECT_EQ(extracted->scene.objects[2].triangleCount, 0u);
}

TEST(Extraction, BlendingMarksTransparent)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> blended = new osg::Geode;
    blended->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::ON);
    blended->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    osg::ref_ptr<osg::Geode> binned = new osg::Geode;
    osg::ref_ptr<osg::Geometry> box = makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1));
    box->getOrCreateStateSet()->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    binned->addDrawable(box);
    osg::ref_ptr<osg::Geode> opaque = new osg::Geode;
    opaque->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    root->addChild(blended);
    root->addChild(binned);
    root->addChild(opaque);

    const auto extracted = osgVis::extractScene(*root);
    ASSERT_EQ(extracted->scene.objects.size(), 3u);
    EXPECT_TRUE(extracted->scene.objects[0].flags & osgVis::core::OBJECT_TRANSPARENT);
    EXPECT_TRUE(extracted->scene.objects[1].flags & osgVis::core::OBJECT_TRANSPARENT);
    EXPECT_FALSE(extracted->scene.objects[2].flags & osgVis::core::OBJECT_TRANSPARENT);
}

TEST(Extraction, DisabledNodesAreSkippedAndOpenTheirChild)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Group> child = new osg::Group;
    osg::ref_ptr<osg::Geode> visible = new osg::Geode;
    visible->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    osg::ref_ptr<osg::Geode> hidden = new osg::Geode;
    hidden->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    hidden->setNodeMask(0);
    child->addChild(visible);
    child->addChild(hidden);
    osg::ref_ptr<osg::Geode> plain = new osg::Geode;
    plain->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    plain->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    root->addChild(child);
    root->addChild(plain);

    const auto extracted = osgVis::extractScene(*root);
    ASSERT_EQ(extracted->scene.objects.size(), 3u);
    ASSERT_EQ(extracted->childRanges.size(), 2u);
    EXPECT_EQ(extracted->childRanges[0].first, 0u);
    EXPECT_EQ(extracted->childRanges[0].end, 1u);
    EXPECT_FALSE(extracted->childRanges[0].closed); // the hidden geode may be switched on later
    EXPECT_EQ(extracted->childRanges[1].first, 1u);
    EXPECT_EQ(extracted->childRanges[1].end, 3u);
    EXPECT_TRUE(extracted->childRanges[1].closed);
}

TEST(Extraction, MarkersFillOccludersCellsAndPortals)
{
    osg::ref_ptr<osg::MatrixTransform> root = new osg::MatrixTransform(osg::Matrix::translate(0, 0, 10));

    osg::ref_ptr<osgVis::Occluder> occluder = new osgVis::Occluder;
    occluder->addPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    osg::ref_ptr<osg::Geode> wall = new osg::Geode;
    wall->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(4, 0.1f, 3)));
    occluder->addChild(wall);

    osg::ref_ptr<osgVis::Cell> cellA = new osgVis::Cell;
    cellA->setName("A");
    cellA->setBounds(osg::BoundingBoxd(0, 0, 0, 5, 5, 3));
    osg::ref_ptr<osgVis::Cell> cellB = new osgVis::Cell;
    cellB->setName("B");
    cellB->setBounds(osg::BoundingBoxd(5, 0, 0, 10, 5, 3));
    // The portal names cell B before the traversal reaches it.
    osg::ref_ptr<osgVis::Portal> portal = new osgVis::Portal;
    portal->setPolygon({{5, 1, 0}, {5, 2, 0}, {5, 2, 2}, {5, 1, 2}});
    portal->setCells("A", "B");
    osg::ref_ptr<osgVis::Portal> dangling = new osgVis::Portal;
    dangling->setPolygon({{5, 1, 0}, {5, 2, 0}, {5, 2, 2}});
    dangling->setCells("A", "nowhere");

    osg::ref_ptr<osg::Geode> loose = new osg::Geode;
    loose->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    root->addChild(occluder);
    root->addChild(cellA);
    root->addChild(portal);
    root->addChild(dangling);
    root->addChild(cellB);
    cellB->addChild(loose);

    const auto extracted = osgVis::extractScene(*root);
    const osgVis::core::Scene& scene = extracted->scene;
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_TRUE(scene.objects[0].flags & osgVis::core::OBJECT_OCCLUDER);
    EXPECT_FALSE(scene.objects[1].flags & osgVis::core::OBJECT_OCCLUDER);
    expectBounds(scene.objects[1].bounds, osg::Vec3d(0, 0, 10), osg::Vec3d(1, 1, 11));

    ASSERT_EQ(scene.occluders.size(), 1u);
    EXPECT_EQ(scene.occluders[0].owner, osgVis::core::InvalidObject);
    ASSERT_EQ(scene.occluders[0].polygon.size(), 4u);
    EXPECT_DOUBLE_EQ(scene.occluders[0].polygon.vertices()[2].x, 1.0);
    EXPECT_DOUBLE_EQ(scene.occluders[0].polygon.vertices()[2].z, 10.0);

    ASSERT_EQ(scene.cells.size(), 2u);
    EXPECT_EQ(scene.cells[0].name, "A");
    EXPECT_EQ(scene.cells[1].name, "B");
    EXPECT_EQ(scene.cells[1].id, 1u);
    expectBounds(scene.cells[1].bounds, osg::Vec3d(5, 0, 10), osg::Vec3d(10, 5, 13));

    ASSERT_EQ(scene.portals.size(), 1u); // the dangling one is dropped with a warning
    EXPECT_EQ(scene.portals[0].cellA, 0u);
    EXPECT_EQ(scene.portals[0].cellB, 1u);
    ASSERT_EQ(scene.portals[0].polygon.size(), 4u);
    EXPECT_DOUBLE_EQ(scene.portals[0].polygon.vertices()[2].z, 12.0);
}

TEST(Extraction, MarkerNodesCopyTheirData)
{
    osg::ref_ptr<osgVis::Portal> portal = new osgVis::Portal;
    portal->setPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    portal->setCells("A", "B");
    osg::ref_ptr<osgVis::Portal> copy = static_cast<osgVis::Portal*>(portal->clone(osg::CopyOp::DEEP_COPY_ALL));
    EXPECT_EQ(copy->getPolygon().size(), 3u);
    EXPECT_EQ(copy->getCellB(), "B");
    EXPECT_STREQ(copy->libraryName(), "osgVis");
    EXPECT_STREQ(copy->className(), "Portal");
}

TEST(Modes, UnknownModeThrowsNamingTheKnownModes)
{
    try
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum,nosuchmode");
        FAIL() << "no exception";
    }
    catch (const osgVis::core::UnknownModeError& e)
    {
        EXPECT_NE(std::string(e.what()).find("frustum"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("nosuchmode"), std::string::npos) << e.what();
    }
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup;
    EXPECT_EQ(group->getModes(), "frustum");
    EXPECT_THROW(group->setModes("bogus"), osgVis::core::UnknownModeError);
    EXPECT_EQ(group->getModes(), "frustum");
    EXPECT_THROW(osg::ref_ptr<osgVis::CullVisitor>(new osgVis::CullVisitor("bogus")), osgVis::core::UnknownModeError);
}

namespace
{
// Extracts `root` and returns the flags of its objects in depth-first order.
std::vector<std::uint32_t> objectFlags(osg::Node& root)
{
    std::vector<std::uint32_t> flags;
    // note: held here; a range-for over the temporary's member would outlive the extraction.
    const osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(root);
    for (const auto& object : scene->scene.objects)
        flags.push_back(object.flags);
    return flags;
}

osg::ref_ptr<osg::Geode> boxGeode()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1)));
    return geode;
}
} // namespace

TEST(Extraction, OnlySolidGeometryDrawnEveryFrameMayOcclude)
{
    using osgVis::core::OBJECT_NO_AUTO_OCCLUDER;
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(boxGeode()); // 0: plain
    osg::ref_ptr<osg::Geode> alpha = boxGeode();
    alpha->getOrCreateStateSet()->setMode(GL_ALPHA_TEST, osg::StateAttribute::ON);
    root->addChild(alpha); // 1
    osg::ref_ptr<osg::Geode> lines = boxGeode();
    lines->getOrCreateStateSet()->setAttribute(
        new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
    root->addChild(lines); // 2
    osg::ref_ptr<osg::Geode> noDepthWrite = boxGeode();
    noDepthWrite->getOrCreateStateSet()->setAttribute(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
    root->addChild(noDepthWrite); // 3
    osg::ref_ptr<osg::Geode> shaded = boxGeode();
    shaded->getOrCreateStateSet()->setAttribute(new osg::Program);
    root->addChild(shaded); // 4
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->addChild(boxGeode(), 0.f, 100.f);
    root->addChild(lod); // 5
    osg::ref_ptr<osg::Switch> toggled = new osg::Switch;
    toggled->addChild(boxGeode());
    root->addChild(toggled); // 6
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrix::translate(5, 0, 0));
    moved->addChild(boxGeode());
    root->addChild(moved); // 7: plain under a transform
    // 8: the parent turns the alpha test on with OVERRIDE; the child's OFF does not win…
    osg::ref_ptr<osg::Group> overriding = new osg::Group;
    overriding->getOrCreateStateSet()->setMode(GL_ALPHA_TEST, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    osg::ref_ptr<osg::Geode> child = boxGeode();
    child->getOrCreateStateSet()->setMode(GL_ALPHA_TEST, osg::StateAttribute::OFF);
    overriding->addChild(child);
    root->addChild(overriding);
    // 9: …unless it is PROTECTED.
    osg::ref_ptr<osg::Group> overridden = new osg::Group;
    overridden->getOrCreateStateSet()->setMode(GL_ALPHA_TEST, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    osg::ref_ptr<osg::Geode> protectedChild = boxGeode();
    protectedChild->getOrCreateStateSet()->setMode(GL_ALPHA_TEST,
                                                   osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    overridden->addChild(protectedChild);
    root->addChild(overridden);

    const std::vector<std::uint32_t> flags = objectFlags(*root);
    ASSERT_EQ(flags.size(), 10u);
    const bool expectedBlocked[] = {false, true, true, true, true, true, true, false, true, false};
    for (std::size_t i = 0; i < flags.size(); ++i)
        EXPECT_EQ((flags[i] & OBJECT_NO_AUTO_OCCLUDER) != 0, expectedBlocked[i]) << "object " << i;
}

TEST(Extraction, FaceCullingMakesOneSidedOccludersStoredFrontCounterClockwise)
{
    using namespace osgVis::core;
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> back = boxGeode();
    back->getOrCreateStateSet()->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
    root->addChild(back); // 0: default CullFace mode is BACK
    osg::ref_ptr<osg::Geode> front = boxGeode();
    front->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT));
    root->addChild(front); // 1
    osg::ref_ptr<osg::Geode> both = boxGeode();
    both->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT_AND_BACK));
    root->addChild(both); // 2
    osg::ref_ptr<osg::Geode> clockwise = boxGeode();
    clockwise->getOrCreateStateSet()->setAttribute(new osg::FrontFace(osg::FrontFace::CLOCKWISE));
    root->addChild(clockwise);  // 3
    root->addChild(boxGeode()); // 4: reference winding

    const auto extracted = osgVis::extractScene(*root);
    const Scene& scene = extracted->scene;
    ASSERT_EQ(scene.objects.size(), 5u);
    const std::uint32_t sides = OBJECT_CULL_BACK | OBJECT_CULL_FRONT;
    EXPECT_EQ(scene.objects[0].flags & sides, std::uint32_t(OBJECT_CULL_BACK));
    EXPECT_EQ(scene.objects[1].flags & sides, std::uint32_t(OBJECT_CULL_FRONT));
    EXPECT_EQ(scene.objects[2].flags & sides, sides);
    EXPECT_EQ(scene.objects[3].flags & sides, 0u);
    // Clockwise-front triangles are stored flipped: each normal opposes the reference one.
    const auto normal = [](const Triangle& t) { return glm::cross(t.b - t.a, t.c - t.a); };
    ASSERT_EQ(scene.objects[3].triangleCount, scene.objects[4].triangleCount);
    for (std::uint32_t i = 0; i < scene.objects[4].triangleCount; ++i)
    {
        const Vec3f flipped = normal(scene.triangles[scene.objects[3].firstTriangle + i]);
        const Vec3f reference = normal(scene.triangles[scene.objects[4].firstTriangle + i]);
        EXPECT_LT(glm::dot(flipped, reference), 0.f) << "triangle " << i;
    }
}
