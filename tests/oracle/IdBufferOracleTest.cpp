// SPDX-License-Identifier: MIT
// Exact visible sets of the ID-buffer oracle on small scenes built here, each checked against the
// CPU ray caster too where the ray caster models the case (it ignores transparency passes' order and
// polygon modes, but honours cull face).

#include "OracleTestScenes.h"

#include <osgVis/oracle/Oracle.h>

#include <osg/CullFace>
#include <osg/MatrixTransform>
#include <osg/Switch>

#include <gtest/gtest.h>

using namespace oracletest;
using osgVis::oracle::IdBufferOracle;
using osgVis::oracle::OracleSettings;
using Names = std::vector<std::string>;

namespace
{
constexpr unsigned Size = 256;

OracleSettings smallSettings(unsigned supersample = 2)
{
    OracleSettings settings;
    settings.width = Size;
    settings.height = Size;
    settings.supersample = supersample;
    return settings;
}

Names idBufferNames(IdBufferOracle& oracle, const Camera& camera)
{
    return namesOf(drawablesOf(oracle), oracle.visible(camera.view, camera.projection).visible);
}

Names rayCastNames(IdBufferOracle& oracle, osg::Node* root, const Camera& camera)
{
    return namesOf(drawablesOf(oracle), osgVis::oracle::rayCastVisible(root, oracle.objects(), camera.view,
                                                                       camera.projection, Size, Size));
}

osg::ref_ptr<osg::Group> group(std::initializer_list<osg::Node*> children)
{
    osg::ref_ptr<osg::Group> g = new osg::Group;
    for (osg::Node* child : children)
        g->addChild(child);
    return g;
}
} // namespace

//        eye (0,0,20) looking down -z
//   C  (front)    z = 5
//  ===== wall ===== z = 0, x,y in [-5, 5]
//   A  (hidden)   B (beside)  z = -5
TEST(IdBufferOracle, BoxesBehindWall)
{
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeBox({0, 0, 0}, {5, 5, 0.1f}, "wall")),
        inGeode(makeBox({0, 0, -5}, {1, 1, 1}, "A")),
        inGeode(makeBox({8, 0, -5}, {1, 1, 1}, "B")),
        inGeode(makeBox({0, 0, 5}, {1, 1, 1}, "C")),
    });
    IdBufferOracle oracle(root.get(), smallSettings());
    const Camera camera = lookDownZ(20, 40, 1, 100);
    EXPECT_EQ(idBufferNames(oracle, camera), (Names{"B", "C", "wall"}));
    EXPECT_EQ(rayCastNames(oracle, root.get(), camera), (Names{"B", "C", "wall"}));
    // Calls are independent: the same view again gives the same answer.
    EXPECT_EQ(idBufferNames(oracle, camera), (Names{"B", "C", "wall"}));
}

//  left wall | slit | right wall   z = 0; the box behind at z = -5 shows only through the slit.
//  The slit is about 1.4 display pixels wide at 256×256 (the view is 14.6 units across at depth 20).
TEST(IdBufferOracle, BoxSeenOnlyThroughThinSlit)
{
    const float halfSlit = 0.04f;
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeBox({-5 - halfSlit, 0, 0}, {5, 10, 0.1f}, "left")),
        inGeode(makeBox({5 + halfSlit, 0, 0}, {5, 10, 0.1f}, "right")),
        inGeode(makeBox({0, 0, -5}, {1, 1, 1}, "box")),
    });
    IdBufferOracle oracle(root.get(), smallSettings());
    const Camera camera = lookDownZ(20, 40, 1, 100);
    EXPECT_EQ(idBufferNames(oracle, camera), (Names{"box", "left", "right"}));
    EXPECT_EQ(rayCastNames(oracle, root.get(), camera), (Names{"box", "left", "right"}));

    // Closing the slit hides the box.
    osg::ref_ptr<osg::Group> closed = group({
        inGeode(makeBox({-5 + halfSlit, 0, 0}, {5, 10, 0.1f}, "left")),
        inGeode(makeBox({5 - halfSlit, 0, 0}, {5, 10, 0.1f}, "right")),
        inGeode(makeBox({0, 0, -5}, {1, 1, 1}, "box")),
    });
    IdBufferOracle closedOracle(closed.get(), smallSettings());
    EXPECT_EQ(idBufferNames(closedOracle, camera), (Names{"left", "right"}));
}

