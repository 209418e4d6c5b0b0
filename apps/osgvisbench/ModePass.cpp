// SPDX-License-Identifier: MIT
#include "ModePass.h"

#include "Progress.h"

namespace osgVis::bench
{
PassResult renderModePass(const std::string& label, BenchViewer& viewer, const std::vector<BenchView>& views,
                          EmittedObjects& emittedObjects, std::size_t objectCount,
                          const std::function<void(std::size_t)>& beforeView,
                          const std::function<void(std::size_t)>& afterView)
{
    PassResult pass;
    if (views.empty())
        return pass;
    beforeView(0);
    viewer.renderFrame(views.front());

    const std::size_t unmatchedBefore = emittedObjects.unmatchedLeaves();
    Progress progress(label, views.size());
    for (std::size_t v = 0; v < views.size(); ++v)
    {
        beforeView(v);
        const BenchViewer::FrameTiming timing = viewer.renderFrame(views[v]);
        pass.renderSeconds += timing.seconds;
        pass.cullMs.push_back(timing.cullMs);
        pass.chainMs.push_back(timing.chainMs);
        if (afterView)
            afterView(v);

        core::VisibleSet emitted(objectCount);
        emittedObjects.collect(viewer.lastRenderStage(), views[v].view, emitted);
        pass.emitted.push_back(std::move(emitted));
        progress.advance(v + 1);
    }
    pass.unmatchedLeaves = emittedObjects.unmatchedLeaves() - unmatchedBefore;
    return pass;
}
} // namespace osgVis::bench
