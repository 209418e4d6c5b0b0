// SPDX-License-Identifier: MIT
// The SceneWatch alone (osgvis/osg/src/SceneWatch, docs/changes.md): a subgraph recorded, edited in
// place the way an application edits it (with the dirty() calls OSG itself needs and no others), then
// compared. Every edit the extraction would read differently must read as a change; nothing changed
// must read as nothing; and an application swapping between state sets that read the same must not
// make the watch grow.
#include "SceneWatch.h"
#include "TestScenes.h"

#include <osgVis/Occluder>

#include <osg/Depth>
#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/PolygonMode>
#include <osg/Program>
#include <osg/Sequence>
#include <osg/StateSet>

#include <gtest/gtest.h>

using osgVis::SceneWatch;
using osgVis::test::makeBox;

namespace
{
// root → transform → geode → box (indexed triangles, with the state set makeBox gives it), and a
// second geode beside the transform holding a strip of two triangles drawn by one DrawArrays.
struct Scene
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform(osg::Matrixd::translate(0, 10, 0));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> box = makeBox(osg::Vec3(-1, -1, -1), osg::Vec3(1, 1, 1));
    osg::ref_ptr<osg::Geometry> strip = new osg::Geometry;
    osg::ref_ptr<osg::DrawArrays> stripRange = new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4);

    Scene()
    {
        osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
        for (int i = 0; i < 6; ++i)
            vertices->push_back(osg::Vec3(float(i / 2), 20, float(i % 2)));
        strip->setVertexArray(vertices);
        strip->addPrimitiveSet(stripRange);
        geode->addDrawable(box);
        transform->addChild(geode);
        root->addChild(transform);
        osg::ref_ptr<osg::Geode> beside = new osg::Geode;
        beside->addDrawable(strip);
        root->addChild(beside);
    }
};

// Records `root` and checks that, untouched, it reads the same (every test's starting point).
void record(SceneWatch& watch, osg::Node& root)
{
    watch.record(root);
    EXPECT_FALSE(watch.changed()) << "nothing edited yet";
}

struct NoDraw : osg::Drawable::DrawCallback
{
};

struct NoBound : osg::Drawable::ComputeBoundingBoxCallback
{
};
} // namespace

TEST(SceneWatch, FindsNothingWhenNothingChanged)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    for (int compare = 0; compare < 3; ++compare)
        EXPECT_FALSE(watch.compare().any()) << "compare " << compare;
    EXPECT_EQ(watch.nodeCount(), 6u);
}

TEST(SceneWatch, FindsNothingBeforeRecording)
{
    SceneWatch watch;
    EXPECT_FALSE(watch.changed());
}

TEST(SceneWatch, FindsAMovedTransformAsMovedOnly)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    scene.transform->setMatrix(osg::Matrixd::translate(0, 11, 0));
    const SceneWatch::Difference& difference = watch.compare();
    EXPECT_FALSE(difference.other);
    ASSERT_EQ(difference.moved.size(), 1u);
    EXPECT_EQ(difference.moved[0], scene.transform.get());
    watch.acceptMatrices(difference);
    EXPECT_FALSE(watch.changed()) << "the new matrix taken";
}

TEST(SceneWatch, FindsAPrimitiveSetsModeChanged)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    osg::PrimitiveSet* triangles = scene.box->getPrimitiveSet(0);
    triangles->setMode(GL_LINES);
    triangles->dirty();
    EXPECT_TRUE(watch.changed());

    // note: OSG reads the mode at each draw, so an application need not call dirty() for it
    triangles->setMode(GL_TRIANGLES);
    record(watch, *scene.root);
    triangles->setMode(GL_LINES);
    EXPECT_TRUE(watch.changed()) << "without dirty()";
}

TEST(SceneWatch, FindsADrawArraysRangeEdited)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    scene.stripRange->setFirst(2);
    scene.stripRange->dirty();
    EXPECT_TRUE(watch.changed()) << "first";

    record(watch, *scene.root);
    scene.stripRange->setCount(3);
    scene.stripRange->dirty();
    EXPECT_TRUE(watch.changed()) << "count";

    // note: OSG reads first and count at each draw, so an application need not call dirty() for them
    record(watch, *scene.root);
    scene.stripRange->setCount(4);
    EXPECT_TRUE(watch.changed()) << "count, without dirty()";
}

TEST(SceneWatch, FindsADrawCallbackSet)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    scene.box->setDrawCallback(new NoDraw);
    EXPECT_TRUE(watch.changed());
}

TEST(SceneWatch, FindsAComputeBoundCallbackSet)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    scene.box->setComputeBoundingBoxCallback(new NoBound);
    EXPECT_TRUE(watch.changed());
}

// A state attribute edited in place: the state set and the attribute stay the same objects.
TEST(SceneWatch, FindsAPolygonModeEditedInPlace)
{
    Scene scene;
    osg::ref_ptr<osg::PolygonMode> polygonMode =
        new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::FILL);
    scene.box->getOrCreateStateSet()->setAttribute(polygonMode);
    SceneWatch watch;
    record(watch, *scene.root);
    polygonMode->setMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE);
    EXPECT_TRUE(watch.changed());
}

