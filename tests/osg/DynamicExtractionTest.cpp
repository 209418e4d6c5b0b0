// SPDX-License-Identifier: MIT
// Dynamic scenes through the adapter: a re-extraction after dirtyScene keeps object ids, reports
// exactly what was inserted, moved and removed, hands views' chains sceneReplaced instead of a
// rebuild, and the VisibilityGroup still draws exactly the objects in the frustum. Bare cull
// visitors with their own render stage, no GL.
//
//   eye at the origin looking down +x, 40° square frustum; boxes 2 m wide at (10, -2), (20, 3),
//   (30, 0), (25, -5) are inside it and none hides another (occlusion modes keep them all), boxes at
//   y = 100 or y = -100 are outside.
#include "TestScenes.h"

#include <osgVis/Occluder>
#include <osgVis/SceneExtractor>
#include <osgVis/VisibilityGroup>

#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/Geode>
#include <osg/MatrixTransform>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <set>

using osgVis::core::ObjectId;
using osgVis::core::SceneChange;
using osgVis::test::makeBox;
using osgVis::test::TestView;
using Kind = SceneChange::Kind;

namespace
{
// A box of 2 m at `centre`, under its own transform (so moving it = changing the matrix).
struct Car
{
    osg::ref_ptr<osg::MatrixTransform> transform;
    osg::ref_ptr<osg::Geometry> box;
};

Car makeCar(const osg::Vec3d& centre, osg::Object::DataVariance variance = osg::Object::STATIC)
{
    Car car{new osg::MatrixTransform(osg::Matrixd::translate(centre)),
            makeBox(osg::Vec3(-1, -1, -1), osg::Vec3(1, 1, 1))};
    car.transform->setDataVariance(variance);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(car.box);
    car.transform->addChild(geode);
    return car;
}

std::vector<SceneChange> changesOf(std::vector<ObjectId> removed, std::vector<ObjectId> moved,
                                   std::vector<ObjectId> inserted)
{
    std::vector<SceneChange> out;
    if (!removed.empty())
        out.push_back({Kind::Removed, removed});
    if (!moved.empty())
        out.push_back({Kind::Moved, moved});
    if (!inserted.empty())
        out.push_back({Kind::Inserted, inserted});
    return out;
}

void expectChanges(const std::vector<SceneChange>& actual, const std::vector<SceneChange>& expected)
{
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i)
    {
        EXPECT_EQ(actual[i].kind, expected[i].kind) << "change " << i;
        EXPECT_EQ(actual[i].objects, expected[i].objects) << "change " << i;
    }
}

// What the chain of each view was told, in order.
struct ChainLog
{
    struct Call
    {
        bool replaced = false; // sceneReplaced; false: setScene
        std::size_t objects = 0;
        std::vector<SceneChange> changes;
    };
    std::vector<Call> calls;
};

class DynamicRecorder : public osgVis::core::VisibilityModule
{
public:
    static constexpr const char* Name = "test-dynamic-recorder";
    explicit DynamicRecorder(std::shared_ptr<ChainLog> log) : _log(std::move(log)) {}
    const char* name() const override { return Name; }
    void setScene(const osgVis::core::Scene& scene) override
    {
        _scene = &scene;
        _log->calls.push_back({false, scene.objects.size(), {}});
    }
    void sceneReplaced(const osgVis::core::Scene& scene, const std::vector<SceneChange>& changes) override
    {
        _scene = &scene;
        _log->calls.push_back({true, scene.objects.size(), changes});
    }
    void cull(const osgVis::core::View&, osgVis::core::VisibleSet&) override {}

private:
    std::shared_ptr<ChainLog> _log;
};

std::shared_ptr<ChainLog> registerRecorder()
{
    auto log = std::make_shared<ChainLog>();
    osgVis::core::registerModule(DynamicRecorder::Name, [log] { return std::make_unique<DynamicRecorder>(log); });
    return log;
}

// Root with three cars: 0 and 1 in view, 2 outside (y = 100).
struct Street
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    std::vector<Car> cars;

    explicit Street(osg::ref_ptr<osg::Group> group = new osg::Group) : root(std::move(group))
    {
        for (const osg::Vec3d& centre : {osg::Vec3d(10, -2, 0), osg::Vec3d(20, 3, 0), osg::Vec3d(20, 100, 0)})
            add(centre);
    }
    Car& add(const osg::Vec3d& centre)
    {
        cars.push_back(makeCar(centre));
        root->addChild(cars.back().transform);
        return cars.back();
    }
};
} // namespace

TEST(DynamicExtraction, UnchangedSceneKeepsIdsAndReportsNothing)
{
    Street street;
    const auto first = osgVis::extractScene(*street.root);
    const auto again = osgVis::reextractScene(*street.root, *first);
    EXPECT_EQ(again->replaces, first.get());
    EXPECT_TRUE(again->changes.empty());
    ASSERT_EQ(again->scene.objects.size(), 3u);
    for (ObjectId id = 0; id < 3; ++id)
    {
        EXPECT_EQ(again->refs[id].drawable, first->refs[id].drawable);
        EXPECT_EQ(again->scene.objects[id].id, id);
    }
    EXPECT_EQ(first->replaces, nullptr);
}