// A slit a third of a display pixel wide between pixel centres: only the supersampled render can see
// the box, and the oracle reports that it did.
TEST(IdBufferOracle, SubPixelSlitFoundBySupersampling)
{
    const Camera camera = lookDownZ(20, 40, 1, 100);
    // Pixel column 128 spans NDC x in [0, 2/256]; its centre is 1/256. Put the slit around x of NDC 0.5/256:
    // between the display sample at NDC 1/256 and the one at -1/256, and across the 2× sample at 0.5/256.
    const double depth = 20.0;
    const double slitCentre = worldAtNdc(camera, 0.5 / 256.0, 0, depth).x();
    const double halfSlit = (worldAtNdc(camera, 1.0 / 256.0, 0, depth).x() - slitCentre) / 3.0;
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeBox({float(slitCentre - halfSlit - 5), 0, 0}, {5, 10, 0.1f}, "left")),
        inGeode(makeBox({float(slitCentre + halfSlit + 5), 0, 0}, {5, 10, 0.1f}, "right")),
        inGeode(makeBox({0, 0, -5}, {1, 1, 1}, "box")),
    });
    IdBufferOracle oracle(root.get(), smallSettings());
    const IdBufferOracle::Result result = oracle.visible(camera.view, camera.projection);
    EXPECT_EQ(namesOf(drawablesOf(oracle), result.visible), (Names{"box", "left", "right"}));
    EXPECT_EQ(result.onlyInSupersampled, 1u);

    IdBufferOracle displayOnly(root.get(), smallSettings(1));
    EXPECT_EQ(idBufferNames(displayOnly, camera), (Names{"left", "right"}));
}

// Boxes straddling each frame edge are visible; the same boxes just outside are not. Checked for a
// symmetric perspective, an off-centre perspective and an orthographic projection.
TEST(IdBufferOracle, FrameEdgesForSeveralProjections)
{
    Camera perspective = lookDownZ(0, 40, 1, 100);
    Camera offCentre = perspective;
    offCentre.projection = osg::Matrixd::frustum(-0.1, 0.6, -0.5, 0.05, 1, 100);
    Camera ortho = perspective;
    ortho.projection = osg::Matrixd::ortho(-3, 9, -7, 2, 1, 100);

    for (const Camera& camera : {perspective, offCentre, ortho})
    {
        const double depth = 30.0;
        const double half = 0.3; // box half size, world units (a few pixels here)
        // NDC offset of a world distance at this depth, along x and y.
        const double ndcPerUnitX = 1.0 / (worldAtNdc(camera, 1, 0, depth) - worldAtNdc(camera, 0, 0, depth)).x();
        const double ndcPerUnitY = 1.0 / (worldAtNdc(camera, 0, 1, depth) - worldAtNdc(camera, 0, 0, depth)).y();
        osg::ref_ptr<osg::Group> root = new osg::Group;
        const struct
        {
            double x, y;
            const char* edge;
        } edges[] = {{1, 0, "right"}, {-1, 0, "left"}, {0, 1, "top"}, {0, -1, "bottom"}};
        for (const auto& e : edges)
        {
            // Straddling: centre half a box inside the edge minus a pixel, so at least a column shows.
            const double inside = 1.0 - (half * 0.5) * (e.x != 0 ? ndcPerUnitX : ndcPerUnitY);
            const double outside = 1.0 + (half * 1.5) * (e.x != 0 ? ndcPerUnitX : ndcPerUnitY);
            const osg::Vec3d in = worldAtNdc(camera, e.x * inside, e.y * inside, depth);
            const osg::Vec3d out = worldAtNdc(camera, e.x * outside, e.y * outside, depth);
            root->addChild(inGeode(makeBox(in, osg::Vec3(half, half, half), std::string(e.edge) + "-in")));
            root->addChild(inGeode(makeBox(out, osg::Vec3(half, half, half), std::string(e.edge) + "-out")));
        }
        IdBufferOracle oracle(root.get(), smallSettings());
        const Names expected{"bottom-in", "left-in", "right-in", "top-in"};
        EXPECT_EQ(idBufferNames(oracle, camera), expected);
        EXPECT_EQ(rayCastNames(oracle, root.get(), camera), expected);
    }
}

