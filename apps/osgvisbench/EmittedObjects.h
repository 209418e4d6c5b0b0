// SPDX-License-Identifier: MIT
#pragma once
// S(v): the objects a cull traversal actually handed to the draw, read back from the render
// stage's bins after the frame. Measuring what was emitted (rather than asking a module what it
// answered) holds every mode to the same standard, OSG's own culling and occlusion queries included.
#include <osgVis/SceneExtractor>
#include <osgVis/core/scene/VisibleSet.h>

#include <osgUtil/RenderStage>

#include <cstddef>
#include <functional>

namespace osgVis::bench
{
// Calls `visit` for every render leaf of `stage`: its nested bins, pre- and post-render stages too.
void forEachRenderLeaf(const osgUtil::RenderStage& stage, const std::function<void(const osgUtil::RenderLeaf&)>& visit);

class EmittedObjects
{
public:
    explicit EmittedObjects(const ExtractedScene& scene);

    // Adds to `emitted` every object with a render leaf in `stage` (and its nested bins and pre/post
    // stages). A leaf's drawable names the candidate objects; a drawable with several instances is
    // resolved by comparing the leaf's model matrix (modelview × view⁻¹) with each instance's world
    // matrix. Leaves that are no object (query boxes, overlays) are ignored.
    void collect(const osgUtil::RenderStage& stage, const osg::Matrixd& view, core::VisibleSet& emitted);

    // Leaves whose drawable is an object but whose matrix matched no instance of it (should stay 0).
    std::size_t unmatchedLeaves() const { return _unmatchedLeaves; }

private:
    void collectLeaf(const osgUtil::RenderLeaf& leaf, core::VisibleSet& emitted);

    const ExtractedScene& _scene;
    osg::Matrixd _inverseView;
    std::size_t _unmatchedLeaves = 0;
};
} // namespace osgVis::bench