TEST(DynamicExtraction, AddRemoveMoveKeepIdsAndAreReportedExactly)
{
    Street street;
    const auto first = osgVis::extractScene(*street.root);

    // Insert a car before the others (a fresh extraction would renumber them all), remove car 1,
    // move car 2 into view.
    Car inserted = makeCar(osg::Vec3d(30, 0, 0));
    street.root->insertChild(0, inserted.transform);
    street.root->removeChild(street.cars[1].transform);
    street.cars[2].transform->setMatrix(osg::Matrixd::translate(40, 0, 0));

    const auto second = osgVis::reextractScene(*street.root, *first);
    EXPECT_EQ(second->replaces, first.get());
    expectChanges(second->changes, changesOf({1}, {2}, {3}));
    ASSERT_EQ(second->scene.objects.size(), 4u);
    EXPECT_EQ(second->refs[0].drawable, street.cars[0].box);
    EXPECT_EQ(second->refs[2].drawable, street.cars[2].box);
    EXPECT_EQ(second->refs[3].drawable, inserted.box);
    EXPECT_TRUE(second->removed(1));
    EXPECT_TRUE(second->scene.objects[1].bounds.empty());
    EXPECT_EQ(second->scene.objects[1].triangleCount, 0u);
    EXPECT_EQ(second->scene.objects[2].bounds.center().x, 40.0);
    EXPECT_EQ(second->scene.objects[3].bounds.center().x, 30.0);
    EXPECT_EQ(second->scene.objects[3].triangleCount, 12u);
    // Stored triangles follow their object.
    const osgVis::core::SceneObject& moved = second->scene.objects[2];
    EXPECT_EQ(second->scene.triangles[moved.firstTriangle].a.x >= 39.f, true);
    // Look-ups and child ranges speak the stable ids.
    EXPECT_EQ(second->find(inserted.box.get(), second->refs[3].path), 3u);
    EXPECT_TRUE(second->idsOf(street.cars[1].box.get()).empty());
    ASSERT_EQ(second->childRanges.size(), 3u);
    EXPECT_EQ(second->childRanges[0].ids, (std::vector<ObjectId>{3}));
    EXPECT_EQ(second->childRanges[1].ids, (std::vector<ObjectId>{0}));
    EXPECT_EQ(second->childRanges[2].ids, (std::vector<ObjectId>{2}));

    // A slot already empty is not reported again; a re-added drawable is a new object.
    street.root->addChild(street.cars[1].transform);
    const auto third = osgVis::reextractScene(*street.root, *second);
    expectChanges(third->changes, changesOf({}, {}, {4}));
    EXPECT_TRUE(third->removed(1));
    EXPECT_EQ(third->refs[4].drawable, street.cars[1].box);
}

TEST(DynamicExtraction, NestedTransformsAndSharedDrawables)
{
    Street street;
    // A car instanced twice: one drawable, two paths, two objects.
    osg::ref_ptr<osg::MatrixTransform> twin = new osg::MatrixTransform(osg::Matrixd::translate(0, 5, 0));
    twin->addChild(street.cars[0].transform);
    street.root->addChild(twin);
    const auto first = osgVis::extractScene(*street.root);
    ASSERT_EQ(first->scene.objects.size(), 4u);
    ASSERT_EQ(first->refs[3].drawable, street.cars[0].box);

    // Moving the inner transform moves both instances; moving the outer one only the second.
    street.cars[0].transform->setMatrix(osg::Matrixd::translate(11, 0, 0));
    const auto second = osgVis::reextractScene(*street.root, *first);
    expectChanges(second->changes, changesOf({}, {0, 3}, {}));
    twin->setMatrix(osg::Matrixd::translate(0, 6, 0));
    const auto third = osgVis::reextractScene(*street.root, *second);
    expectChanges(third->changes, changesOf({}, {3}, {}));
    EXPECT_EQ(third->scene.objects[3].bounds.center().y, 6.0);
    // Removing one path removes one instance.
    street.root->removeChild(twin);
    const auto fourth = osgVis::reextractScene(*street.root, *third);
    expectChanges(fourth->changes, changesOf({3}, {}, {}));
    EXPECT_EQ(fourth->idsOf(street.cars[0].box.get()), (std::vector<ObjectId>{0}));
}

TEST(DynamicExtraction, DynamicTransformFlagsItsObjectsAndAFlagChangeIsAMove)
{
    Street street;
    Car car = street.add(osg::Vec3d(50, 0, 0));
    const auto first = osgVis::extractScene(*street.root);
    EXPECT_EQ(first->scene.objects[3].flags & osgVis::core::OBJECT_DYNAMIC, 0u);
    car.transform->setDataVariance(osg::Object::DYNAMIC);
    const auto second = osgVis::reextractScene(*street.root, *first);
    EXPECT_NE(second->scene.objects[3].flags & osgVis::core::OBJECT_DYNAMIC, 0u);
    expectChanges(second->changes, changesOf({}, {3}, {}));
}

