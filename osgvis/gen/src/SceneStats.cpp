// SPDX-License-Identifier: MIT
#include <osgVis/gen/SceneStats.h>

#include <osg/Drawable>
#include <osg/NodeVisitor>
#include <osg/TriangleFunctor>

namespace osgVis::gen
{
namespace
{
struct TriangleCounter
{
    std::uint64_t count = 0;
    void operator()(const osg::Vec3&, const osg::Vec3&, const osg::Vec3&) { ++count; }
};

class StatsVisitor : public osg::NodeVisitor
{
public:
    StatsVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) { setNodeMaskOverride(~0u); }

    void apply(osg::Drawable& drawable) override
    {
        osg::TriangleFunctor<TriangleCounter> counter;
        drawable.accept(counter);
        ++stats.objects;
        stats.triangles += counter.count;
    }

    SceneStats stats;
};
} // namespace

SceneStats sceneStats(osg::Node& root)
{
    StatsVisitor visitor;
    root.accept(visitor);
    return visitor.stats;
}
} // namespace osgVis::gen
