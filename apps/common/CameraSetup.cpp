// SPDX-License-Identifier: MIT
#include "CameraSetup.h"

#include <glm/gtc/type_ptr.hpp>

namespace osgVis::apps
{
// note: osg::Matrixd stores the transpose of the mathematical matrix row by row, which is the
// same memory layout as GLM's column-major storage, so the conversion is a plain copy.
osg::Matrixd toOsgMatrix(const core::Mat4& m)
{
    return osg::Matrixd(glm::value_ptr(m));
}

core::Mat4 toCoreMatrix(const osg::Matrixd& m)
{
    return glm::make_mat4(m.ptr());
}

osg::Matrixd walkViewMatrix(const core::WalkKey& key)
{
    return toOsgMatrix(key.viewMatrix());
}

void applyWalkProjection(osg::Camera& camera, const core::WalkProjection& projection, double aspect)
{
    camera.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera.setCullingMode(camera.getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
    camera.setProjectionMatrix(toOsgMatrix(projection.matrix(aspect)));
}
} // namespace osgVis::apps
