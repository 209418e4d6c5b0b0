// SPDX-License-Identifier: MIT
#pragma once
// The threading model and async options both apps take (--threading, --async): names as OSG
// spells its enum, on/off lists.
#include <osgViewer/ViewerBase>

#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::apps
{
struct ThreadingNameError : std::invalid_argument
{
    using std::invalid_argument::invalid_argument;
};

// "SingleThreaded", "CullDrawThreadPerContext", "DrawThreadPerContext" or
// "CullThreadPerCameraDrawThreadPerContext"; throws ThreadingNameError listing them.
osgViewer::ViewerBase::ThreadingModel parseThreadingModel(const std::string& name);
const char* threadingModelName(osgViewer::ViewerBase::ThreadingModel model);
// "SingleThreaded|CullDrawThreadPerContext|…" for usage texts.
std::string threadingModelChoices();
// "on" / "off" (also a comma list "on,off" when `list`); throws ThreadingNameError.
std::vector<bool> parseOnOff(const std::string& flag, const std::string& text, bool list);
} // namespace osgVis::apps
