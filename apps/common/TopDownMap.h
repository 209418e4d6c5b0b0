// SPDX-License-Identifier: MIT
#pragma once
// A plan view of what one view drew, as an image (no GL): the footprints of the scene's objects
// seen from above, green where drawn, red where culled inside the view frustum (occlusion culling
// at work), grey where outside it (frustum culling), smaller footprints over larger; the eye as a
// white dot and the frustum's outline on the ground in yellow. For pictures beside a frame.
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <osg/Image>

namespace osgVis::apps
{
struct TopDownMapColours
{
    unsigned char background[3] = {24, 24, 32};
    unsigned char drawn[3] = {60, 200, 90};
    unsigned char culled[3] = {215, 50, 45};
    unsigned char outside[3] = {90, 90, 96};
    unsigned char frustum[3] = {250, 220, 60};
    unsigned char eye[3] = {255, 255, 255};
};

// `view` and `projection` in the core's convention (column vectors); the map covers the scene's
// bounds (x right, y up), `height` pixels tall, as wide as the bounds' aspect gives (at least 1).
// Returns an RGB image, bottom row first (OSG's convention).
osg::ref_ptr<osg::Image> drawTopDownMap(const core::Scene& scene, const core::VisibleSet& drawn, const core::Mat4& view,
                                        const core::Mat4& projection, unsigned height,
                                        const TopDownMapColours& colours = {});
} // namespace osgVis::apps
