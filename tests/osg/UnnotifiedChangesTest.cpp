// SPDX-License-Identifier: MIT
// Changes nobody reports: an application that never calls dirtyScene() and edits its nodes directly,
// as an update callback does (a transform's matrix, a group's children, vertices edited in place, a
// Switch, an LOD as the eye moves, node masks, state). At the next cull the VisibilityGroup (and
// osgVis::CullVisitor, on a plain group) must draw what OSG now draws: in every mode, an object
// brought into view and whatever a moved, disabled or transparent wall hid; in the modes that cull
// by the frustum, not an object gone out of view. Bare cull visitors (TestView), no GL; each step
// draws a few frames with the eye standing still.
//
//   eye at the origin looking down +y (z up), 40° square frustum.
//   wall (a static MatrixTransform over one box): x ∈ [-1, 20], y ∈ [10, 11], z ∈ [-20, 20]; it
//   hides the boxes 2 m wide at (2.5, 25, 0) and (6, 25, 0) (every occlusion mode but cellportal
//   leaves them out, and the tests that change the wall check that it did before the change);
//   a box at (-5, 25, 0) passes left of it, in view; (0, -25, 0) is behind the eye.
//
//          □ (-5, 25)      □ (2.5, 25)  □ (6, 25)
//                 ▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔▔ wall, y = 10, from x = -1
//                   ◉ eye, looking up the page
//                   □ (0, -25), behind the eye
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/PositionAttitudeTransform>
#include <osg/StateSet>
#include <osg/Switch>

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

using osgVis::test::makeBox;
using osgVis::test::TestView;

namespace
{
using Drawn = std::set<const osg::Drawable*>;

const osg::Vec3 Centre(0, 25, 0);      // the middle of the view (behind the wall where there is one)
const osg::Vec3 BehindEye(0, -25, 0);  // outside the frustum
const osg::Vec3 OpenBeside(-5, 25, 0); // in view, left of the wall's shadow
const osg::Vec3 BehindTheWall[] = {osg::Vec3(2.5f, 25, 0), osg::Vec3(6, 25, 0)};

osg::Matrixd lookingDownY(const osg::Vec3d& eye)
{
    return osg::Matrixd::lookAt(eye, eye + osg::Vec3d(0, 1, 0), osg::Vec3d(0, 0, 1));
}

// A box 2 m wide around `centre`.
osg::ref_ptr<osg::Geometry> boxAt(const osg::Vec3& centre)
{
    return makeBox(centre - osg::Vec3(1, 1, 1), centre + osg::Vec3(1, 1, 1));
}

osg::ref_ptr<osg::Geode> geodeOf(osg::Drawable* drawable)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable);
    return geode;
}

// A drawable under its own transform: moving it is setMatrix.
struct Placed
{
    osg::ref_ptr<osg::MatrixTransform> transform;
    osg::ref_ptr<osg::Geometry> box;
};

Placed place(osg::ref_ptr<osg::Geometry> box, const osg::Vec3& at, osg::Object::DataVariance variance)
{
    Placed placed{new osg::MatrixTransform(osg::Matrixd::translate(at)), std::move(box)};
    placed.transform->setDataVariance(variance);
    placed.transform->addChild(geodeOf(placed.box));
    return placed;
}

// The wall of the sketch, placed at y = 10 by a static transform.
Placed makeWall()
{
    return place(makeBox(osg::Vec3(-1, 0, -20), osg::Vec3(20, 1, 20)), osg::Vec3(0, 10, 0), osg::Object::STATIC);
}

// What the frames of one step drew: in every one of them, and in any.
struct Frames
{
    Drawn every, any;
    bool drewEvery(const osg::Drawable* drawable) const { return every.count(drawable) != 0; }
    bool drewAny(const osg::Drawable* drawable) const { return any.count(drawable) != 0; }
};

std::string modeName(const ::testing::TestParamInfo<const char*>& info)
{
    std::string name = info.param;
    std::replace(name.begin(), name.end(), '+', '_');
    return name;
}
} // namespace

