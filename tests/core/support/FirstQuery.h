// SPDX-License-Identifier: MIT
#pragma once
// A fresh module's first query: what it keeps of a scene in one view, and its statistics (the
// budget tests compare such answers across budgets).
#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/scene/VisibleSet.h>

namespace osgVis::test
{
template <class Module> struct FirstQuery
{
    core::VisibleSet visible;
    typename Module::Statistics stats;
};

template <class Module, class Options>
FirstQuery<Module> firstQuery(const core::Scene& scene, const core::View& view, const Options& options)
{
    Module module(options);
    module.setScene(scene);
    FirstQuery<Module> answer{core::VisibleSet(scene.objects.size(), true), {}};
    module.cull(view, answer.visible);
    answer.stats = module.lastStatistics();
    return answer;
}
} // namespace osgVis::test
