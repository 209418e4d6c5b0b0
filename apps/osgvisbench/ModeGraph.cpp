// SPDX-License-Identifier: MIT
#include "ModeGraph.h"

#include "ExactReplay.h"
#include "OcclusionQueryGraph.h"

#include <osgVis/VisibilityGroup>

namespace osgVis::bench
{
namespace
{
osg::ref_ptr<osg::Node> underVisibilityGroup(osg::Node& model, const std::string& chain, bool async = false,
                                             const core::AsyncOptions& asyncOptions = {}, bool backOff = false)
{
    osg::ref_ptr<VisibilityGroup> group = new VisibilityGroup;
    group->setModes(chain);
    if (backOff)
        group->setBackOff(core::BackOffOptions{});
    if (async)
        group->setAsync(true, asyncOptions);
    group->addChild(&model);
    return group;
}
} // namespace

osg::ref_ptr<osg::Node> buildModeGraph(const BenchMode& mode, osg::Node& model, const ExtractedScene& scene, bool async,
                                       const core::AsyncOptions& asyncOptions, bool backOff)
{
    switch (mode.kind)
    {
    case BenchMode::Kind::OsgDefault:
        return &model;
    case BenchMode::Kind::OcclusionQueries:
        return buildOcclusionQueryGraph(scene);
    case BenchMode::Kind::Exact:
        return underVisibilityGroup(model, ExactReplay::moduleName());
    case BenchMode::Kind::ModuleChain:
        break;
    }
    return underVisibilityGroup(model, mode.chain, async, asyncOptions, backOff);
}
} // namespace osgVis::bench
