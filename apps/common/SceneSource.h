// SPDX-License-Identifier: MIT
#pragma once
// Where an app's scene and walk come from (osgvisviewer and osgvisbench load them the same way): a
// model file (with the walk beside it, a walk given by --walk, or an automatic walk through its free
// space), a baked `.pvs` file (the model it names, with its baked cell-portal data registered for
// the cellportal modes) or a generated scene with its own walk. `--walk auto` and `--walk orbit`
// ask for the automatic walk (FreeSpaceWalk.h) or an orbit around the model (OrbitWalk.h) whatever
// the scene has.

#include <osgVis/SceneExtractor>
#include <osgVis/core/scene/Walk.h>

#include <osg/Node>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace osgVis::apps
{
struct SceneError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// What to load, as the apps' command lines give it.
struct SceneRequest
{
    std::string scenePath;            // any OSG-readable model or a .pvs file; ignored with generateKind
    std::string generateKind;         // a generator kind ("office", "city", ...) or empty
    std::uint64_t triangles = 200000; // size knob of a generated scene
    std::uint32_t seed = 1;           // seed of a generated scene or of a random walk
    std::string forestLayout;         // with generateKind "forest": single, line or dense (empty: dense)
    // A walk file, "auto" (through the model's free space), "random" (random gazes, seeded by `seed`,
    // from jittered eyes of that free space), "orbit" (around it), or empty: SCENE's
    // stem + ".walk" if there is one, the generator's walk with generateKind, else "auto" (an orbit
    // when no eye can be found in the model).
    std::string walkPath;
    unsigned width = 0, height = 0;   // pixels; 0 keeps the walk's own size
};

struct LoadedScene
{
    osg::ref_ptr<osg::Node> model;
    // The model's objects in the adapter's numbering (ids match a VisibilityGroup holding `model`).
    osg::ref_ptr<ExtractedScene> objects;
    core::Walk walk;             // size already overridden by --size
    std::string name;            // for messages and reports
    std::string walkSource;      // "path.walk", "generated", "automatic walk (...)" or "automatic orbit"
};

// Throws SceneError with a message that names the file at fault (unreadable model, empty scene,
// malformed walk with the parser's line message). For a `.pvs` scene it prints to stderr whether
// the baked data are trusted (and why not).
LoadedScene loadScene(const SceneRequest& request);

} // namespace osgVis::apps
