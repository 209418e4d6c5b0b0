// SPDX-License-Identifier: MIT
#pragma once
// Top-down plan of the scene for checking a culling mode by eye: every object's footprint coloured
// drawn (green), culled inside the frustum (red) or outside the frustum (grey), plus the frustum
// wedge and the eye of the observed camera; over it, what a module with a spatial structure recorded
// about the same query (DebugRecordLayers). Drawn by an orthographic HUD camera looking down the
// scene's z axis (the generator's and OSG's up axis).
#include "CullingModes.h"
#include "DebugRecordLayers.h"

#include <osgVis/SceneExtractor>
#include <osgVis/core/module/ModuleChain.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <osg/Camera>
#include <osg/Geometry>
#include <osg/observer_ptr>
#include <osgText/Text>

#include <string>

namespace osgVis::viewer
{
class DebugMap
{
public:
    // `objects` gives the footprints; `modes` the mode whose answer colours the map ("osg": OSG's
    // frustum test; else the mode's chain run on the VisibilityGroup's own extraction, so that ids
    // and occluders are the group's).
    DebugMap(const ExtractedScene& objects, const CullingModes& modes);

    // Add this to the scene root, outside the culled model.
    osg::Camera* camera() const { return _camera.get(); }
    // The viewer's scene: the culled model of `modes` beside this map's camera.
    osg::ref_ptr<osg::Group> sceneWithMap(const CullingModes& modes) const;
    // The camera whose view the map explains (its view, projection and viewport are read each frame).
    void setObservedCamera(osg::Camera* camera) { _observed = camera; }
    void setEnabled(bool enabled);
    bool enabled() const { return _camera->getNodeMask() != 0; }
    // Where the map draws in the window, in pixels.
    void setViewport(int x, int y, int width, int height);

private:
    class Refresh;
    void refresh(double time);
    void buildGeometry();
    void fitProjection();
    void followMode();
    void classify(const core::View& view);

    osg::ref_ptr<const ExtractedScene> _objects;
    const CullingModes& _modes;
    std::string _mode;                              // mode of _chain
    osg::ref_ptr<const ExtractedScene> _chainScene; // the group's extraction _chain works on
    core::ModuleChain _chain;                       // empty: frustum test only
    core::VisibleSet _visible;
    core::DebugRecord _record; // what _chain's stages recorded about their last query
    DebugRecordLayers _recordLayers;
    std::vector<core::ObjectId> _drawOrder; // largest footprint first, so small ones stay visible

    osg::ref_ptr<osg::Camera> _camera;
    osg::observer_ptr<osg::Camera> _observed;
    osg::ref_ptr<osg::Geometry> _fills, _outlines, _frustum, _eye;
    osg::ref_ptr<osgText::Text> _label;
};
} // namespace osgVis::viewer
