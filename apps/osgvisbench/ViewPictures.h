// SPDX-License-Identifier: MIT
#pragma once
// Pictures for people (--report): a few views spread over the walk, each mode's frame read back
// after its timed pass, and side by side for two modes with a top-down map of what one drew.
#include "BenchView.h"
#include "BenchViewer.h"
#include "EmittedObjects.h"

#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <osg/Image>

#include <functional>
#include <string>
#include <vector>

namespace osgVis::bench
{
// `count` view indices spread evenly over `views` (all of them when there are fewer).
std::vector<std::size_t> pictureViews(std::size_t views, unsigned count);

struct ModeFrames
{
    std::vector<osg::ref_ptr<osg::Image>> images; // one per picture view
    std::vector<core::VisibleSet> drawn;          // what the cull emitted for that frame
};

// Renders each of `which` once more (untimed, after the mode's pass) and reads back its pixels and
// emitted objects. `beforeView(v)` runs first, as in the timed pass.
ModeFrames captureModeFrames(BenchViewer& viewer, const std::vector<BenchView>& views,
                             const std::vector<std::size_t>& which, EmittedObjects& emittedObjects,
                             std::size_t objectCount, const std::function<void(std::size_t)>& beforeView);

// Writes DIR/view-NNNN.png per picture view: the baseline's frame | the mode's frame | the top-down
// map of what the mode drew (apps::drawTopDownMap). Returns the file names (relative to DIR).
std::vector<std::string> writeSideBySide(const std::string& directory, const ModeFrames& baseline, const ModeFrames& mode,
                                         const core::Scene& scene, const std::vector<BenchView>& views,
                                         const std::vector<std::size_t>& which);
} // namespace osgVis::bench