TEST(SceneWatch, FindsADepthWriteMaskEditedInPlace)
{
    Scene scene;
    osg::ref_ptr<osg::Depth> depth = new osg::Depth;
    scene.transform->getOrCreateStateSet()->setAttribute(depth);
    SceneWatch watch;
    record(watch, *scene.root);
    depth->setWriteMask(false);
    EXPECT_TRUE(watch.changed());
}

TEST(SceneWatch, FindsAProgramAddedToAStateSet)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    scene.box->getStateSet()->setAttributeAndModes(new osg::Program);
    EXPECT_TRUE(watch.changed());
}

TEST(SceneWatch, FindsAStateSetAddedOnAParent)
{
    Scene scene;
    ASSERT_EQ(scene.transform->getStateSet(), nullptr);
    SceneWatch watch;
    record(watch, *scene.root);
    scene.transform->getOrCreateStateSet()->setMode(GL_BLEND, osg::StateAttribute::ON);
    EXPECT_TRUE(watch.changed()) << "blending on";

    scene.transform->setStateSet(nullptr);
    record(watch, *scene.root);
    scene.transform->getOrCreateStateSet();
    EXPECT_TRUE(watch.changed()) << "an empty one";
}

TEST(SceneWatch, FindsASequencesFrameChanged)
{
    Scene scene;
    osg::ref_ptr<osg::Sequence> sequence = new osg::Sequence;
    for (float x : {-5.f, 5.f})
    {
        osg::ref_ptr<osg::Geode> frame = new osg::Geode;
        frame->addDrawable(makeBox(osg::Vec3(x, 30, 0), osg::Vec3(x + 1, 31, 1)));
        sequence->addChild(frame, 0.1);
    }
    sequence->setValue(0);
    scene.root->addChild(sequence);
    SceneWatch watch;
    record(watch, *scene.root);
    sequence->setValue(1);
    EXPECT_TRUE(watch.changed());
}

TEST(SceneWatch, FindsAnOccluderPolygonAdded)
{
    Scene scene;
    osg::ref_ptr<osgVis::Occluder> occluder = new osgVis::Occluder;
    scene.root->addChild(occluder);
    SceneWatch watch;
    record(watch, *scene.root);
    occluder->addPolygon({osg::Vec3d(-5, 15, -5), osg::Vec3d(5, 15, -5), osg::Vec3d(5, 15, 5), osg::Vec3d(-5, 15, 5)});
    EXPECT_TRUE(watch.changed());
}

// The extraction flags what lies below a culling-inactive node as never culled.
TEST(SceneWatch, FindsCullingActiveTurnedOff)
{
    Scene scene;
    SceneWatch watch;
    record(watch, *scene.root);
    scene.geode->setCullingActive(false);
    EXPECT_TRUE(watch.changed()) << "a geode";

    scene.geode->setCullingActive(true);
    record(watch, *scene.root);
    scene.strip->setCullingActive(false);
    EXPECT_TRUE(watch.changed()) << "a drawable";
}

// An application toggling a highlight: two state sets that read the same for the extraction,
// swapped on one node at every frame. Each swap is no change, and the watch must not grow with them.
TEST(SceneWatch, KeepsItsMemoryBoundedUnderStateSwaps)
{
    Scene scene;
    osg::ref_ptr<osg::StateSet> plain = new osg::StateSet, highlight = new osg::StateSet;
    scene.transform->setStateSet(plain);
    SceneWatch watch;
    record(watch, *scene.root);
    const std::size_t states = watch.stateEntries(), held = watch.heldEntries();
    constexpr int Swaps = 100000;
    for (int swap = 0; swap < Swaps; ++swap)
    {
        scene.transform->setStateSet(swap % 2 ? plain : highlight);
        ASSERT_FALSE(watch.changed()) << "swap " << swap << ": the same reading";
        ASSERT_LE(watch.stateEntries(), 2 * states + 64) << "swap " << swap;
        ASSERT_LE(watch.heldEntries(), 2 * held + 64) << "swap " << swap;
    }

    // A new state set at every frame (a copy, as some applications make), dropped by the application.
    for (int swap = 0; swap < 1000; ++swap)
    {
        scene.transform->setStateSet(new osg::StateSet);
        ASSERT_FALSE(watch.changed()) << "copy " << swap;
        ASSERT_LE(watch.stateEntries(), 2 * states + 64) << "copy " << swap;
        ASSERT_LE(watch.heldEntries(), 2 * held + 64) << "copy " << swap;
    }

    // Still watching: the state set now in use, edited, and the one before, put back edited.
    scene.transform->getStateSet()->setMode(GL_BLEND, osg::StateAttribute::ON);
    EXPECT_TRUE(watch.changed()) << "the state set in use, edited";
    scene.transform->setStateSet(plain);
    plain->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    EXPECT_TRUE(watch.changed()) << "an earlier one, put back edited";
}
