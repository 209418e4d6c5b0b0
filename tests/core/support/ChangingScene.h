// SPDX-License-Identifier: MIT
#pragma once
// A scene that changes under a module the way renderers change theirs, for the tests of modules that
// take changes (mask, frustum, octree, cdt).
#include <osgVis/core/module/VisibilityModule.h>

#include <functional>
#include <memory>
#include <vector>

namespace osgVis::test
{
// Moves a box object (made by addBox) in place: same triangle count, new bounds and triangles.
void reshapeBox(core::Scene& scene, core::ObjectId id, const core::Vec3& lo, const core::Vec3& hi);

// A street front (building at x -10..10, y 0..10, height 15) hiding three boxes, and an open box to
// the right: seen from (0, -20, 5) along +y the front hides the three and not the open one.
struct StreetFront
{
    core::Scene scene;
    core::ObjectId front = core::InvalidObject, open = core::InvalidObject;
    std::vector<core::ObjectId> hiddenBoxes;
};
StreetFront makeStreetFront();

// Changes go to the scene in place (sceneChanged) or to a copy (sceneReplaced); every copy is kept
// alive, since the module may hold any of them.
class ChangingScene
{
public:
    void reset(core::Scene first);
    const core::Scene& current() const { return *_scenes.back(); }
    core::Scene& current() { return *_scenes.back(); }
    /// Per object id: removed by a change (what the renderer no longer draws).
    const std::vector<bool>& removed() const { return _removed; }
    void change(core::VisibilityModule& module, core::SceneChange::Kind kind, std::vector<core::ObjectId> ids,
                const std::function<void(core::Scene&)>& mutate, bool replace);

private:
    std::vector<std::unique_ptr<core::Scene>> _scenes;
    std::vector<bool> _removed;
};
} // namespace osgVis::test