class UnnotifiedChanges : public ::testing::TestWithParam<const char*>
{
protected:
    UnnotifiedChanges()
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(GetParam());
        // Back-off's probe frames let every object through; no case draws enough frames to reach
        // one, and here it is off besides.
        osgVis::core::BackOffOptions noBackOff;
        noBackOff.enabled = false;
        group->setBackOff(noBackOff);
        root = group;
    }

    // From here on the root is a plain osg::Group and the view culls it with an osgVis::CullVisitor.
    // note: its back-off cannot be turned off; a case draws far fewer than the 56 frames before its
    // first probe.
    void cullWithOsgVisCullVisitor()
    {
        root = new osg::Group;
        view = TestView(new osgVis::CullVisitor(GetParam()));
    }

    // Three frames from `eye`, looking down +y.
    Frames draw(const osg::Vec3d& eye = osg::Vec3d())
    {
        Frames frames;
        for (int frame = 0; frame < 3; ++frame)
        {
            const Drawn drawn = view.draw(*root, lookingDownY(eye));
            frames.any.insert(drawn.begin(), drawn.end());
            if (frame == 0)
            {
                frames.every = drawn;
                continue;
            }
            Drawn every;
            std::set_intersection(frames.every.begin(), frames.every.end(), drawn.begin(), drawn.end(),
                                  std::inserter(every, every.end()));
            frames.every.swap(every);
        }
        return frames;
    }

    // Modes whose answer leaves out every object outside the frustum (as DynamicCulling checks);
    // the others only promise to keep what is visible.
    bool cullsOutsideTheFrustum() const
    {
        const std::string mode = GetParam();
        return mode == "frustum" || mode == "octree" || mode == "frustum+octree";
    }

    // A box behind the eye under a transform of `variance`, moved into the view's centre and back.
    void checkTransformMovedIntoView(osg::Object::DataVariance variance)
    {
        const Placed car = place(boxAt(osg::Vec3()), BehindEye, variance);
        root->addChild(car.transform);
        const Frames before = draw();
        if (cullsOutsideTheFrustum())
        {
            EXPECT_FALSE(before.drewAny(car.box)) << "behind the eye";
        }

        car.transform->setMatrix(osg::Matrixd::translate(Centre));
        EXPECT_TRUE(draw().drewEvery(car.box)) << "moved into the view's centre";

        car.transform->setMatrix(osg::Matrixd::translate(BehindEye));
        const Frames after = draw();
        if (cullsOutsideTheFrustum())
        {
            EXPECT_FALSE(after.drewAny(car.box)) << "moved behind the eye again";
        }
    }

    struct WallScene
    {
        Placed wall;
        std::vector<osg::ref_ptr<osg::Geometry>> behind; // the boxes the wall hides
    };

    // Modes that hide both boxes behind the wall in this scene, in every frame (found by running):
    // octree, mask, cdt, frustum+octree and multifocal. Not frustum, which culls by the frustum only,
    // nor cellportal, whose cells a free-standing wall does not close off: it sees past the wall's
    // ends through portals and keeps the boxes.
    bool hidesBehindTheWall() const
    {
        const std::string mode = GetParam();
        return mode != "frustum" && mode != "cellportal";
    }

    // The wall and the boxes behind it under the root, drawn once: the wall is in view and, in the
    // modes that occlude here, the boxes are hidden, so that what a change of the wall uncovers is
    // proven uncovered by the change (a mode that never hid them would pass any such test).
    WallScene addWallScene()
    {
        WallScene scene{makeWall(), {}};
        root->addChild(scene.wall.transform);
        for (const osg::Vec3& at : BehindTheWall)
        {
            scene.behind.push_back(boxAt(at));
            root->addChild(geodeOf(scene.behind.back()));
        }
        const Frames before = draw();
        EXPECT_TRUE(before.drewEvery(scene.wall.box)) << "the wall, in view";
        if (hidesBehindTheWall())
        {
            for (std::size_t i = 0; i < scene.behind.size(); ++i)
                EXPECT_FALSE(before.drewAny(scene.behind[i])) << "box " << i << " behind the wall, hidden";
        }
        return scene;
    }

    static void expectUncovered(const Frames& frames, const WallScene& scene)
    {
        for (std::size_t i = 0; i < scene.behind.size(); ++i)
            EXPECT_TRUE(frames.drewEvery(scene.behind[i])) << "box " << i << " behind where the wall stood";
    }

    // The wall lifted far above the view: every box it hid is drawn.
    void checkWallMovedAway()
    {
        const WallScene scene = addWallScene();
        scene.wall.transform->setMatrix(osg::Matrixd::translate(0, 10, 100));
        const Frames after = draw();
        expectUncovered(after, scene);
        if (cullsOutsideTheFrustum())
        {
            EXPECT_FALSE(after.drewAny(scene.wall.box)) << "the wall, out of view";
        }
    }

    osg::ref_ptr<osg::Group> root; // the VisibilityGroup, or a plain group for osgVis::CullVisitor
    TestView view;
};

// 1. A moving object whose transform says so, and one whose application forgot to.
TEST_P(UnnotifiedChanges, DynamicTransformMovedIntoViewIsDrawn)
{
    checkTransformMovedIntoView(osg::Object::DYNAMIC);
}

TEST_P(UnnotifiedChanges, StaticTransformMovedIntoViewIsDrawn)
{
    checkTransformMovedIntoView(osg::Object::STATIC);
}

