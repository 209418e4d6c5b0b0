// SPDX-License-Identifier: MIT
#pragma once
// Internal: the visible set landing on the graph where the cull traversal stands (issue 46). Over the
// extraction's CullTree, a group's children are skipped whole when none of their objects is visible
// and they draw nothing else, let through to OSG whole when all are, and otherwise culled here, the
// way osgUtil::CullVisitor culls a plain group or transform (its own frustum test, state, matrix),
// child by child down to the drawables. No callback is consulted and no path compared on the way.
#include "CullTree.h"

#include <osgUtil/CullVisitor>

namespace osgVis
{
// Where the walk hands a child to OSG's own traversal: `decided` when every object below is visible
// and the subtree draws nothing else, so nothing below needs looking up.
class ChildAcceptor
{
public:
    virtual void accept(osg::Node& child, bool decided) = 0;

protected:
    ~ChildAcceptor() = default;
};

class TreeCull
{
public:
    TreeCull(osgUtil::CullVisitor& cv, const ExtractedScene& scene, const core::VisibleSet& visible,
             ChildAcceptor& acceptor)
        : _cv(cv), _scene(scene), _tree(*scene.cullTree), _visible(visible), _acceptor(acceptor)
    {
    }

    /// Culls the children of `group`, the tree's node `at`, which is on top of the visitor's node path
    /// with its own state and matrix pushed (the extraction root: at 0).
    void cullChildren(std::uint32_t at, osg::Group& group);
    /// Culls `group`, the tree's node `at`, on top of the visitor's node path, as
    /// osgUtil::CullVisitor::apply does a plain group or transform, its children by cullChildren.
    void cullGroup(std::uint32_t at, osg::Group& group);

private:
    void cullChild(std::uint32_t at, osg::Node& child);
    void cullDrawable(const CullTree::Node& node, osg::Drawable& drawable);

    osgUtil::CullVisitor& _cv;
    const ExtractedScene& _scene;
    const CullTree& _tree;
    const core::VisibleSet& _visible;
    ChildAcceptor& _acceptor;
};
} // namespace osgVis
