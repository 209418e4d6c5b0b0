// SPDX-License-Identifier: MIT
#pragma once
// What osgvisglfw shows: a model file or a built-in demo, placed under an osgVis::VisibilityGroup
// for a module chain, or left alone for OSG's own culling.
#include <osgVis/VisibilityGroup>

#include <osg/Node>

#include <stdexcept>
#include <string>

namespace osgVis::glfwapp
{
struct SceneError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// The name of the baseline mode: no osgVis node in the graph.
extern const char* const OsgMode;

struct CulledScene
{
    osg::ref_ptr<osg::Node> root;                  // what the viewer renders
    osg::ref_ptr<VisibilityGroup> visibilityGroup; // null in mode "osg"
};

// A wall, boxes in front of the wall and boxes hidden behind it (seen from the trackball's
// home, which looks along +y): frustum+octree culls the hidden ones.
osg::ref_ptr<osg::Node> demoScene();

// Throws SceneError naming the file when it is missing, no OSG plugin reads it or it draws nothing.
osg::ref_ptr<osg::Node> readModel(const std::string& path);

// Throws core::UnknownModeError listing "osg" and every registered module.
CulledScene cullWithMode(osg::Node* model, const std::string& mode);
} // namespace osgVis::glfwapp