// 2. Geodes attached below nested groups (depth 2 and 3 under the root), detached and attached
// again. The outer group also holds a box behind the eye, so a cull that believed it held nothing
// else could skip it whole.
TEST_P(UnnotifiedChanges, GeodesAttachedBelowNestedGroupsAreDrawnWhileAttached)
{
    osg::ref_ptr<osg::Group> outer = new osg::Group, inner = new osg::Group;
    outer->addChild(geodeOf(boxAt(BehindEye)));
    outer->addChild(inner);
    root->addChild(outer);
    draw();

    const osg::ref_ptr<osg::Geometry> shallow = boxAt(osg::Vec3(-3, 25, 0)), deep = boxAt(osg::Vec3(3, 25, 0));
    const osg::ref_ptr<osg::Geode> shallowGeode = geodeOf(shallow), deepGeode = geodeOf(deep);
    for (const char* round : {"attached", "attached again"})
    {
        outer->addChild(shallowGeode);
        inner->addChild(deepGeode);
        const Frames attached = draw();
        EXPECT_TRUE(attached.drewEvery(shallow)) << round << ", depth 2";
        EXPECT_TRUE(attached.drewEvery(deep)) << round << ", depth 3";

        outer->removeChild(shallowGeode);
        inner->removeChild(deepGeode);
        const Frames detached = draw();
        EXPECT_FALSE(detached.drewAny(shallow)) << "detached, depth 2";
        EXPECT_FALSE(detached.drewAny(deep)) << "detached, depth 3";
    }
}

// 3. Vertices moved in place from behind the eye into view, as an animation writes them.
TEST_P(UnnotifiedChanges, VerticesEditedInPlaceIntoViewAreDrawn)
{
    const osg::ref_ptr<osg::Geometry> box = boxAt(BehindEye);
    root->addChild(geodeOf(box));
    const Frames before = draw();
    if (cullsOutsideTheFrustum())
    {
        EXPECT_FALSE(before.drewAny(box)) << "behind the eye";
    }

    auto* vertices = static_cast<osg::Vec3Array*>(box->getVertexArray());
    for (osg::Vec3& vertex : *vertices)
        vertex += Centre - BehindEye;
    vertices->dirty();
    box->dirtyBound();
    EXPECT_TRUE(draw().drewEvery(box)) << "moved into the view's centre";
}

// 4. A Switch swapping which of its two children is on.
TEST_P(UnnotifiedChanges, SwitchedOnChildIsDrawnAndSwitchedOffChildIsNot)
{
    const osg::ref_ptr<osg::Geometry> left = boxAt(osg::Vec3(-3, 25, 0)), right = boxAt(osg::Vec3(3, 25, 0));
    osg::ref_ptr<osg::Switch> switcher = new osg::Switch;
    switcher->addChild(geodeOf(left), true);
    switcher->addChild(geodeOf(right), false);
    root->addChild(switcher);
    const Frames first = draw();
    EXPECT_TRUE(first.drewEvery(left));
    EXPECT_FALSE(first.drewAny(right));

    switcher->setValue(0, false);
    switcher->setValue(1, true);
    const Frames swapped = draw();
    EXPECT_FALSE(swapped.drewAny(left)) << "switched off";
    EXPECT_TRUE(swapped.drewEvery(right)) << "switched on";

    switcher->setValue(0, true);
    switcher->setValue(1, false);
    const Frames back = draw();
    EXPECT_TRUE(back.drewEvery(left)) << "switched on again";
    EXPECT_FALSE(back.drewAny(right)) << "switched off again";
}

// 5. An object moved out from behind the wall into the open beside it, and back.
TEST_P(UnnotifiedChanges, ObjectMovedOutFromBehindTheWallIsDrawn)
{
    root->addChild(makeWall().transform);
    const osg::ref_ptr<osg::Geometry> box = boxAt(osg::Vec3());
    osg::ref_ptr<osg::PositionAttitudeTransform> mover = new osg::PositionAttitudeTransform;
    mover->setPosition(BehindTheWall[0]);
    mover->addChild(geodeOf(box));
    root->addChild(mover);
    draw(); // the occlusion modes may hide it

    mover->setPosition(OpenBeside);
    EXPECT_TRUE(draw().drewEvery(box)) << "beside the wall, in the open";

    mover->setPosition(BehindTheWall[0]);
    const Frames back = draw(); // hidden again for the occlusion modes; frustum culling keeps it
    if (std::string(GetParam()) == "frustum")
    {
        EXPECT_TRUE(back.drewEvery(box)) << "behind the wall, in view";
    }
}

// 6. The wall (an occluder) moved out of view.
TEST_P(UnnotifiedChanges, WallMovedAwayUncoversEveryBoxBehindIt)
{
    checkWallMovedAway();
}

