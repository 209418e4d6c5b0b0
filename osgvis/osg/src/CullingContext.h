// SPDX-License-Identifier: MIT
#pragma once
// Internal: how a VisibilityGroup tells the drawables below it, during its children's cull
// traversal, which of them are visible. A thread_local stack of active contexts (cull traversals
// of several cameras may run on several threads at once) plus a cull callback on each object
// drawable that consults it.
#include <osgVis/SceneExtractor>

#include <osgVis/core/scene/VisibleSet.h>

#include <osg/Callback>

namespace osgVis
{
struct CullingContext
{
    const osg::NodeVisitor* visitor = nullptr;
    const ExtractedScene* scene = nullptr;
    const core::VisibleSet* visible = nullptr;
    std::size_t rootDepth = 0; // index of the extraction root in the visitor's node path
    bool everything = false;   // every object is visible: no drawable needs looking up
};

// Pushes a context for the lifetime of the scope.
class ScopedCullingContext
{
public:
    explicit ScopedCullingContext(const CullingContext& context);
    ~ScopedCullingContext();
    ScopedCullingContext(const ScopedCullingContext&) = delete;
    ScopedCullingContext& operator=(const ScopedCullingContext&) = delete;
};

// True when an active context of `visitor` on this thread knows the drawable reached through the
// visitor's current node path and calls it hidden. Without an active context nothing is hidden.
// A clustered drawable (ClusterLayout) with some clusters visible is drawn here, by a ClusterDraw of
// its visible clusters, when `visitor` is a cull visitor: then too the drawable itself is culled.
bool hiddenByActiveContext(osg::NodeVisitor& visitor, osg::Drawable& drawable);

// Culls a drawable that an active context calls hidden; otherwise defers to the callback that was
// installed before it.
class VisibilityCullCallback : public osg::DrawableCullCallback
{
public:
    explicit VisibilityCullCallback(osg::Callback* chained = nullptr) : _chained(chained) {}
    VisibilityCullCallback(const VisibilityCullCallback& other, const osg::CopyOp& copyop)
        : osg::Object(other, copyop), osg::Callback(other, copyop), osg::DrawableCullCallback(other, copyop),
          _chained(other._chained)
    {
    }
    META_Object(osgVis, VisibilityCullCallback);

    using osg::DrawableCullCallback::cull;
    bool cull(osg::NodeVisitor* nv, osg::Drawable* drawable, osg::RenderInfo* renderInfo) const override;

    const osg::Callback* getChained() const { return _chained.get(); }

    // Installs the callback on `drawable` once, keeping any callback already there.
    static void installOn(osg::Drawable& drawable);

protected:
    ~VisibilityCullCallback() override = default;

    osg::ref_ptr<osg::Callback> _chained;
};
} // namespace osgVis
