// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/View.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
View makeView(const Mat4& viewMatrix, const Mat4& projectionMatrix, double time, std::uint32_t viewportWidth,
              std::uint32_t viewportHeight)
{
    View v;
    v.viewMatrix = viewMatrix;
    v.projectionMatrix = projectionMatrix;
    const Vec4 eye = glm::inverse(viewMatrix) * Vec4(0.0, 0.0, 0.0, 1.0);
    v.eye = Vec3(eye) / eye.w;
    v.frustum = Frustum::fromMatrix(projectionMatrix * viewMatrix);
    v.time = time;
    v.viewportWidth = viewportWidth;
    v.viewportHeight = viewportHeight;
    // A perspective projection copies -z into w; an orthographic one keeps w = 1.
    v.orthographic = projectionMatrix[3][3] == 1.0 && projectionMatrix[2][3] == 0.0;
    return v;
}

double nearDistance(const View& view)
{
    const Mat4& projection = view.projectionMatrix;
    const double distance = projection[3][2] / (projection[2][2] - 1.0);
    return std::isfinite(distance) && distance > 0.0 ? distance : 0.0;
}

double nearPlaneReach(const View& view)
{
    const Mat4 clipToWorld = glm::inverse(view.projectionMatrix * view.viewMatrix);
    double reach = 0.0;
    for (int corner = 0; corner < 4; ++corner)
    {
        const Vec4 p = clipToWorld * Vec4((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, -1.0, 1.0);
        if (p.w != 0.0)
            reach = std::max(reach, glm::length(Vec3(p) / p.w - view.eye));
    }
    return std::isfinite(reach) ? reach : 0.0;
}
} // namespace osgVis::core
