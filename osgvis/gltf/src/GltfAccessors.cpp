// SPDX-License-Identifier: MIT
// The validated glTF accessor reader (and node transform check) shared by the osgdb_gltf plugin and
// osgvisrawgl.
#include <osgVis/gltf/GltfAccessors.h>

#include <osgVis/gltf/GltfError.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

namespace osgVis::gltf
{
namespace
{
// A bound on the floats one accessor may expand to, so a forged count cannot ask for terabytes.
constexpr std::size_t maxAccessorValues = std::size_t(1) << 28;

std::string accessorName(int index) { return "accessor " + std::to_string(index); }

std::size_t componentSize(int componentType)
{
    switch (componentType)
    {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

int componentCount(int type)
{
    switch (type)
    {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    default:
        return 0;
    }
}

// a + b ≤ limit without overflow.
bool fits(std::size_t a, std::size_t b, std::size_t limit) { return a <= limit && b <= limit - a; }

// Checked view of an accessor's elements: `data` null means the accessor has no buffer view
// (all zeros, as glTF specifies).
struct ElementView
{
    const unsigned char* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

ElementView viewAccessor(const tinygltf::Model& model, int accessorIndex, const char* usage)
{
    checkReference(usage, "accessor", accessorIndex, model.accessors.size());
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(accessorIndex)];
    const std::string name = accessorName(accessorIndex) + " (" + usage + ")";
    if (accessor.sparse.isSparse)
        throw GltfError(name + " is sparse, which is not supported");
    ElementView view;
    view.componentType = accessor.componentType;
    view.components = componentCount(accessor.type);
    view.normalized = accessor.normalized;
    view.count = accessor.count;
    const std::size_t size = componentSize(accessor.componentType);
    if (size == 0)
        throw GltfError(name + " has invalid component type " + std::to_string(accessor.componentType));
    if (view.components == 0)
        throw GltfError(name + " has type " + std::to_string(accessor.type) + ", expected SCALAR or VEC2/3/4");
    if (view.count > maxAccessorValues / std::size_t(view.components))
        throw GltfError(name + " has an implausible count " + std::to_string(view.count));
    if (accessor.bufferView < 0)
        return view;
    checkReference(name, "buffer view", accessor.bufferView, model.bufferViews.size());
    const ByteRange bytes = bufferViewBytes(model, accessor.bufferView);
    const std::size_t elementSize = size * std::size_t(view.components);
    const std::size_t byteStride = model.bufferViews[std::size_t(accessor.bufferView)].byteStride;
    if (byteStride != 0 && byteStride < elementSize)
        throw GltfError(name + ": buffer view " + std::to_string(accessor.bufferView) + " has byte stride " +
                        std::to_string(byteStride) + ", smaller than the element size " + std::to_string(elementSize));
    view.stride = byteStride != 0 ? byteStride : elementSize;
    if (view.count > 0)
    {
        // note: the last element needs only elementSize bytes, not a whole stride. A stride longer than
        // the view with two or more elements cannot fit (and could overflow the product below).
        const bool strideFits = view.count == 1 || view.stride <= bytes.size;
        const std::size_t lastStart = strideFits ? (view.count - 1) * view.stride : 0;
        if (!strideFits || !fits(accessor.byteOffset, lastStart, bytes.size) ||
            !fits(accessor.byteOffset + lastStart, elementSize, bytes.size))
            throw GltfError(accessorName(accessorIndex) + " reads past the end of buffer view " +
                            std::to_string(accessor.bufferView));
    }
    view.data = bytes.data + accessor.byteOffset;
    return view;
}

template <typename T> T load(const unsigned char* at)
{
    T value;
    std::memcpy(&value, at, sizeof(T));
    return value;
}

float readComponent(const unsigned char* at, int componentType, bool normalized)
{
    switch (componentType)
    {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? float(load<std::uint8_t>(at)) / 255.0f : float(load<std::uint8_t>(at));
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return normalized ? std::max(float(load<std::int8_t>(at)) / 127.0f, -1.0f) : float(load<std::int8_t>(at));
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return normalized ? float(load<std::uint16_t>(at)) / 65535.0f : float(load<std::uint16_t>(at));
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return normalized ? std::max(float(load<std::int16_t>(at)) / 32767.0f, -1.0f) : float(load<std::int16_t>(at));
    default:
        return float(load<std::uint32_t>(at));
    }
}

std::string typeList(const std::vector<int>& types)
{
    std::string list;
    for (int type : types)
        list += (list.empty() ? "" : "/") + std::to_string(type);
    return list;
}
} // namespace

ByteRange bufferViewBytes(const tinygltf::Model& model, int bufferViewIndex)
{
    if (bufferViewIndex < 0 || std::size_t(bufferViewIndex) >= model.bufferViews.size())
        throw GltfError("buffer view " + std::to_string(bufferViewIndex) + " does not exist (there are " +
                        std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(bufferViewIndex)];
    checkReference("buffer view " + std::to_string(bufferViewIndex), "buffer", view.buffer, model.buffers.size());
    const std::vector<unsigned char>& buffer = model.buffers[std::size_t(view.buffer)].data;
    if (!fits(view.byteOffset, view.byteLength, buffer.size()))
        throw GltfError("buffer view " + std::to_string(bufferViewIndex) + " reads past the end of buffer " +
                        std::to_string(view.buffer) + " (bytes " + std::to_string(view.byteOffset) + "+" +
                        std::to_string(view.byteLength) + " of " + std::to_string(buffer.size()) + ")");
    return {buffer.data() + view.byteOffset, view.byteLength};
}

FloatElements readFloatAccessor(const tinygltf::Model& model, int accessorIndex, const std::vector<int>& allowedTypes,
                                const std::vector<int>& componentTypes, const char* usage)
{
    const ElementView view = viewAccessor(model, accessorIndex, usage);
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(accessorIndex)];
    if (std::find(allowedTypes.begin(), allowedTypes.end(), accessor.type) == allowedTypes.end())
        throw GltfError(accessorName(accessorIndex) + " (" + usage + ") has type " + std::to_string(accessor.type) +
                        ", expected " + typeList(allowedTypes));
    if (std::find(componentTypes.begin(), componentTypes.end(), view.componentType) == componentTypes.end())
        throw GltfError(accessorName(accessorIndex) + " (" + usage + ") has component type " +
                        std::to_string(view.componentType) + ", expected " + typeList(componentTypes));
    FloatElements elements;
    elements.count = view.count;
    elements.components = view.components;
    elements.values.assign(view.count * std::size_t(view.components), 0.0f);
    if (!view.data)
        return elements;
    const std::size_t size = componentSize(view.componentType);
    for (std::size_t i = 0; i < view.count; ++i)
        for (int c = 0; c < view.components; ++c)
            elements.values[i * std::size_t(view.components) + std::size_t(c)] =
                readComponent(view.data + i * view.stride + std::size_t(c) * size, view.componentType, view.normalized);
    return elements;
}

std::vector<std::uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessorIndex, std::size_t vertexCount)
{
    const ElementView view = viewAccessor(model, accessorIndex, "indices");
    if (view.components != 1)
        throw GltfError(accessorName(accessorIndex) + " (indices) is not SCALAR");
    if (view.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        view.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        view.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw GltfError(accessorName(accessorIndex) + " (indices) has component type " +
                        std::to_string(view.componentType) + ", expected unsigned byte, short or int");
    std::vector<std::uint32_t> indices(view.count, 0);
    // note: an accessor without buffer view reads as zeros, which must still name a vertex
    if (!view.data && view.count != 0 && vertexCount == 0)
        throw GltfError("index 0 at position 0 of " + accessorName(accessorIndex) +
                        " is out of range (the primitive has 0 vertices)");
    if (!view.data)
        return indices;
    for (std::size_t i = 0; i < view.count; ++i)
    {
        const unsigned char* at = view.data + i * view.stride;
        const std::uint32_t index = view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? load<std::uint8_t>(at)
                                    : view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                        ? load<std::uint16_t>(at)
                                        : load<std::uint32_t>(at);
        if (index >= vertexCount)
            throw GltfError("index " + std::to_string(index) + " at position " + std::to_string(i) + " of " +
                            accessorName(accessorIndex) + " is out of range (the primitive has " +
                            std::to_string(vertexCount) + " vertices)");
        indices[i] = index;
    }
    return indices;
}

void checkNodeTransform(const tinygltf::Node& node, int nodeIndex)
{
    const std::string where = "node " + std::to_string(nodeIndex);
    const auto check = [&where](const std::vector<double>& values, const char* what, std::size_t size)
    {
        if (!values.empty() && values.size() != size)
            throw GltfError(where + " has " + what + " of " + std::to_string(values.size()) + " values, expected " +
                            std::to_string(size));
    };
    if (!node.matrix.empty())
    {
        check(node.matrix, "a matrix", 16);
        return; // a matrix stands for the rest, which neither reader reads then
    }
    check(node.scale, "a scale", 3);
    check(node.rotation, "a rotation", 4);
    check(node.translation, "a translation", 3);
}
} // namespace osgVis::gltf
