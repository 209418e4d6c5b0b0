#pragma once
// What is wrong with a glTF model, in words; the reader prefixes "gltf: <file>: " and hands it to
// osgDB as the ReadResult's message.
#include <stdexcept>
#include <string>

namespace osgVis::gltfplugin
{
struct GltfError : public std::runtime_error
{
    explicit GltfError(const std::string& what) : std::runtime_error(what) {}
};
} // namespace osgVis::gltfplugin
