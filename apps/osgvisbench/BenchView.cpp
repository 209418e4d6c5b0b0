#include "BenchView.h"

#include "../osgvisviewer/CameraSetup.h"

#include <cmath>

namespace osgVis::bench
{
namespace
{
std::vector<std::size_t> evenlySpacedIndices(std::size_t available, unsigned count)
{
    std::vector<std::size_t> indices;
    if (count == 0 || count >= available)
    {
        for (std::size_t i = 0; i < available; ++i)
            indices.push_back(i);
        return indices;
    }
    for (unsigned i = 0; i < count; ++i)
    {
        const double position = count == 1 ? 0.0 : double(i) * double(available - 1) / double(count - 1);
        indices.push_back(std::size_t(std::llround(position)));
    }
    return indices;
}
} // namespace

std::vector<BenchView> makeBenchViews(const core::Walk& walk, unsigned count)
{
    const core::Mat4 projection = walk.projection.matrix(walk.aspect());
    std::vector<BenchView> views;
    for (std::size_t index : evenlySpacedIndices(walk.keys.size(), count))
    {
        BenchView view;
        view.key = walk.keys[index];
        const core::Mat4 viewMatrix = view.key.viewMatrix();
        view.view = viewer::toOsgMatrix(viewMatrix);
        view.projection = viewer::toOsgMatrix(projection);
        view.frustum = core::Frustum::fromMatrix(projection * viewMatrix);
        views.push_back(view);
    }
    return views;
}
} // namespace osgVis::bench
