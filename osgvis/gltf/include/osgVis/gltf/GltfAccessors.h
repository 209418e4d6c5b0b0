// SPDX-License-Identifier: MIT
#pragma once
// Validated reading of glTF accessors: the accessor, its buffer view and buffer, the component
// type, the element count and stride are all checked against the bytes that exist before any is
// read, so a malformed file gives a GltfError naming the accessor, never an out-of-range read.
// Shared by the osgdb_gltf plugin and osgvisrawgl (tinygltf only, no OSG).
#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace osgVis::gltf
{
// An accessor's elements as floats, `components` per element (normalized integer types are mapped
// to [0,1] / [-1,1] as glTF specifies). `componentTypes` lists the accepted TINYGLTF_COMPONENT_TYPE_*
// values; `usage` names the attribute in messages ("POSITION").
struct FloatElements
{
    std::vector<float> values;
    std::size_t count = 0;
    int components = 0;
};
FloatElements readFloatAccessor(const tinygltf::Model& model, int accessorIndex, const std::vector<int>& allowedTypes,
                                const std::vector<int>& componentTypes, const char* usage);

// An index accessor (SCALAR unsigned byte/short/int) as 32-bit indices, each checked to be below
// `vertexCount`.
std::vector<std::uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessorIndex, std::size_t vertexCount);

// The bytes [begin, begin + size) of buffer view `bufferViewIndex` after checking that they lie in
// its buffer (images stored in a .glb's binary chunk).
struct ByteRange
{
    const unsigned char* data = nullptr;
    std::size_t size = 0;
};
ByteRange bufferViewBytes(const tinygltf::Model& model, int bufferViewIndex);

// The sizes of node `nodeIndex`'s own transform, checked before either reader composes it: a
// matrix of 16 values, else (where given) a scale of 3, a rotation of 4 and a translation of 3.
void checkNodeTransform(const tinygltf::Node& node, int nodeIndex);
} // namespace osgVis::gltf
