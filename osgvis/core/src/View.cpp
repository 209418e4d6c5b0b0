#include <osgVis/core/View.h>

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
} // namespace osgVis::core
