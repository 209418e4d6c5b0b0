// SPDX-License-Identifier: MIT
#pragma once
// The culling modes the viewer switches between: `osg` (the plain graph under OSG's own culling)
// and every module chain of the core registry, applied by placing the model under an
// osgVis::VisibilityGroup. A mode change requested from an event handler takes effect in the next
// update traversal, where OSG allows scene-structure changes.
#include <osgVis/VisibilityGroup>

#include <osg/Group>

#include <string>
#include <vector>

namespace osgVis::viewer
{
// The name of the baseline mode: no osgVis node in the graph.
extern const char* const OsgMode;

// "osg" followed by every registered module, in the order key `m` cycles through them.
std::vector<std::string> cyclingModes();
// Throws core::UnknownModeError whose message lists the known modes.
void checkMode(const std::string& mode);

class CullingModes
{
public:
    // `async`: the VisibilityGroup culls with asynchronous visibility (VisibilityGroup::setAsync).
    CullingModes(osg::Node* model, const std::string& mode, bool async = false);

    // The node to put in the viewer's scene: it holds the model, directly or under the group.
    osg::Group* node() const { return _slot.get(); }
    const std::string& mode() const { return _mode; }
    // Mode after `mode()` in cycling order (the first one after a mode outside the cycle).
    std::string nextMode() const;
    // Takes effect in the next update traversal; a mode the registry rejects keeps the old one.
    void requestMode(const std::string& mode);
    VisibilityGroup* visibilityGroup() const { return _group.get(); }

private:
    void apply(const std::string& mode);
    class ApplyRequest;

    osg::ref_ptr<osg::Node> _model;
    osg::ref_ptr<osg::Group> _slot;
    osg::ref_ptr<VisibilityGroup> _group;
    std::string _mode;
    std::string _requested;
    bool _async = false;
};
} // namespace osgVis::viewer
