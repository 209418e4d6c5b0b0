// SPDX-License-Identifier: MIT
#pragma once
// Test helper: every drawable instance of a graph with its world-space bounds, found by a traversal
// of its own (independent of the generator's model).
#include <osg/Drawable>
#include <osg/NodeVisitor>
#include <osg/Transform>

#include <string>
#include <vector>

namespace osgVis::gen::test
{
struct DrawableInstance
{
    const osg::Drawable* drawable = nullptr;
    std::string name;
    osg::BoundingBox worldBounds;
};

class DrawableCollector : public osg::NodeVisitor
{
public:
    DrawableCollector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Drawable& drawable) override
    {
        const osg::Matrix world = osg::computeLocalToWorld(getNodePath());
        const osg::BoundingBox local = drawable.getBoundingBox();
        DrawableInstance instance{&drawable, drawable.getName(), {}};
        for (int i = 0; i < 8; ++i)
            instance.worldBounds.expandBy(local.corner(unsigned(i)) * world);
        instances.push_back(instance);
    }

    std::vector<DrawableInstance> instances;
};

inline std::vector<DrawableInstance> drawablesOf(osg::Node& root)
{
    DrawableCollector collector;
    root.accept(collector);
    return collector.instances;
}
} // namespace osgVis::gen::test
