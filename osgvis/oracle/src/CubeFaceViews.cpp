// SPDX-License-Identifier: MIT
#include <osgVis/oracle/CubeFaceViews.h>

namespace osgVis::oracle
{
std::array<osg::Matrixd, 6> cubeFaceViews(const osg::Vec3d& eye)
{
    struct Face
    {
        osg::Vec3d forward, up;
    };
    static const Face faces[6] = {{{1, 0, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}},
                                  {{0, -1, 0}, {0, 0, 1}}, {{0, 0, 1}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}}};
    std::array<osg::Matrixd, 6> views;
    for (std::size_t i = 0; i < 6; ++i)
        views[i] = osg::Matrixd::lookAt(eye, eye + faces[i].forward, faces[i].up);
    return views;
}

osg::Matrixd cubeFaceProjection(double zNear, double zFar)
{
    // note: frustum, not perspective(90°): tan(π/4) rounds below 1, which would leave cracks between faces
    return osg::Matrixd::frustum(-zNear, zNear, -zNear, zNear, zNear, zFar);
}
} // namespace osgVis::oracle
