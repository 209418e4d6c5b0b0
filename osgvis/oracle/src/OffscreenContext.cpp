// SPDX-License-Identifier: MIT
#include <osgVis/oracle/OffscreenContext.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace osgVis::oracle
{
osg::ref_ptr<osg::GraphicsContext> createOffscreenContext(unsigned width, unsigned height, bool doubleBuffered)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->setUndefinedScreenDetailsToDefaultScreen();
    traits->x = 0;
    traits->y = 0;
    traits->width = int(width);
    traits->height = int(height);
    traits->red = traits->green = traits->blue = 8;
    traits->alpha = 0; // note: with alpha, Xvfb answers the viewer's pbuffer swap with BadMatch
    traits->depth = 24;
    traits->samples = 0;
    traits->sampleBuffers = 0;
    traits->pbuffer = true;
    traits->doubleBuffer = doubleBuffered;
    traits->windowDecoration = false;
    traits->sharedContext = nullptr;

    constexpr int Attempts = 20;
    for (int attempt = 0; attempt < Attempts; ++attempt)
    {
        osg::ref_ptr<osg::GraphicsContext> context = osg::GraphicsContext::createGraphicsContext(traits.get());
        if (context && context->valid())
            return context;
        std::this_thread::sleep_for(std::chrono::milliseconds(10 * (attempt + 1)));
    }
    throw std::runtime_error("osgVis oracle: cannot create a pbuffer OpenGL context on DISPLAY '" +
                             traits->displayName() + "' (no display? run under xvfb-run)");
}
} // namespace osgVis::oracle
