// SPDX-License-Identifier: MIT
#include "ThreadingModel.h"

#include <sstream>

namespace osgVis::apps
{
namespace
{
struct Named
{
    const char* name;
    osgViewer::ViewerBase::ThreadingModel model;
};
const Named Models[] = {
    {"SingleThreaded", osgViewer::ViewerBase::SingleThreaded},
    {"CullDrawThreadPerContext", osgViewer::ViewerBase::CullDrawThreadPerContext},
    {"DrawThreadPerContext", osgViewer::ViewerBase::DrawThreadPerContext},
    {"CullThreadPerCameraDrawThreadPerContext", osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext},
};
} // namespace

osgViewer::ViewerBase::ThreadingModel parseThreadingModel(const std::string& name)
{
    for (const Named& named : Models)
        if (name == named.name)
            return named.model;
    throw ThreadingNameError("unknown threading model '" + name + "' (use " + threadingModelChoices() + ")");
}

const char* threadingModelName(osgViewer::ViewerBase::ThreadingModel model)
{
    for (const Named& named : Models)
        if (model == named.model)
            return named.name;
    return "AutomaticSelection";
}

std::string threadingModelChoices()
{
    std::string choices;
    for (const Named& named : Models)
        choices += (choices.empty() ? "" : "|") + std::string(named.name);
    return choices;
}

std::vector<bool> parseOnOff(const std::string& flag, const std::string& text, bool list)
{
    std::vector<bool> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
    {
        if (item != "on" && item != "off")
            throw ThreadingNameError(flag + " expects on or off" + (list ? " (or a list such as on,off)" : "") +
                                     ", got '" + text + "'");
        values.push_back(item == "on");
    }
    if (values.empty() || (!list && values.size() != 1) || text.back() == ',')
        throw ThreadingNameError(flag + " expects on or off" + (list ? " (or a list such as on,off)" : "") +
                                 ", got '" + text + "'");
    return values;
}
} // namespace osgVis::apps