// An orthographic view straight through a row: the box behind an equal box is hidden, whatever its distance.
TEST(IdBufferOracle, OrthographicOcclusion)
{
    Camera camera = lookDownZ(50, 40, 1, 100);
    camera.projection = osg::Matrixd::ortho(-10, 10, -10, 10, 1, 100);
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeBox({2, 2, 0}, {1, 1, 1}, "front")),
        inGeode(makeBox({2, 2, -30}, {0.9f, 0.9f, 0.9f}, "behind")),
        inGeode(makeBox({-5, -5, -30}, {0.5f, 0.5f, 0.5f}, "apart")),
    });
    IdBufferOracle oracle(root.get(), smallSettings());
    EXPECT_EQ(idBufferNames(oracle, camera), (Names{"apart", "front"}));
    EXPECT_EQ(rayCastNames(oracle, root.get(), camera), (Names{"apart", "front"}));
}

// One Geode, eight drawables: d0..d6 in a row, d7 straight behind d3. Eight objects; d7 hidden.
TEST(IdBufferOracle, GeodeWithEightDrawablesOneHidden)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (int i = 0; i < 7; ++i)
        geode->addDrawable(makeBox({float(i * 2 - 6), 0, 0}, {0.8f, 0.8f, 0.8f}, "d" + std::to_string(i)));
    geode->addDrawable(makeBox({0, 0, -4}, {0.5f, 0.5f, 0.5f}, "d7"));
    osg::ref_ptr<osg::Group> root = group({geode.get()});
    IdBufferOracle oracle(root.get(), smallSettings());
    ASSERT_EQ(oracle.objects().size(), 8u);
    const Camera camera = lookDownZ(20, 40, 1, 100);
    EXPECT_EQ(idBufferNames(oracle, camera), (Names{"d0", "d1", "d2", "d3", "d4", "d5", "d6"}));
    EXPECT_EQ(rayCastNames(oracle, root.get(), camera), (Names{"d0", "d1", "d2", "d3", "d4", "d5", "d6"}));
}

// Transparent panes hide nothing: the box behind three stacked panes is visible, and so is every pane;
// a pane behind an opaque wall is not. The view is orthographic and the panes congruent, so every
// pixel of one pane is a pixel of all three: each pass of transparent IDs can find only one of them.
TEST(IdBufferOracle, TransparentPanesHideNothing)
{
    Camera camera = lookDownZ(20, 40, 1, 100);
    camera.projection = osg::Matrixd::ortho(-10, 10, -10, 10, 1, 100);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    for (int i = 0; i < 3; ++i)
    {
        osg::ref_ptr<osg::Geode> pane = inGeode(makeQuadZ(-3, 3, -3, 3, 4.0f - i, true, "pane" + std::to_string(i)));
        makeTransparent(*pane);
        root->addChild(pane.get());
    }
    root->addChild(inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "box")));
    root->addChild(inGeode(makeBox({7, 0, -3}, {2, 2, 0.1f}, "wall")));
    osg::ref_ptr<osg::Geode> hiddenPane = inGeode(makeQuadZ(6, 8, -1, 1, -6, true, "pane-hidden"));
    makeTransparent(*hiddenPane);
    root->addChild(hiddenPane.get());

    IdBufferOracle oracle(root.get(), smallSettings());
    for (const auto& object : oracle.objects())
        EXPECT_EQ(object.transparent, object.drawable->getName().rfind("pane", 0) == 0) << object.drawable->getName();
    const Names expected{"box", "pane0", "pane1", "pane2", "wall"};
    EXPECT_EQ(idBufferNames(oracle, camera), expected);
    EXPECT_EQ(rayCastNames(oracle, root.get(), camera), expected);
}

