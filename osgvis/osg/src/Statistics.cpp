// SPDX-License-Identifier: MIT
#include <osgVis/Statistics>

#include <osg/Camera>
#include <osgViewer/View>
#include <osgViewer/ViewerBase>
#include <osgViewer/ViewerEventHandlers>

namespace osgVis
{
namespace
{
void write(osg::Stats& stats, unsigned frameNumber, const CullStatistics& figures)
{
    stats.setAttribute(frameNumber, STATS_OBJECTS, figures.objects);
    stats.setAttribute(frameNumber, STATS_VISIBLE, figures.visible);
    stats.setAttribute(frameNumber, STATS_TRIANGLES, static_cast<double>(figures.trianglesVisible));
    stats.setAttribute(frameNumber, STATS_CULL_MS, figures.cullMs);
    if (figures.clustered)
        stats.setAttribute(frameNumber, STATS_CLUSTERS, figures.clustersVisible);
    if (figures.pagedNodes != 0)
        stats.setAttribute(frameNumber, STATS_PAGED_SKIPPED, figures.pagedNodesSkipped);
    if (figures.async)
        stats.setAttribute(frameNumber, STATS_ASYNC_FALLBACK, figures.asyncFallback ? 1.0 : 0.0);
    if (figures.backOff)
        stats.setAttribute(frameNumber, STATS_BACKED_OFF, figures.backedOff ? 1.0 : 0.0);
}
} // namespace

void recordStatistics(osg::Camera* camera, unsigned frameNumber, const CullStatistics& figures)
{
    if (!camera)
        return;
    if (osg::Stats* stats = camera->getStats())
        write(*stats, frameNumber, figures);
    // note: StatsHandler's user lines read the viewer's stats, not the camera's.
    if (auto* view = dynamic_cast<osgViewer::View*>(camera->getView()))
        if (osgViewer::ViewerBase* viewer = view->getViewerBase())
            if (osg::Stats* stats = viewer->getViewerStats())
                write(*stats, frameNumber, figures);
}

void addStatsLines(osgViewer::StatsHandler& handler)
{
    const osg::Vec4 text(0.6f, 1.0f, 0.6f, 1.0f), bar(0.6f, 1.0f, 0.6f, 0.5f);
    handler.addUserStatsLine("osgVis objects", text, bar, STATS_OBJECTS, 1.0f, false, false, "", "", 0.0f);
    handler.addUserStatsLine("osgVis visible", text, bar, STATS_VISIBLE, 1.0f, false, false, "", "", 0.0f);
    handler.addUserStatsLine("osgVis triangles", text, bar, STATS_TRIANGLES, 1.0f, false, false, "", "", 0.0f);
    handler.addUserStatsLine("osgVis clusters drawn", text, bar, STATS_CLUSTERS, 1.0f, false, false, "", "", 0.0f);
    // Paged nodes found hidden, whose tiles the pager is therefore not asked for.
    handler.addUserStatsLine("osgVis paged skipped", text, bar, STATS_PAGED_SKIPPED, 1.0f, false, false, "", "", 0.0f);
    // The cull thread's time in osgVis (with async on, only the frustum intersection of a region).
    handler.addUserStatsLine("osgVis cull ms", text, bar, STATS_CULL_MS, 1.0f, true, false, "", "", 10.0f);
    handler.addUserStatsLine("osgVis async fallback", text, bar, STATS_ASYNC_FALLBACK, 1.0f, true, false, "", "",
                             1.0f);
    // 1 while the view's culling costs more than it saves and every object goes to OSG's own culling.
    handler.addUserStatsLine("osgVis backed off", text, bar, STATS_BACKED_OFF, 1.0f, true, false, "", "", 1.0f);
}
} // namespace osgVis
