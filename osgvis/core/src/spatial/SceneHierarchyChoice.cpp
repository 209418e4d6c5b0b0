// SPDX-License-Identifier: MIT
// The choice between a renderer's hierarchy and a module's own tree (visibility API, Luka §3.3:
// "ordered traversal by callback"), shared by the octree, mask and cdt modules.
#include <osgVis/core/spatial/SceneHierarchyChoice.h>

namespace osgVis::core
{
void SceneHierarchyChoice::choose(const Scene& scene, bool wanted)
{
    _hierarchy.reset();
    _problem.clear();
    if (!wanted || !scene.hierarchy)
        return;
    _index.build(*scene.hierarchy, scene);
    if (_index.usable())
        _hierarchy = scene.hierarchy;
    _problem = _index.problem();
}
} // namespace osgVis::core
