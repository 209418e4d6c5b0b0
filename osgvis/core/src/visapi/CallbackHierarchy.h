// SPDX-License-Identifier: MIT
#pragma once
// A renderer's hierarchy handed over through osgVis/visapi.h (osgvis_hierarchy_desc) as the core's
// TraversalHierarchy. What a module's visitor throws never crosses the renderer's C code: the
// thunks catch it, stop the walk (every later enter answers "skip") and rethrow after it.
#include <osgVis/visapi.h>

#include <osgVis/core/scene/TraversalHierarchy.h>

namespace osgVis::core::capi
{
class CallbackHierarchy : public TraversalHierarchy
{
public:
    explicit CallbackHierarchy(const osgvis_hierarchy_desc& desc) : _desc(desc) {}
    ~CallbackHierarchy() override;
    CallbackHierarchy(const CallbackHierarchy&) = delete;
    CallbackHierarchy& operator=(const CallbackHierarchy&) = delete;

    HierarchyLayout layout() const override;
    std::uint32_t nodeCount() const override { return _desc.node_count; }
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override;

private:
    osgvis_hierarchy_desc _desc;
};
} // namespace osgVis::core::capi
