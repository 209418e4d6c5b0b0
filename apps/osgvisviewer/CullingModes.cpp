// SPDX-License-Identifier: MIT
#include "CullingModes.h"

#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/NodeVisitor>

#include <algorithm>
#include <iostream>

namespace osgVis::viewer
{
const char* const OsgMode = "osg";

std::vector<std::string> cyclingModes()
{
    std::vector<std::string> modes{OsgMode};
    for (const std::string& name : core::moduleNames())
        modes.push_back(name);
    return modes;
}

void checkMode(const std::string& mode)
{
    if (mode == OsgMode)
        return;
    try
    {
        core::createChain(mode);
    }
    catch (const core::ModuleLoadError&)
    {
        throw; // a plugin was found but is unusable: its message names the file and the reason
    }
    catch (const core::UnknownModeError&)
    {
        std::string list;
        for (const std::string& name : cyclingModes())
            list += (list.empty() ? "" : ", ") + name;
        throw core::UnknownModeError("unknown mode '" + mode + "'; modes: " + list +
                                     " (chain modules with +, e.g. frustum+octree; a plugin osgvis_module_<name>.so on OSGVIS_MODULE_PATH "
                                     "or in lib/osgvis-modules is a mode too)");
    }
}

class CullingModes::ApplyRequest : public osg::NodeCallback
{
public:
    explicit ApplyRequest(CullingModes& owner) : _owner(owner) {}

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        if (_owner._requested != _owner._mode)
            _owner.apply(_owner._requested);
        traverse(node, nv);
    }

private:
    CullingModes& _owner;
};

CullingModes::CullingModes(osg::Node* model, const std::string& mode, bool async)
    : _model(model), _slot(new osg::Group), _mode(OsgMode), _requested(OsgMode), _async(async)
{
    _slot->setName("osgvisviewer culling mode");
    _slot->addChild(_model.get());
    _slot->setUpdateCallback(new ApplyRequest(*this));
    _requested = mode;
    apply(mode);
}

std::string CullingModes::nextMode() const
{
    const std::vector<std::string> modes = cyclingModes();
    auto it = std::find(modes.begin(), modes.end(), _mode);
    if (it == modes.end() || ++it == modes.end())
        return modes.front();
    return *it;
}

void CullingModes::requestMode(const std::string& mode)
{
    _requested = mode;
}

void CullingModes::apply(const std::string& mode)
{
    try
    {
        if (mode != OsgMode)
        {
            if (!_group)
            {
                _group = new VisibilityGroup;
                _group->setName("osgvisviewer visibility");
                _group->setAsync(_async);
                // An application should never run slower for culling: do no harm is on here.
                _group->setBackOff(core::BackOffOptions{});
                _group->addChild(_model.get());
            }
            _group->setModes(mode);
        }
        osg::Node* wanted = mode == OsgMode ? _model.get() : static_cast<osg::Node*>(_group.get());
        if (_slot->getChild(0) != wanted)
            _slot->replaceChild(_slot->getChild(0), wanted);
        _mode = mode;
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisviewer: cannot switch to mode '" << mode << "': " << e.what() << "\n";
        _requested = _mode;
    }
}
} // namespace osgVis::viewer