TEST(DynamicExtraction, ChangedStandAloneOccludersFallBackToAFreshExtraction)
{
    Street street;
    const auto first = osgVis::extractScene(*street.root);
    street.root->removeChild(street.cars[0].transform);
    osg::ref_ptr<osgVis::Occluder> wall = new osgVis::Occluder;
    wall->addPolygon({osg::Vec3d(5, -5, -5), osg::Vec3d(5, 5, -5), osg::Vec3d(5, 5, 5), osg::Vec3d(5, -5, 5)});
    street.root->addChild(wall);
    const auto second = osgVis::reextractScene(*street.root, *first);
    EXPECT_EQ(second->replaces, nullptr);
    EXPECT_TRUE(second->changes.empty());
    ASSERT_EQ(second->scene.objects.size(), 2u); // dense again, depth-first
    EXPECT_EQ(second->refs[0].drawable, street.cars[1].box);
}

TEST(DynamicExtraction, ViewsHoldingThePreviousExtractionGetSceneReplaced)
{
    const auto log = registerRecorder();
    osg::ref_ptr<osgVis::VisibilityGroup> group =
        new osgVis::VisibilityGroup(std::string("frustum,") + DynamicRecorder::Name);
    Street street(group);
    TestView viewA, viewB;
    viewA.draw(*group);
    viewB.draw(*group);
    ASSERT_EQ(log->calls.size(), 2u);
    EXPECT_FALSE(log->calls[0].replaced);
    EXPECT_FALSE(log->calls[1].replaced);

    // View A sees one change; view B skips it and sees the next one: it holds an older extraction.
    street.cars[2].transform->setMatrix(osg::Matrixd::translate(30, 0, 0));
    group->dirtyScene();
    viewA.draw(*group);
    ASSERT_EQ(log->calls.size(), 3u);
    EXPECT_TRUE(log->calls[2].replaced);
    expectChanges(log->calls[2].changes, changesOf({}, {2}, {}));

    group->removeChild(street.cars[0].transform);
    viewA.draw(*group);
    viewB.draw(*group);
    ASSERT_EQ(log->calls.size(), 5u);
    EXPECT_TRUE(log->calls[3].replaced);
    expectChanges(log->calls[3].changes, changesOf({0}, {}, {}));
    EXPECT_FALSE(log->calls[4].replaced);
    EXPECT_EQ(log->calls[4].objects, 3u);

    // Statistics count live objects only.
    EXPECT_EQ(group->getLastStatistics().objects, 2u);
    EXPECT_EQ(group->getLastStatistics().visible, 2u);
}

class DynamicCulling : public ::testing::TestWithParam<const char*>
{
};

TEST_P(DynamicCulling, DrawsExactlyTheObjectsInViewAfterEachChange)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(GetParam());
    Street street(group);
    TestView view;
    using Drawn = std::set<const osg::Drawable*>;
    EXPECT_EQ(view.draw(*group), (Drawn{street.cars[0].box.get(), street.cars[1].box.get()}));

    // Drive car 2 into view and car 0 out of it.
    street.cars[2].transform->setMatrix(osg::Matrixd::translate(30, 0, 0));
    street.cars[0].transform->setMatrix(osg::Matrixd::translate(10, -100, 0));
    group->dirtyScene();
    EXPECT_EQ(view.draw(*group), (Drawn{street.cars[1].box.get(), street.cars[2].box.get()}));
    EXPECT_EQ(group->getViewCuller()->getScene()->changes.size(), 1u);

    // Drop a new building in view, remove car 1.
    Car building = street.add(osg::Vec3d(25, -5, 0));
    group->removeChild(street.cars[1].transform);
    EXPECT_EQ(view.draw(*group), (Drawn{street.cars[2].box.get(), building.box.get()}));

    // Nest a car under the new building's transform (it follows the building).
    Car rider = makeCar(osg::Vec3d(0, 0, 3));
    building.transform->addChild(rider.transform);
    group->dirtyScene();
    EXPECT_EQ(view.draw(*group), (Drawn{street.cars[2].box.get(), building.box.get(), rider.box.get()}));
    building.transform->setMatrix(osg::Matrixd::translate(15, 200, 0));
    group->dirtyScene();
    EXPECT_EQ(view.draw(*group), (Drawn{street.cars[2].box.get()}));

    const auto scene = group->getViewCuller()->getScene();
    ASSERT_TRUE(scene);
    EXPECT_NE(scene->replaces, nullptr);
    EXPECT_EQ(scene->scene.objects.size(), 5u);
    EXPECT_TRUE(scene->removed(1));
}

INSTANTIATE_TEST_SUITE_P(Modes, DynamicCulling, ::testing::Values("frustum", "octree", "frustum+octree"));
