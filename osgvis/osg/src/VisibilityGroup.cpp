// SPDX-License-Identifier: MIT
#include <osgVis/VisibilityGroup>

#include <osgVis/core/api/ModuleSettings.h>

#include "CullingContext.h"
#include "PagedNodeCulling.h"
#include "TreeCull.h"

#include <osgUtil/CullVisitor>

namespace osgVis
{
VisibilityGroup::VisibilityGroup() : _culler(new ViewCuller) {}

VisibilityGroup::VisibilityGroup(const std::string& modes) : _culler(new ViewCuller(modes)) {}

// note: a copy gets its own culler (its own extraction and per-view state), with the same modes,
// async, options and baked data (shared: they are immutable).
VisibilityGroup::VisibilityGroup(const VisibilityGroup& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _culler(new ViewCuller(other.getModes()))
{
    _culler->setAsync(other.getAsync(), other.getAsyncOptions());
    _culler->setBackOff(other.getBackOffOptions());
    _culler->setExtractionOptions(other.getExtractionOptions());
    _culler->setPagingOptions(other.getPagingOptions());
    _culler->setBakedData(other.getBakedData());
}

void VisibilityGroup::setChain(const std::vector<core::StageSettings>& chain)
{
    _culler->setChain(chain);
}

std::vector<core::StageSettings> VisibilityGroup::getChain() const
{
    return _culler->getChain();
}

VisibilityGroup::~VisibilityGroup() = default;

bool VisibilityGroup::addChild(osg::Node* child)
{
    dirtyScene();
    return osg::Group::addChild(child);
}

bool VisibilityGroup::insertChild(unsigned index, osg::Node* child)
{
    dirtyScene();
    return osg::Group::insertChild(index, child);
}

bool VisibilityGroup::removeChildren(unsigned pos, unsigned numChildrenToRemove)
{
    dirtyScene();
    return osg::Group::removeChildren(pos, numChildrenToRemove);
}

bool VisibilityGroup::replaceChild(osg::Node* origChild, osg::Node* newChild)
{
    dirtyScene();
    return osg::Group::replaceChild(origChild, newChild);
}

bool VisibilityGroup::setChild(unsigned i, osg::Node* node)
{
    dirtyScene();
    return osg::Group::setChild(i, node);
}

namespace
{
// A drawable the tree walk cannot reach itself: below a node it does not enter (Switch, LOD, paged
// node, nested VisibilityGroup, a node with a cull callback), between the root and the drawable.
bool belowUnenterableNode(const osg::NodePath& path)
{
    for (std::size_t depth = 1; depth + 1 < path.size(); ++depth)
        if (!enterableNode(*path[depth]))
            return true;
    return false;
}

class GroupChildAcceptor : public ChildAcceptor
{
public:
    explicit GroupChildAcceptor(osg::NodeVisitor& nv) : _nv(nv) {}
    void accept(osg::Node& child, bool) override { child.accept(_nv); }

private:
    osg::NodeVisitor& _nv;
};
} // namespace

void VisibilityGroup::installCullCallbacks(const ExtractedScene& scene)
{
    std::lock_guard<std::mutex> lock(_installMutex);
    if (_callbacksInstalledFor.get() == &scene)
        return;
    // note: drawables of an earlier extraction keep their callback; it finds them in no active
    // context's scene any more and hides nothing.
    for (const ObjectRef& ref : scene.refs)
        if (ref.drawable && belowUnenterableNode(ref.path))
            VisibilityCullCallback::installOn(*ref.drawable);
        else if (ref.paged)
            PagedNodeCullCallback::installOn(*ref.paged);
    _callbacksInstalledFor = &scene;
}

void VisibilityGroup::traverse(osg::NodeVisitor& nv)
{
    auto* cv = nv.getVisitorType() == osg::NodeVisitor::CULL_VISITOR ? nv.asCullVisitor() : nullptr;
    if (!cv || _children.empty())
    {
        osg::Group::traverse(nv);
        return;
    }

    // The modelview at this group maps its local frame, the frame of the extracted bounds, to eye space.
    const ViewCuller::Result result =
        _culler->cull(*cv, *this, *cv->getModelViewMatrix(), *cv->getProjectionMatrix());
    if (result.everything)
    {
        osg::Group::traverse(nv);
        return;
    }
    installCullCallbacks(*result.scene);
    // The context serves only the callbacks below nodes the walk does not enter.
    const ScopedCullingContext context(
        {cv, result.scene.get(), result.visible, cv->getNodePath().size() - 1, result.everything});
    GroupChildAcceptor acceptor(nv);
    TreeCull(*cv, *result.scene, *result.visible, acceptor).cullChildren(0, *this);
}
} // namespace osgVis
