// SPDX-License-Identifier: MIT
#include "CullingContext.h"

#include "ClusterCulling.h"
#include "PagedNodeCulling.h"

#include <osgUtil/CullVisitor>

#include <vector>

namespace osgVis
{
namespace
{
std::vector<CullingContext>& activeContexts()
{
    thread_local std::vector<CullingContext> contexts;
    return contexts;
}
} // namespace

ScopedCullingContext::ScopedCullingContext(const CullingContext& context)
{
    activeContexts().push_back(context);
}

ScopedCullingContext::~ScopedCullingContext()
{
    activeContexts().pop_back();
}

bool hiddenByActiveContext(osg::NodeVisitor& visitor, osg::Drawable& drawable)
{
    const osg::NodePath& path = visitor.getNodePath();
    // note: nested VisibilityGroups each hold a context; any one of them may hide the drawable. Of
    // clusters, the innermost context that knows them decides (the last on the stack).
    const CullingContext* clusters = nullptr;
    core::ObjectId firstCluster = core::InvalidObject;
    for (const CullingContext& context : activeContexts())
    {
        if (context.everything || context.visitor != &visitor || context.rootDepth >= path.size())
            continue;
        const core::ObjectId id = context.scene->find(&drawable, path, context.rootDepth);
        if (id == core::InvalidObject)
            continue;
        if (context.scene->refs[id].clusters)
        {
            clusters = &context;
            firstCluster = id;
        }
        else if (!context.visible->test(id))
            return true;
    }
    osgUtil::CullVisitor* cv = visitor.asCullVisitor();
    if (!clusters || !cv)
        return false;
    const ClusterLayout& layout = *clusters->scene->refs[firstCluster].clusters;
    return cullClusters(*cv, drawable, layout, firstCluster, *clusters->visible) != ClusterCull::Whole;
}

bool placeholderHiddenByActiveContext(osg::NodeVisitor& visitor, const osg::Node& node)
{
    const osg::NodePath& path = visitor.getNodePath();
    for (const CullingContext& context : activeContexts())
    {
        if (context.everything || context.visitor != &visitor || context.rootDepth >= path.size())
            continue;
        const core::ObjectId id = context.scene->find(&node, path, context.rootDepth);
        if (id != core::InvalidObject && !context.visible->test(id))
            return true;
    }
    return false;
}

bool VisibilityCullCallback::cull(osg::NodeVisitor* nv, osg::Drawable* drawable, osg::RenderInfo*) const
{
    // Mirrors osgUtil::CullVisitor::apply(osg::Drawable&) for the callback we replaced.
    if (nv && drawable && culledByCallback(*nv, *drawable, _chained.get()))
        return true;
    return nv && drawable && hiddenByActiveContext(*nv, *drawable);
}

void VisibilityCullCallback::installOn(osg::Drawable& drawable)
{
    osg::Callback* current = drawable.getCullCallback();
    if (dynamic_cast<VisibilityCullCallback*>(current))
        return;
    drawable.setCullCallback(new VisibilityCullCallback(current));
}
} // namespace osgVis
