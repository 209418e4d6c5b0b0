// SPDX-License-Identifier: MIT
#include <osgVis/core/module/VisibilityModule.h>

namespace osgVis::core
{
void VisibilityModule::sceneChanged(const SceneChange&)
{
    if (_scene)
        setScene(*_scene);
}

void VisibilityModule::sceneReplaced(const Scene& scene, const std::vector<SceneChange>&)
{
    setScene(scene);
}
} // namespace osgVis::core
