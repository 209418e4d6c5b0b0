// SPDX-License-Identifier: MIT
#include <osgVis/VisibilityGroup>

#include "CullingContext.h"
#include "PagedNodeCulling.h"

#include <osgUtil/CullVisitor>

#include <algorithm>

namespace osgVis
{
VisibilityGroup::VisibilityGroup() : _culler(new ViewCuller) {}

VisibilityGroup::VisibilityGroup(const std::string& modes) : _culler(new ViewCuller(modes)) {}

// note: a copy gets its own culler (its own extraction and per-view state), with the same modes and async.
VisibilityGroup::VisibilityGroup(const VisibilityGroup& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _culler(new ViewCuller(other.getModes()))
{
    _culler->setAsync(other.getAsync(), other.getAsyncOptions());
    _culler->setBackOff(other.getBackOffOptions());
    _culler->setExtractionOptions(other.getExtractionOptions());
    _culler->setPagingOptions(other.getPagingOptions());
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

void VisibilityGroup::installCullCallbacks(const ExtractedScene& scene)
{
    std::lock_guard<std::mutex> lock(_installMutex);
    if (_callbacksInstalledFor.get() == &scene)
        return;
    // note: drawables of an earlier extraction keep their callback; it finds them in no active
    // context's scene any more and hides nothing.
    for (const ObjectRef& ref : scene.refs)
        if (ref.drawable)
            VisibilityCullCallback::installOn(*ref.drawable);
        else if (ref.paged)
            PagedNodeCullCallback::installOn(*ref.paged);
    _callbacksInstalledFor = &scene;
}

namespace
{
// False only for a child with objects, none of them visible.
bool anyVisible(const ChildRange& range, const core::VisibleSet& visible)
{
    if (!range.ids.empty())
        return std::any_of(range.ids.begin(), range.ids.end(), [&](core::ObjectId id) { return visible.test(id); });
    if (range.first >= range.end)
        return true;
    for (core::ObjectId id = range.first; id < range.end; ++id)
        if (visible.test(id))
            return true;
    return false;
}
} // namespace

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
    installCullCallbacks(*result.scene);

    const osg::NodePath& path = cv->getNodePath();
    const ScopedCullingContext context({cv, result.scene.get(), result.visible, path.size() - 1, result.everything});
    const std::vector<ChildRange>& ranges = result.scene->childRanges;
    const bool rangesMatch = !result.everything && ranges.size() == _children.size();
    for (unsigned i = 0; i < _children.size(); ++i)
    {
        if (rangesMatch && ranges[i].closed && !anyVisible(ranges[i], *result.visible))
            continue; // a closed child draws nothing but its objects
        _children[i]->accept(nv);
    }
}
} // namespace osgVis
