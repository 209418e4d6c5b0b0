// SPDX-License-Identifier: MIT
#include "ViewPictures.h"

#include <CameraSetup.h>
#include <TopDownMap.h>

#include <osgDB/WriteFile>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace osgVis::bench
{
std::vector<std::size_t> pictureViews(std::size_t views, unsigned count)
{
    std::vector<std::size_t> which;
    if (views == 0 || count == 0)
        return which;
    const std::size_t n = std::min<std::size_t>(views, count);
    for (std::size_t i = 0; i < n; ++i)
        which.push_back(n == 1 ? 0 : i * (views - 1) / (n - 1));
    return which;
}

ModeFrames captureModeFrames(BenchViewer& viewer, const std::vector<BenchView>& views,
                             const std::vector<std::size_t>& which, EmittedObjects& emittedObjects,
                             std::size_t objectCount, const std::function<void(std::size_t)>& beforeView)
{
    ModeFrames frames;
    for (const std::size_t v : which)
    {
        beforeView(v);
        frames.images.push_back(viewer.renderAndCapture(views[v]));
        core::VisibleSet emitted(objectCount);
        emittedObjects.collect(viewer.lastRenderStage(), views[v].view, emitted);
        frames.drawn.push_back(std::move(emitted));
    }
    return frames;
}

namespace
{
// Copies `source` into `target` with its lower-left corner at column x (both RGB, same height or less).
void blit(const osg::Image& source, osg::Image& target, int x)
{
    for (int row = 0; row < std::min(source.t(), target.t()); ++row)
        std::memcpy(target.data(x, row), source.data(0, row), std::size_t(3 * std::min(source.s(), target.s() - x)));
}
} // namespace

std::vector<std::string> writeSideBySide(const std::string& directory, const ModeFrames& baseline, const ModeFrames& mode,
                                         const core::Scene& scene, const std::vector<BenchView>& views,
                                         const std::vector<std::size_t>& which)
{
    std::vector<std::string> files;
    for (std::size_t i = 0; i < which.size() && i < baseline.images.size() && i < mode.images.size(); ++i)
    {
        const osg::Image* left = baseline.images[i].get();
        const osg::Image* middle = mode.images[i].get();
        if (!left || !middle)
            continue;
        const BenchView& view = views[which[i]];
        const osg::ref_ptr<osg::Image> map =
            apps::drawTopDownMap(scene, mode.drawn[i], apps::toCoreMatrix(view.view), apps::toCoreMatrix(view.projection),
                                 unsigned(middle->t()));
        const int gap = 4;
        osg::ref_ptr<osg::Image> picture = new osg::Image;
        picture->allocateImage(left->s() + middle->s() + map->s() + 2 * gap, middle->t(), 1, GL_RGB, GL_UNSIGNED_BYTE);
        std::memset(picture->data(), 255, picture->getTotalSizeInBytes());
        blit(*left, *picture, 0);
        blit(*middle, *picture, left->s() + gap);
        blit(*map, *picture, left->s() + middle->s() + 2 * gap);
        char name[32];
        std::snprintf(name, sizeof name, "view-%04zu.png", which[i]);
        const std::string path = (std::filesystem::path(directory) / name).string();
        if (!osgDB::writeImageFile(*picture, path))
            throw std::runtime_error("cannot write picture '" + path + "' (is OSG's png plugin installed?)");
        files.push_back(name);
    }
    return files;
}
} // namespace osgVis::bench
