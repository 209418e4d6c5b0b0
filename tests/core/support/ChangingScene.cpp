// SPDX-License-Identifier: MIT
#include "ChangingScene.h"

#include "BoxScenes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace osgVis::test
{
void reshapeBox(core::Scene& scene, core::ObjectId id, const core::Vec3& lo, const core::Vec3& hi)
{
    const std::vector<core::Triangle> t = boxTriangles(lo, hi);
    core::SceneObject& object = scene.objects[id];
    ASSERT_EQ(object.triangleCount, t.size());
    std::copy(t.begin(), t.end(), scene.triangles.begin() + object.firstTriangle);
    object.bounds = boundsOf(t);
}

StreetFront makeStreetFront()
{
    StreetFront street;
    street.front = addBox(street.scene, {-10, 0, 0}, {10, 10, 15}, "street front");
    for (int i = 0; i < 3; ++i)
        street.hiddenBoxes.push_back(addBox(street.scene, {-6.0 + 4.0 * i, 20, 0}, {-5.0 + 4.0 * i, 21, 2},
                                            "hidden box " + std::to_string(i)));
    street.open = addBox(street.scene, {25, 20, 0}, {26, 21, 2}, "open box");
    return street;
}

void ChangingScene::reset(core::Scene first)
{
    _scenes.clear();
    _scenes.push_back(std::make_unique<core::Scene>(std::move(first)));
    _removed.assign(current().objects.size(), false);
}

void ChangingScene::change(core::VisibilityModule& module, core::SceneChange::Kind kind, std::vector<core::ObjectId> ids,
                           const std::function<void(core::Scene&)>& mutate, bool replace)
{
    const core::SceneChange c{kind, ids};
    if (replace)
    {
        _scenes.push_back(std::make_unique<core::Scene>(current()));
        mutate(current());
        module.sceneReplaced(current(), {c});
    }
    else
    {
        mutate(current());
        module.sceneChanged(c);
    }
    _removed.resize(current().objects.size(), false);
    for (core::ObjectId id : ids)
        _removed[id] = kind == core::SceneChange::Kind::Removed;
}
} // namespace osgVis::test
