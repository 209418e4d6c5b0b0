// SPDX-License-Identifier: MIT
#include "BenchView.h"

#include <CameraSetup.h>

namespace osgVis::bench
{
std::vector<BenchView> makeBenchViews(const core::Walk& walk)
{
    const core::Mat4 projection = walk.projection.matrix(walk.aspect());
    std::vector<BenchView> views;
    views.reserve(walk.keys.size());
    for (const core::WalkKey& key : walk.keys)
    {
        BenchView view;
        view.key = key;
        const core::Mat4 viewMatrix = key.viewMatrix();
        view.view = apps::toOsgMatrix(viewMatrix);
        view.projection = apps::toOsgMatrix(projection);
        view.frustum = core::Frustum::fromMatrix(projection * viewMatrix);
        views.push_back(view);
    }
    return views;
}

std::vector<core::View> makeCoreViews(const core::Walk& walk)
{
    const core::Mat4 projection = walk.projection.matrix(walk.aspect());
    std::vector<core::View> views;
    views.reserve(walk.keys.size());
    for (const core::WalkKey& key : walk.keys)
        views.push_back(core::makeView(key.viewMatrix(), projection, key.time, walk.width, walk.height));
    return views;
}
} // namespace osgVis::bench
