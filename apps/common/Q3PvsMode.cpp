// SPDX-License-Identifier: MIT
#include "Q3PvsMode.h"

#include <osgVis/Q3Bsp>

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/module/BakedDataStore.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <osg/Geode>

#include <memory>

namespace osgVis::apps
{
namespace
{
struct LevelCells
{
    Q3Bsp bsp;
    std::vector<std::vector<int>> objectClusters; // per object; empty: always kept
};

class Q3PvsModule : public core::VisibilityModule
{
public:
    const char* name() const override { return "q3-pvs-approx"; }
    // q3map2's claim, not ours: on OpenArena's ce1m7 the oracle sees objects it leaves out.
    bool approximate() const override { return true; }

    void setScene(const core::Scene& scene) override
    {
        _cells = core::BakedDataStore<LevelCells>::instance().find(core::sceneFingerprint(scene));
        _cachedCluster = -2;
    }

    void cull(const core::View& view, core::VisibleSet& visible) override
    {
        if (!_cells || view.orthographic || _cells->objectClusters.size() != visible.capacity())
            return;
        const int eyeCluster = _cells->bsp.clusterAt(view.eye);
        if (eyeCluster < 0)
            return; // solid space or outside: q3map2's PVS says nothing there
        if (eyeCluster != _cachedCluster)
        {
            _keep.assign(visible.capacity(), 0);
            for (std::size_t id = 0; id < _keep.size(); ++id)
            {
                const std::vector<int>& clusters = _cells->objectClusters[id];
                bool seen = clusters.empty();
                for (std::size_t k = 0; k < clusters.size() && !seen; ++k)
                    seen = _cells->bsp.clusterSees(eyeCluster, clusters[k]);
                _keep[id] = seen;
            }
            _cachedCluster = eyeCluster;
        }
        for (std::size_t id = 0; id < _keep.size(); ++id)
            if (!_keep[id] && visible.test(core::ObjectId(id)))
                visible.clear(core::ObjectId(id));
    }

private:
    std::shared_ptr<const LevelCells> _cells;
    std::vector<std::uint8_t> _keep; // for _cachedCluster
    int _cachedCluster = -2;
};

} // namespace

void registerQ3PvsMode()
{
    static std::once_flag once;
    std::call_once(once, [] { core::registerModule("q3-pvs-approx", [] { return std::make_unique<Q3PvsModule>(); }); });
}

std::string attachQ3Pvs(const std::string& path, osg::Node& model, const ExtractedScene& objects)
{
    try
    {
        auto cells = std::make_shared<LevelCells>(LevelCells{Q3Bsp::read(path), {}});
        const std::vector<int>& drawableFaces = cells->bsp.drawableFaces();
        osg::Geode* geode = cells->bsp.pluginGeode(model);
        if (!geode)
            return "no q3-pvs-approx: no geode of " + std::to_string(drawableFaces.size()) +
                   " drawables (one per face piece of the file), so the faces cannot be told apart";
        cells->objectClusters.assign(objects.scene.objects.size(), {});
        std::size_t placed = 0;
        for (std::size_t k = 0; k < drawableFaces.size(); ++k)
            for (core::ObjectId id : objects.idsOf(geode->getDrawable(unsigned(k))))
                if (id < cells->objectClusters.size())
                {
                    cells->objectClusters[id] = cells->bsp.faceClusters()[std::size_t(drawableFaces[k])];
                    placed += cells->objectClusters[id].empty() ? 0 : 1;
                }
        const std::string summary = "q3-pvs-approx: " + std::to_string(cells->bsp.clusterCount()) + " clusters" +
                                    (cells->bsp.hasVisibility() ? "" : " (no visdata: every cluster sees all)") +
                                    ", " + std::to_string(placed) + " of " +
                                    std::to_string(objects.scene.objects.size()) + " objects in their leaves";
        core::BakedDataStore<LevelCells>::instance().put(core::sceneFingerprint(objects.scene), std::move(cells));
        return summary;
    }
    catch (const std::exception& e)
    {
        return std::string("no q3-pvs-approx: ") + e.what();
    }
}
} // namespace osgVis::apps
