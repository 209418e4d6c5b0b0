// SPDX-License-Identifier: MIT
#pragma once
// Internal: what OSG's own cull traversal decides where it reaches the extraction root, read from the
// cull visitor, so that the kit removes only what its modules prove hidden behind geometry this camera
// draws, with the state it draws it with (docs/architecture.md, "OSG's rules and the kit's"):
//   - the state the traversal brings (the camera's and every state set above the root): where it lets
//     nothing occlude (wire-frame, no depth write, ...) or lets nothing fail its depth test, no
//     occlusion holds, and the view is left to OSG;
//   - the traversal mask: where it leaves out a node above an occluder, that occluder is not drawn,
//     and the view is left to OSG;
//   - near and far computed by OSG (osgViewer's default): the draw's planes are not the projection's,
//     so the modules get a projection that culls on neither (near/far below).
#include <osgVis/SceneExtractor>

#include <osgVis/core/geometry/Aabb.h>

#include <osg/Matrixd>
#include <osgUtil/CullVisitor>

#include <cstdint>
#include <vector>

namespace osgVis
{
// Why OSG alone must cull this view (its state or masks break what the extraction assumed), or null.
// `stateSets` is scratch space (reused, so a warm cull allocates nothing).
const char* whyLeftToOsg(osgUtil::CullVisitor& cv, const ExtractedScene& scene,
                         std::vector<const osg::StateSet*>& stateSets);

// The projection the modules cull with. With near and far computed by OSG (and no clamping callback of
// the application's), the same sides, a far plane beyond every object of `bounds` (the root's frame,
// mapped to eye space by `modelView`) and a near plane no nearer than OSG's clamping can choose, so
// that no occluder counts where the draw clips it: Adjusted, and objects nearer than that near plane
// must be kept (they may be drawn in front of it). Unknown where the projection is of a kind this
// cannot adjust (the view is then left to OSG).
enum class ModulesProjection
{
    AsDrawn,
    Adjusted,
    Unknown
};
ModulesProjection projectionForModules(osgUtil::CullVisitor& cv, const osg::Matrixd& modelView,
                                       const core::Aabb& bounds, osg::Matrixd& projection);

// Bits of the depth buffer `camera` draws into (core::View::depthBits, the depth-tie margins' unit): its
// context's where it draws to the frame buffer (what OSG asks a context for where it has none of
// OSG's), a stated depth attachment's where it draws to a texture or render buffer, and 16 where
// neither says (so the margins stay wide enough); 24 without a camera (a bare visitor draws nothing).
std::uint32_t depthBitsOf(const osg::Camera* camera);
} // namespace osgVis
