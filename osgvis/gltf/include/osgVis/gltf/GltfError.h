// SPDX-License-Identifier: MIT
#pragma once
// What is wrong with a glTF model, in words: thrown by the shared accessor reader (GltfAccessors.h)
// and by the osgdb_gltf plugin, which prefixes "gltf: <file>: " and hands it to osgDB as the
// ReadResult's message; osgvisrawgl turns it into its SceneError.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace osgVis::gltf
{
struct GltfError : public std::runtime_error
{
    explicit GltfError(const std::string& what) : std::runtime_error(what) {}
};

// Every index a glTF file holds is checked before use: "<referrer> refers to <kind> <index>, but
// there are <count>" when it names nothing.
inline void checkReference(const std::string& referrer, const char* kind, int index, std::size_t count)
{
    if (index < 0 || std::size_t(index) >= count)
        throw GltfError(referrer + " refers to " + kind + " " + std::to_string(index) + ", but there are " +
                        std::to_string(count));
}
} // namespace osgVis::gltf
