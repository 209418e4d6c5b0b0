// SPDX-License-Identifier: MIT
#pragma once
// Parsing .gltf (JSON) or .glb (binary, told by its "glTF" magic) bytes with tinygltf. External
// buffers and images resolve against `baseDir`, then through osgDB's data file search (the options'
// database path list); images are kept encoded for OSG's image plugins to decode. tinygltf's errors
// become a GltfError, its warnings go to OSG_WARN. glTF 1.0 and required extensions (e.g.
// KHR_draco_mesh_compression) are rejected as not supported.
#include <tiny_gltf.h>

#include <string>

namespace osgDB
{
class Options;
}

namespace osgVis::gltfplugin
{
tinygltf::Model parseGltf(const std::string& bytes, const std::string& baseDir, const std::string& fileName,
                          const osgDB::Options* options);
} // namespace osgVis::gltfplugin
