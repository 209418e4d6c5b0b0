// SPDX-License-Identifier: MIT
#include "PagedNodeCulling.h"

#include "CullingContext.h"

namespace osgVis
{
bool PagedNodeCullCallback::run(osg::Object* object, osg::Object* data)
{
    osg::Node* node = object ? object->asNode() : nullptr;
    osg::NodeVisitor* nv = data ? data->asNodeVisitor() : nullptr;
    if (node && nv && placeholderHiddenByActiveContext(*nv, *node))
        return true; // not traversed: no tile of this node is requested, none is drawn
    return traverse(object, data);
}

void PagedNodeCullCallback::installOn(osg::Group& node)
{
    osg::Callback* current = node.getCullCallback();
    for (osg::Callback* c = current; c; c = c->getNestedCallback())
        if (dynamic_cast<PagedNodeCullCallback*>(c))
            return;
    osg::ref_ptr<PagedNodeCullCallback> callback = new PagedNodeCullCallback;
    callback->setNestedCallback(current);
    node.setCullCallback(callback.get());
}
} // namespace osgVis
