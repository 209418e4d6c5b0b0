#include <osgVis/core/VisibilityModule.h>

namespace osgVis::core
{
void VisibilityModule::sceneChanged(const SceneChange&)
{
    if (_scene)
        setScene(*_scene);
}
} // namespace osgVis::core
