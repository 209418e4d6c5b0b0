// SPDX-License-Identifier: MIT
#pragma once
// Internal: how a cull traversal skips a paged node (osg::PagedLOD, osg::ProxyNode) whose
// placeholder the active culling contexts call hidden, so that OSG's own paging logic, which asks
// the DatabasePager for the node's tiles, never runs for it this frame (docs/paging.md).
#include <osg/Callback>
#include <osg/Group>
#include <osg/NodeVisitor>

namespace osgVis
{
// True when an active context of `visitor` on this thread knows `node`'s placeholder, reached
// through the visitor's current node path, and calls it hidden.
bool placeholderHiddenByActiveContext(osg::NodeVisitor& visitor, const osg::Node& node);

// A paged node's cull callback: returns without traversing when the placeholder is hidden;
// otherwise runs the callback that was installed before it, or traverses.
class PagedNodeCullCallback : public osg::Callback
{
public:
    PagedNodeCullCallback() = default;
    PagedNodeCullCallback(const PagedNodeCullCallback& other, const osg::CopyOp& copyop)
        : osg::Object(other, copyop), osg::Callback(other, copyop)
    {
    }
    META_Object(osgVis, PagedNodeCullCallback);

    bool run(osg::Object* object, osg::Object* data) override;

    // Installs the callback on `node` once, ahead of any cull callback already there.
    static void installOn(osg::Group& node);

protected:
    ~PagedNodeCullCallback() override = default;
};
} // namespace osgVis
