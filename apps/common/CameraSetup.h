// SPDX-License-Identifier: MIT
#pragma once
// The camera settings every mode shares, so that a conservative culling mode draws exactly the
// pixels of the `osg` baseline: the walk's own projection with one fixed near/far for the whole
// walk, and no small-feature culling (it hides small visible objects).
#include <osgVis/core/scene/Walk.h>

#include <osg/Camera>
#include <osg/Matrixd>

namespace osgVis::apps
{
osg::Matrixd toOsgMatrix(const core::Mat4& m);
core::Mat4 toCoreMatrix(const osg::Matrixd& m);

osg::Matrixd walkViewMatrix(const core::WalkKey& key);

void applyWalkProjection(osg::Camera& camera, const core::WalkProjection& projection, double aspect);
} // namespace osgVis::apps