// 7. A disabled node (beside an enabled one) enabled by its mask; the wall disabled by its mask.
TEST_P(UnnotifiedChanges, NodeEnabledByItsMaskIsDrawn)
{
    const osg::ref_ptr<osg::Geometry> enabled = boxAt(osg::Vec3(-3, 25, 0)), box = boxAt(osg::Vec3(3, 25, 0));
    const osg::ref_ptr<osg::Geode> geode = geodeOf(box);
    geode->setNodeMask(0);
    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->addChild(geodeOf(enabled));
    group->addChild(geode);
    root->addChild(group);
    const Frames before = draw();
    EXPECT_TRUE(before.drewEvery(enabled));
    EXPECT_FALSE(before.drewAny(box)) << "disabled";

    geode->setNodeMask(~0u);
    const Frames after = draw();
    EXPECT_TRUE(after.drewEvery(enabled));
    EXPECT_TRUE(after.drewEvery(box)) << "enabled";
}

TEST_P(UnnotifiedChanges, WallDisabledByItsMaskUncoversEveryBoxBehindIt)
{
    const WallScene scene = addWallScene();
    scene.wall.transform->getChild(0)->setNodeMask(0);
    const Frames after = draw();
    expectUncovered(after, scene);
    EXPECT_FALSE(after.drewAny(scene.wall.box)) << "the wall, disabled";
}

// 8. An LOD as the eye steps back and forth across its switch distance: the child OSG selects (the
// same LOD culled alone by a stock visitor) is drawn, the other one is not.
TEST_P(UnnotifiedChanges, LodDrawsTheChildOsgSelectsAsTheEyeMoves)
{
    // Two boxes in one place, as two levels of detail of one object, 20 m ahead of the origin.
    const osg::ref_ptr<osg::Geometry> detailed = boxAt(osg::Vec3(0, 20, 0)), coarse = boxAt(osg::Vec3(0, 20, 0));
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->addChild(geodeOf(detailed), 0.f, 50.f);
    lod->addChild(geodeOf(coarse), 50.f, 1e9f);
    root->addChild(lod);

    TestView plainOsg;
    for (const osg::Vec3d& eye : {osg::Vec3d(0, 0, 0), osg::Vec3d(0, -60, 0), osg::Vec3d(0, 0, 0)})
    {
        const Drawn selected = plainOsg.draw(*lod, lookingDownY(eye));
        EXPECT_EQ(selected, (Drawn{eye.y() < 0 ? coarse.get() : detailed.get()})) << "OSG's own choice";
        const Frames frames = draw(eye);
        EXPECT_EQ(frames.every, selected) << "eye at y = " << eye.y();
        EXPECT_EQ(frames.any, selected) << "eye at y = " << eye.y();
    }
}

// 9. The wall made transparent in its own state set: it hides nothing any more.
TEST_P(UnnotifiedChanges, WallTurnedTransparentUncoversEveryBoxBehindIt)
{
    const WallScene scene = addWallScene();
    osg::StateSet* state = scene.wall.box->getOrCreateStateSet();
    state->setMode(GL_BLEND, osg::StateAttribute::ON);
    state->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    const Frames after = draw();
    expectUncovered(after, scene);
    EXPECT_TRUE(after.drewEvery(scene.wall.box)) << "the wall, transparent and in view";
}

// 10. A box behind the wall whose geode has its culling turned off: OSG never culls it by its bound,
// so no mode may hide it any more.
TEST_P(UnnotifiedChanges, BoxBehindTheWallMadeCullingInactiveIsDrawn)
{
    const WallScene scene = addWallScene();
    scene.behind[0]->getParent(0)->setCullingActive(false);
    const Frames after = draw();
    EXPECT_TRUE(after.drewEvery(scene.behind[0])) << "culling inactive";
    if (hidesBehindTheWall())
    {
        EXPECT_FALSE(after.drewAny(scene.behind[1])) << "the other box, still behind the wall";
    }
}

// 11. Cases 1 and 6 with osgVis::CullVisitor culling a plain group.
TEST_P(UnnotifiedChanges, CullVisitorDrawsADynamicTransformMovedIntoView)
{
    cullWithOsgVisCullVisitor();
    checkTransformMovedIntoView(osg::Object::DYNAMIC);
}

TEST_P(UnnotifiedChanges, CullVisitorDrawsAStaticTransformMovedIntoView)
{
    cullWithOsgVisCullVisitor();
    checkTransformMovedIntoView(osg::Object::STATIC);
}

TEST_P(UnnotifiedChanges, CullVisitorDrawsWhatAMovedWallUncovered)
{
    cullWithOsgVisCullVisitor();
    checkWallMovedAway();
}

// cellportal bakes its cells on the spot and multifocal computes the PVS of the eye's grid cell as
// it enters it: neither needs a bake made beforehand.
INSTANTIATE_TEST_SUITE_P(Modes, UnnotifiedChanges,
                         ::testing::Values("frustum", "octree", "mask", "cdt", "frustum+octree", "cellportal",
                                           "multifocal"),
                         modeName);
