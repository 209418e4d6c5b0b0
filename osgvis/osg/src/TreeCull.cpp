// SPDX-License-Identifier: MIT
// The cull traversal over the extraction's tree (TreeCull.h). What it stands in for is OSG 3.6's
// osgUtil::CullVisitor::apply(osg::Group&) and apply(osg::Transform&) (Geode and the kit's markers
// take the Group code there), entered through osg::Node::accept.
#include "TreeCull.h"

#include "ClusterCulling.h"

#include <osg/Transform>

#include <vector>

namespace osgVis
{
namespace
{
// Model-view matrices for the transforms the walk enters, reused once nothing else holds them (the
// render leaves of a frame still drawing do), as osg::CullStack reuses its own: warm, no allocation.
class MatrixPool
{
public:
    osg::RefMatrix* take(const osg::Matrixd& value)
    {
        for (std::size_t tried = 0; tried < _matrices.size(); ++tried)
        {
            osg::RefMatrix* matrix = _matrices[_next].get();
            _next = (_next + 1) % _matrices.size();
            if (matrix->referenceCount() == 1)
            {
                matrix->set(value);
                return matrix;
            }
        }
        _matrices.push_back(new osg::RefMatrix(value));
        return _matrices.back().get();
    }

private:
    std::vector<osg::ref_ptr<osg::RefMatrix>> _matrices;
    std::size_t _next = 0;
};

MatrixPool& threadMatrices()
{
    // note: one per cull thread; a matrix is handed out only while the pool alone holds it
    thread_local MatrixPool pool;
    return pool;
}
} // namespace

void TreeCull::cullChildren(std::uint32_t at, osg::Group& group)
{
    const CullTree::Node& node = _tree.nodes[at];
    const unsigned count = group.getNumChildren();
    for (unsigned i = 0; i < count; ++i)
    {
        osg::Node& child = *group.getChild(i);
        // note: a child list changed since the extraction (which the next cull's comparison finds)
        // or a child without objects is OSG's to traverse
        const std::uint32_t slot = count == node.childCount ? _tree.children[node.firstChild + i] : CullTree::None;
        if (slot == CullTree::None || _tree.nodes[slot].node != &child)
            _acceptor.accept(child, false);
        else
            cullChild(slot, child);
    }
}

void TreeCull::cullChild(std::uint32_t at, osg::Node& child)
{
    const CullTree::Node& node = _tree.nodes[at];
    const std::size_t visible = _tree.visibleCount(node, _visible);
    if (visible == 0 && node.closed)
        return; // draws nothing but its objects, none of them visible
    if (visible == node.idCount)
        _acceptor.accept(child, node.closed);
    else if (osg::Drawable* drawable = child.asDrawable())
        cullDrawable(node, *drawable);
    else if (!node.enterable)
        _acceptor.accept(child, false); // the callbacks below it decide
    else if (_cv.validNodeMask(child))
    {
        _cv.pushOntoNodePath(&child);
        cullGroup(at, *child.asGroup());
        _cv.popFromNodePath();
    }
}

void TreeCull::cullGroup(std::uint32_t at, osg::Group& group)
{
    if (_cv.isCulled(group))
        return;
    _cv.pushCurrentMask();
    osg::StateSet* state = group.getStateSet();
    if (state)
        _cv.pushStateSet(state);
    osg::Transform* transform = group.asTransform();
    if (transform)
    {
        osg::RefMatrix* matrix = threadMatrices().take(*_cv.getModelViewMatrix());
        transform->computeLocalToWorldMatrix(*matrix, &_cv);
        _cv.pushModelViewMatrix(matrix, transform->getReferenceFrame());
    }
    cullChildren(at, group);
    if (transform)
        _cv.popModelViewMatrix();
    if (state)
        _cv.popStateSet();
    _cv.popCurrentMask();
}

// A drawable with some of its objects hidden: a clustered instance with some clusters visible, or a
// hidden drawable with a cull callback of its own (run, as before, for what else it does).
void TreeCull::cullDrawable(const CullTree::Node& node, osg::Drawable& drawable)
{
    if (!_cv.validNodeMask(drawable))
        return;
    const core::ObjectId first = _tree.runs[node.firstRun].first;
    const ObjectRef& ref = _scene.refs[first];
    _cv.pushOntoNodePath(&drawable);
    const bool whole = ref.clusters ? drawClusteredWhole(_cv, drawable, *ref.clusters, first, _visible)
                                    : (culledByCallback(_cv, drawable, drawable.getCullCallback()), false);
    _cv.popFromNodePath();
    if (whole)
        _acceptor.accept(drawable, true);
}
} // namespace osgVis
