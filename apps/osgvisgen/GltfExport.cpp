// SPDX-License-Identifier: MIT
#include "GltfExport.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/Switch>
#include <osg/Transform>
#include <osg/TriangleIndexFunctor>

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>

namespace osgVis::gen
{
namespace
{
struct TriangleIndices
{
    std::vector<std::uint32_t>* out = nullptr;
    void operator()(unsigned a, unsigned b, unsigned c) { out->insert(out->end(), {a, b, c}); }
};

// Adds `item` to one of the model's lists; its index there, which glTF's references use.
template <class T> int append(std::vector<T>& list, const T& item)
{
    list.push_back(item);
    return int(list.size() - 1);
}

class Exporter
{
public:
    tinygltf::Model model;

    Exporter() { model.buffers.emplace_back(); }

    // The glTF node of `node`, or -1 when it holds nothing drawable.
    int node(osg::Node& node)
    {
        tinygltf::Node out;
        out.name = node.getName();
        if (osg::Transform* transform = node.asTransform())
        {
            osg::Matrixd matrix;
            transform->computeLocalToWorldMatrix(matrix, nullptr);
            // note: OSG's row-vector layout is glTF's column-major array.
            out.matrix.assign(matrix.ptr(), matrix.ptr() + 16);
        }
        if (osg::Geode* geode = node.asGeode())
            out.mesh = mesh(*geode);
        if (osg::Group* group = node.asGroup())
            for (unsigned i = 0; i < group->getNumChildren(); ++i)
            {
                if (!active(*group, i))
                    continue;
                const int child = this->node(*group->getChild(i));
                if (child >= 0)
                    out.children.push_back(child);
            }
        if (out.mesh < 0 && out.children.empty())
            return -1;
        return append(model.nodes, out);
    }

private:
    static bool active(const osg::Group& group, unsigned child)
    {
        if (group.getChild(child)->getNodeMask() == 0)
            return false;
        if (const auto* toggle = dynamic_cast<const osg::Switch*>(&group))
            return toggle->getValue(child);
        if (const auto* lod = dynamic_cast<const osg::LOD*>(&group))
            return child == 0 && lod->getNumChildren() > 0; // the finest level only
        return true;
    }

    int mesh(osg::Geode& geode)
    {
        const auto cached = _meshes.find(&geode);
        if (cached != _meshes.end())
            return cached->second;
        tinygltf::Mesh out;
        out.name = geode.getName();
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
        {
            osg::Geometry* geometry = geode.getDrawable(i)->asGeometry();
            const auto* vertices = geometry ? dynamic_cast<const osg::Vec3Array*>(geometry->getVertexArray()) : nullptr;
            if (!vertices || vertices->empty())
                continue;
            osg::TriangleIndexFunctor<TriangleIndices> triangles;
            std::vector<std::uint32_t> indices;
            triangles.out = &indices;
            geometry->accept(triangles);
            if (indices.empty())
                continue;
            tinygltf::Primitive primitive;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            primitive.attributes["POSITION"] = positions(*vertices);
            primitive.indices = indexAccessor(indices);
            out.primitives.push_back(primitive);
        }
        const int index = out.primitives.empty() ? -1 : append(model.meshes, out);
        _meshes[&geode] = index;
        return index;
    }

    // An accessor of `count` elements over `size` bytes, which it appends to the one buffer as a
    // new buffer view (4-byte aligned); the caller adds it to the model (append).
    tinygltf::Accessor viewAccessor(const void* bytes, std::size_t size, std::size_t count, int target,
                                    int componentType, int type)
    {
        std::vector<unsigned char>& data = model.buffers[0].data;
        data.resize((data.size() + 3) / 4 * 4);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = size;
        view.target = target;
        data.insert(data.end(), static_cast<const unsigned char*>(bytes),
                    static_cast<const unsigned char*>(bytes) + size);
        tinygltf::Accessor accessor;
        accessor.bufferView = append(model.bufferViews, view);
        accessor.componentType = componentType;
        accessor.type = type;
        accessor.count = count;
        return accessor;
    }

    int positions(const osg::Vec3Array& vertices)
    {
        tinygltf::Accessor accessor =
            viewAccessor(vertices.getDataPointer(), vertices.size() * sizeof(osg::Vec3), vertices.size(),
                         TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
        accessor.minValues.assign(3, std::numeric_limits<double>::max());
        accessor.maxValues.assign(3, std::numeric_limits<double>::lowest());
        for (const osg::Vec3& v : vertices)
            for (int c = 0; c < 3; ++c)
            {
                accessor.minValues[std::size_t(c)] = std::min(accessor.minValues[std::size_t(c)], double(v[c]));
                accessor.maxValues[std::size_t(c)] = std::max(accessor.maxValues[std::size_t(c)], double(v[c]));
            }
        return append(model.accessors, accessor);
    }

    int indexAccessor(const std::vector<std::uint32_t>& indices)
    {
        return append(model.accessors, viewAccessor(indices.data(), indices.size() * sizeof(std::uint32_t),
                                                    indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER,
                                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR));
    }

    std::map<const osg::Geode*, int> _meshes;
};

bool endsWith(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}
} // namespace

bool writeGltf(osg::Node& root, const std::string& path, std::string& error)
{
    Exporter exporter;
    const int top = exporter.node(root);
    if (top < 0)
    {
        error = "the scene has no triangles to write";
        return false;
    }
    // OSG's Z-up into glTF's Y-up: (x, y, z) → (x, z, -y), exactly (a column-major matrix of 0 and ±1).
    tinygltf::Node yUp;
    yUp.name = "Z-up to glTF Y-up";
    yUp.matrix = {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    yUp.children = {top};
    tinygltf::Scene scene;
    scene.nodes = {append(exporter.model.nodes, yUp)};
    exporter.model.scenes.push_back(scene);
    exporter.model.defaultScene = 0;
    exporter.model.asset.version = "2.0";
    exporter.model.asset.generator = "osgvisgen";
    exporter.model.buffers[0].data.resize((exporter.model.buffers[0].data.size() + 3) / 4 * 4);

    tinygltf::TinyGLTF writer;
    const bool binary = endsWith(path, ".glb") || endsWith(path, ".GLB");
    if (!writer.WriteGltfSceneToFile(&exporter.model, path, true, true, !binary, binary))
    {
        error = "cannot write '" + path + "'";
        return false;
    }
    return true;
}
} // namespace osgVis::gen
