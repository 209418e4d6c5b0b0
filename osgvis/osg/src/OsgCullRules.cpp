// SPDX-License-Identifier: MIT
// OSG's rules where its cull traversal stands (OsgCullRules.h). The near/far bounds follow OSG 3.6's
// osg::clampProjectionMatrix (include/osg/CullSettings): a perspective near plane is the nearest drawn
// bound's depth pulled in by 0.98, but never nearer than far × nearFarRatio, where far is the
// farthest drawn bound's depth; an orthographic one lies at least one unit beyond both.
#include "OsgCullRules.h"

#include "OccluderEligibility.h"

#include <osg/Camera>
#include <osg/FrameBufferObject>
#include <osg/GraphicsContext>
#include <osgUtil/RenderStage>
#include <osgUtil/StateGraph>

#include <algorithm>
#include <cmath>
#include <limits>

namespace osgVis
{
namespace
{
// The state sets the traversal has pushed down to here, outermost first: the camera's, the global
// ones a SceneView pushes, and those of every node above.
void stateSetsAbove(osgUtil::CullVisitor& cv, std::vector<const osg::StateSet*>& out)
{
    out.clear();
    for (const osgUtil::StateGraph* graph = cv.getCurrentStateGraph(); graph; graph = graph->_parent)
        if (graph->getStateSet())
            out.push_back(graph->getStateSet());
    std::reverse(out.begin(), out.end());
}

// Farthest distance from the eye that anything this camera draws can lie at: OSG's computed far plane
// (before its 2 % push) is no farther. 0 for a bare visitor, which draws nothing but the root.
double farthestDrawn(osgUtil::CullVisitor& cv)
{
    osgUtil::RenderStage* stage = cv.getCurrentRenderBin() ? cv.getCurrentRenderStage() : nullptr;
    const osg::Camera* camera = stage ? stage->getCamera() : nullptr;
    const osg::RefMatrix* view = stage ? stage->getInitialViewMatrix() : nullptr;
    if (!camera || !view)
        return 0.0;
    double farthest = 0.0;
    for (unsigned i = 0; i < camera->getNumChildren(); ++i)
    {
        const osg::BoundingSphere& sphere = camera->getChild(i)->getBound();
        if (sphere.valid())
            farthest = std::max(farthest, (osg::Vec3d(sphere.center()) * *view).length() + sphere.radius());
    }
    return farthest;
}

// Eye-space depths (along -z) of `bounds`' corners.
std::pair<double, double> depthRange(const core::Aabb& bounds, const osg::Matrixd& modelView)
{
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
    for (int corner = 0; corner < 8; ++corner)
    {
        const osg::Vec3d p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                           (corner & 4) ? bounds.max.z : bounds.min.z);
        const double depth = -(p * modelView).z();
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    return {nearest, farthest};
}
} // namespace

const char* whyLeftToOsg(osgUtil::CullVisitor& cv, const ExtractedScene& scene,
                         std::vector<const osg::StateSet*>& stateSets)
{
    const osg::Node::NodeMask traversal = cv.getTraversalMask() | cv.getNodeMaskOverride();
    for (const osg::Node::NodeMask mask : scene.occluderMasks)
        if ((mask & traversal) == 0)
            return "the traversal mask leaves out an occluder";
    stateSetsAbove(cv, stateSets);
    const InheritedStateRules rules = inheritedStateRules(stateSets);
    if (rules.hidesNothingBecause)
        return rules.hidesNothingBecause;
    if (!rules.occludable)
        return "drawn without a depth test nearer geometry can fail";
    return nullptr;
}

std::uint32_t depthBitsOf(const osg::Camera* camera)
{
    if (!camera)
        return 24;
    const osg::GraphicsContext* gc = camera->getGraphicsContext();
    const osg::Camera::BufferAttachmentMap& attachments = camera->getBufferAttachmentMap();
    if (camera->getRenderTargetImplementation() == osg::Camera::FRAME_BUFFER || attachments.empty())
    {
        // note: without a context of OSG's (a SceneView drawn into someone else's), what OSG would ask one for
        const osg::GraphicsContext::Traits* traits = gc ? gc->getTraits() : nullptr;
        const unsigned bits = traits ? traits->depth : osg::GraphicsContext::Traits().depth;
        return bits > 0 ? bits : 16u;
    }
    for (osg::Camera::BufferComponent component : {osg::Camera::DEPTH_BUFFER, osg::Camera::PACKED_DEPTH_STENCIL_BUFFER})
    {
        const auto found = attachments.find(component);
        if (found == attachments.end())
            continue;
        switch (found->second._internalFormat)
        {
        case GL_DEPTH_COMPONENT24:
        case GL_DEPTH24_STENCIL8_EXT:
            return 24;
        case GL_DEPTH_COMPONENT32:
            return 32;
        default:
            return 16;
        }
    }
    return 16;
}

ModulesProjection projectionForModules(osgUtil::CullVisitor& cv, const osg::Matrixd& modelView,
                                       const core::Aabb& bounds, osg::Matrixd& projection)
{
    if (cv.getComputeNearFarMode() == osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR)
        return ModulesProjection::AsDrawn;
    if (cv.getClampProjectionMatrixCallback() || bounds.empty())
        return ModulesProjection::Unknown;
    const auto [nearest, farthest] = depthRange(bounds, modelView);
    double left, right, bottom, top, zNear, zFar;
    if (projection.getFrustum(left, right, bottom, top, zNear, zFar))
    {
        const double farPlane = std::max(farthest, 0.0) * 1.05 + 1e-6;
        const double nearPlane = std::max(farthestDrawn(cv), farPlane) * cv.getNearFarRatio();
        if (!(nearPlane > 0.0) || !std::isfinite(nearPlane) || nearPlane >= farPlane || !(zNear > 0.0))
            return ModulesProjection::Unknown;
        const double scale = nearPlane / zNear;
        projection.makeFrustum(left * scale, right * scale, bottom * scale, top * scale, nearPlane, farPlane);
        return ModulesProjection::Adjusted;
    }
    if (projection.getOrtho(left, right, bottom, top, zNear, zFar))
    {
        const double margin = 1.0 + 0.02 * (farthest - nearest);
        projection.makeOrtho(left, right, bottom, top, nearest - margin, farthest + margin);
        return ModulesProjection::AsDrawn; // nothing drawn lies outside these planes
    }
    return ModulesProjection::Unknown;
}
} // namespace osgVis
