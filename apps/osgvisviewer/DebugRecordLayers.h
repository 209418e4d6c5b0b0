// SPDX-License-Identifier: MIT
#pragma once
// The part of the debug map that shows what a module recorded about its last query
// (core::DebugRecord): its tree nodes as rectangles coloured by state (occluded red, visible or
// partly occluded green, outside the frustum grey), the occluders it used as thick blue outlines,
// and the eye's cell as a yellow rectangle, all flattened onto the map's z = 0 plane. Modules that
// record nothing leave every layer empty, so the map looks as it does without them.
#include <osgVis/core/scene/DebugRecord.h>

#include <osg/Geometry>

#include <string>
#include <vector>

namespace osgVis::viewer
{
class DebugRecordLayers
{
public:
    DebugRecordLayers();

    // The geometries to add to the map's geode (their render bins place them among the map's layers).
    std::vector<osg::Drawable*> drawables() const;
    // Redraws the layers from `record`.
    void update(const core::DebugRecord& record);
    // One line for the map's label explaining the colours; empty when the record is empty.
    const std::string& legend() const { return _legend; }

private:
    osg::ref_ptr<osg::Geometry> _nodeFills, _nodeOutlines, _occluders, _eyeCell;
    std::string _legend;
};
} // namespace osgVis::viewer
