// SPDX-License-Identifier: MIT
#include "ProgressiveTable.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/scene/View.h>

#include <iostream>

namespace osgVis::bench
{
namespace
{
struct Stage
{
    const char* name;
    const char* module; // registered CellPortalModule mode
};
// The paper's order. Nesting: cell-to-cell ⊇ cell-to-object ⊇ eye-to-object and
// cell-to-cell ⊇ eye-to-cell ⊇ eye-to-object; cell-to-object and eye-to-cell are not nested.
constexpr Stage stages[] = {{"cell-to-cell", "cellportal-cells"},
                            {"cell-to-object", "cellportal-pvs"},
                            {"eye-to-cell", "cellportal-eyecells"},
                            {"eye-to-object", "cellportal"}};

ProgressiveRow runStage(const char* name, core::VisibilityModule& module, const core::Scene& scene,
                        const std::vector<core::View>& views)
{
    double keptTriangles = 0.0, keptObjects = 0.0;
    core::VisibleSet visible;
    for (const core::View& view : views)
    {
        visible.reset(scene.objects.size(), true);
        module.cull(view, visible);
        for (core::ObjectId id : visible.ids())
            keptTriangles += scene.objects[id].triangleCount;
        keptObjects += double(visible.count());
    }
    const double viewCount = double(views.size());
    ProgressiveRow row;
    row.stage = name;
    row.drawnFraction = keptTriangles / (viewCount * double(scene.totalTriangles()));
    row.objectsFraction = keptObjects / (viewCount * double(scene.objects.size()));
    return row;
}
} // namespace

bool wantsProgressiveTable(const std::vector<BenchMode>& modes)
{
    for (const BenchMode& mode : modes)
        if (mode.kind == BenchMode::Kind::ModuleChain && mode.chain.find("cellportal") != std::string::npos)
            return true;
    return false;
}

std::vector<ProgressiveRow> runProgressiveTable(const core::Scene& scene, const core::Walk& walk)
{
    if (walk.keys.empty() || scene.objects.empty() || scene.totalTriangles() == 0)
        return {};
    const core::Mat4 projection = walk.projection.matrix(walk.aspect());
    std::vector<core::View> views;
    views.reserve(walk.keys.size());
    for (const core::WalkKey& key : walk.keys)
        views.push_back(core::makeView(key.viewMatrix(), projection, key.time, walk.width, walk.height));

    std::cerr << "progressive table: cell-portal stages over " << views.size() << " views (cull only)" << std::endl;
    std::vector<ProgressiveRow> rows{{"entire model", 1.0, 1.0}};
    for (const Stage& stage : stages)
    {
        const std::unique_ptr<core::VisibilityModule> module = core::createModule(stage.module);
        module->setScene(scene);
        rows.push_back(runStage(stage.name, *module, scene, views));
    }
    return rows;
}
} // namespace osgVis::bench