// The object's own state applies: a single-sided wall with back-face culling hides the box behind
// it only when it faces the eye.
TEST(IdBufferOracle, BackFaceCulledWallShowsTheBoxBehind)
{
    for (bool facesEye : {true, false})
    {
        osg::ref_ptr<osg::Geode> wall = inGeode(makeQuadZ(-5, 5, -5, 5, 0, facesEye, "wall"));
        wall->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));
        osg::ref_ptr<osg::Group> root = group({wall.get(), inGeode(makeBox({0, 0, -5}, {1, 1, 1}, "box"))});
        IdBufferOracle oracle(root.get(), smallSettings());
        const Camera camera = lookDownZ(20, 40, 1, 100);
        const Names expected = facesEye ? Names{"wall"} : Names{"box"};
        EXPECT_EQ(idBufferNames(oracle, camera), expected) << "wall faces eye: " << facesEye;
        EXPECT_EQ(rayCastNames(oracle, root.get(), camera), expected) << "wall faces eye: " << facesEye;
    }
}

// The projection is used as given: nothing beyond its far plane is drawn (no near/far recomputation),
// and an object a third of a pixel wide over a pixel centre is not dropped (no small-feature culling).
TEST(IdBufferOracle, UsesProjectionAsGivenWithoutSmallFeatureCulling)
{
    const Camera camera = lookDownZ(0, 40, 1, 50);
    // One display pixel at depth 40 is 2·40·tan(20°)/256 ≈ 0.114 units.
    const osg::Vec3d pixelCentre = worldAtNdc(camera, 1.0 / 256.0, 1.0 / 256.0, 40.0);
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeBox(pixelCentre, {0.02f, 0.02f, 0.02f}, "tiny")),
        inGeode(makeBox({3, 0, -49.5f}, {0.4f, 0.4f, 0.4f}, "at-far")),
        inGeode(makeBox({-3, 0, -51}, {0.4f, 0.4f, 0.4f}, "beyond-far")),
        inGeode(makeBox({0, 3, -0.5f}, {0.2f, 0.2f, 0.2f}, "before-near")),
    });
    IdBufferOracle oracle(root.get(), smallSettings(1)); // note: the display render alone must see it
    EXPECT_EQ(idBufferNames(oracle, camera), (Names{"at-far", "tiny"}));
    EXPECT_EQ(rayCastNames(oracle, root.get(), camera), (Names{"at-far", "tiny"}));
}

// The oracle redraws the objects outside their graph, with their path's state and world matrix.
TEST(IdBufferOracle, ObjectsKeepTheirTransformsAndInstances)
{
    osg::ref_ptr<osg::Geometry> shared = makeBox({0, 0, 0}, {1, 1, 1}, "shared");
    osg::ref_ptr<osg::MatrixTransform> left = new osg::MatrixTransform(osg::Matrixd::translate(-4, 0, 0));
    osg::ref_ptr<osg::MatrixTransform> right = new osg::MatrixTransform(osg::Matrixd::translate(4, 0, 0));
    osg::ref_ptr<osg::Geode> geode = inGeode(shared.get());
    left->addChild(geode.get());
    right->addChild(geode.get());
    // A wall in front of the right instance only.
    osg::ref_ptr<osg::Group> root = group({left.get(), right.get(), inGeode(makeBox({4, 0, 3}, {2, 2, 0.1f}, "wall"))});
    IdBufferOracle oracle(root.get(), smallSettings());
    ASSERT_EQ(oracle.objects().size(), 3u);
    const IdBufferOracle::Result result = oracle.visible(lookDownZ(20, 40, 1, 100).view,
                                                         lookDownZ(20, 40, 1, 100).projection);
    // objects: 0 = shared under left, 1 = shared under right, 2 = wall
    EXPECT_EQ(result.visible, (std::vector<std::uint32_t>{0, 2}));
}
