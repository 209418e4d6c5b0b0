#pragma once
// Where the viewer's scene and walk come from: a model file (with the walk beside it, a walk
// given by --walk, or an automatic orbit), a baked `.pvs` file (the model it names, with its baked
// cell-portal data registered for the cellportal modes) or a generated scene with its own walk.
#include "Options.h"

#include <osgVis/SceneExtractor>
#include <osgVis/core/Walk.h>

#include <osg/Node>

#include <stdexcept>
#include <string>

namespace osgVis::viewer
{
struct SceneError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct ViewerScene
{
    osg::ref_ptr<osg::Node> model;
    // The model's objects in the adapter's numbering (ids match a VisibilityGroup holding `model`).
    osg::ref_ptr<ExtractedScene> objects;
    core::Walk walk;             // size already overridden by --size
    std::string name;            // for messages and reports
    std::string walkSource;      // "path.walk", "generated" or "automatic orbit"
};

// Throws SceneError with a message that names the file at fault (unreadable model, empty scene,
// malformed walk with the parser's line message). For a `.pvs` scene it prints to stderr whether
// the baked data are trusted (and why not).
ViewerScene loadViewerScene(const ViewerOptions& options);

} // namespace osgVis::viewer
