// SPDX-License-Identifier: MIT
#pragma once
// What every osgvispvs bake does with files: refuse an output it could not write before the long
// work, name the model relative to the .pvs, and read and extract the model as the apps do.
#include "PvsToolOptions.h"

#include <osgVis/SceneExtractor>

#include <osg/Node>

#include <stdexcept>
#include <string>

namespace osgVis::pvstool
{
// A file the tool cannot produce; main prints it and exits with 1.
struct ToolError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// Fails before a long bake, not after it: the output's folder must exist and take a new file.
void checkWritable(const std::string& path, const char* what);
// The model as the .pvs names it: relative to the .pvs's folder, so both can move together.
std::string modelPathFromPvs(const std::string& modelFile, const std::string& pvsFile);

struct LoadedModel
{
    osg::ref_ptr<osg::Node> model;
    osg::ref_ptr<ExtractedScene> extracted; // with triangles
};
// Checks the outputs (-o, --json) can be written, reads the model with osgDB, repairs it as the
// .pvs plugin and the apps do (so the bake sees the drawn scene) and extracts it with triangles.
// Throws ToolError for a missing or unreadable model or one without drawables.
// `workerRank`: an MPI rank other than 0, which writes no file (its machine may not even see the
// output's folder) and leaves the note on repairs to rank 0.
LoadedModel loadModelToBake(const PvsToolOptions& options, bool workerRank = false);
// The solid space `modelFile` states: a Quake 3 level's (.bsp) brushes and spawn points; nothing
// for other models. Throws ToolError for a level whose brushes cannot be read.
core::SolidSpace statedSolids(const std::string& modelFile);
} // namespace osgVis::pvstool
