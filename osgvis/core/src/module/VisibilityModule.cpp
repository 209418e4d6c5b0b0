// SPDX-License-Identifier: MIT
#include <osgVis/core/module/VisibilityModule.h>

namespace osgVis::core
{
void VisibilityModule::sceneChanged(const SceneChange& change)
{
    if (_scene)
        sceneReplaced(*_scene, {change});
}

void VisibilityModule::sceneReplaced(const Scene& scene, const std::vector<SceneChange>&)
{
    setScene(scene);
}
} // namespace osgVis::core
