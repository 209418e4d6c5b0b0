// SPDX-License-Identifier: MIT
#pragma once
// Live scene edits during an interactive walk (keys b and B / Delete): drop a building box a few
// metres ahead of the eye, or delete the building nearest the centre of the view. The edits change
// the model graph itself; `onChange` then tells the culling (VisibilityGroup::dirtyScene), which
// re-extracts with stable ids and hands the modules the change (sceneReplaced).
#include <osgVis/SceneExtractor>

#include <osg/Group>
#include <osg/Matrixd>

#include <functional>
#include <string>

namespace osgVis::viewer
{
class BuildingTool
{
public:
    // Dropped buildings go into a group added under `model` (which must be an osg::Group for drops;
    // removal works on any model). Their base is the model's lowest point.
    BuildingTool(osg::Node& model, std::function<void()> onChange);

    // A box (6 x 6 m, 10 m high, named "dropped building") whose near face stands `ahead` metres in
    // front of the eye of `view` (world → eye), along the horizontal view direction. Null when the
    // model is no group.
    osg::Node* dropAhead(const osg::Matrixd& view, double ahead = 5.0);

    // Deletes (from its geode) the building whose bounds centre is nearest the view's centre line, in
    // front of the eye: objects named "building" or "dropped building", else any object but the
    // ground ("street", "pavement"). Returns the deleted object's name, empty when none qualifies.
    std::string removeNearestCentre(const osg::Matrixd& view);

    osg::Group* droppedGroup() const { return _dropped.get(); }

private:
    osg::ref_ptr<osg::Node> _model;
    osg::ref_ptr<osg::Group> _dropped;
    std::function<void()> _onChange;
    double _groundZ = 0.0;
};
} // namespace osgVis::viewer
