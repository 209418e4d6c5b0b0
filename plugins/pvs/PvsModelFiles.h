// SPDX-License-Identifier: MIT
#pragma once
// Where the model of a .pvs file lies on disk: the path the file names (relative to the .pvs's
// folder, then as given, then on osgDB's data path), or for a corrupt .pvs the model saved beside it.
#include <osgDB/Options>

#include <string>

namespace osgVis::pvsplugin
{
// The existing file `modelPath` (as stored in the .pvs at `pvsFile`) refers to, or "".
std::string findNamedModel(const std::string& modelPath, const std::string& pvsFile, const osgDB::Options* options);
// <stem>.osgb, .osgt, .ive, .osg beside `pvsFile`, the first that exists, or "".
std::string findModelBeside(const std::string& pvsFile);
// `modelFile` as a .pvs at `pvsFile` names it: relative to the .pvs's folder, so both can move together.
std::string modelPathFromPvs(const std::string& modelFile, const std::string& pvsFile);
} // namespace osgVis::pvsplugin
