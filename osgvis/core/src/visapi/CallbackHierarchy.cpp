// SPDX-License-Identifier: MIT
#include "CallbackHierarchy.h"

#include <osgVis/core/capi/HierarchyNodes.h>

#include <exception>

namespace osgVis::core::capi
{
namespace
{
struct WalkState
{
    HierarchyVisitor& visitor;
    std::exception_ptr failure;
};

int enterThunk(void* state, const osgvis_hierarchy_node* node)
{
    WalkState& walk = *static_cast<WalkState*>(state);
    if (walk.failure || !node)
        return 0;
    try
    {
        return walk.visitor.enter(coreNode(*node)) ? 1 : 0;
    }
    catch (...)
    {
        walk.failure = std::current_exception();
        return 0;
    }
}

void leaveThunk(void* state, const osgvis_hierarchy_node* node)
{
    WalkState& walk = *static_cast<WalkState*>(state);
    if (walk.failure || !node)
        return;
    try
    {
        walk.visitor.leave(coreNode(*node));
    }
    catch (...)
    {
        walk.failure = std::current_exception();
    }
}
} // namespace

CallbackHierarchy::~CallbackHierarchy()
{
    if (_desc.destroy)
        _desc.destroy(_desc.user_data);
}

HierarchyLayout CallbackHierarchy::layout() const
{
    // Anything but an explicit "disjoint" is taken as the weaker promise.
    return _desc.layout == OSGVIS_HIERARCHY_DISJOINT ? HierarchyLayout::Disjoint : HierarchyLayout::Overlapping;
}

void CallbackHierarchy::traverse(const Vec3& eye, HierarchyVisitor& visitor) const
{
    WalkState walk{visitor, nullptr};
    const osgvis_hierarchy_visitor thunks{&walk, enterThunk, leaveThunk};
    const double e[3] = {eye.x, eye.y, eye.z};
    _desc.traverse(_desc.user_data, e, &thunks);
    if (walk.failure)
        std::rethrow_exception(walk.failure);
}
} // namespace osgVis::core::capi
