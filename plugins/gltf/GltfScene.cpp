// SPDX-License-Identifier: MIT
#include "GltfScene.h"

#include "GltfMaterials.h"
#include "GltfMeshes.h"

#include <osgVis/gltf/GltfAccessors.h>
#include <osgVis/gltf/GltfError.h>

#include <osg/MatrixTransform>
#include <osg/ValueObject>

#include <map>
#include <vector>

namespace osgVis::gltfplugin
{
using gltf::checkReference;
using gltf::GltfError;

namespace
{
osg::Matrixd nodeMatrix(const tinygltf::Node& node, int nodeIndex)
{
    gltf::checkNodeTransform(node, nodeIndex);
    // note: glTF's column-major array is exactly the memory layout of OSG's row-vector matrix.
    if (!node.matrix.empty())
        return osg::Matrixd(node.matrix.data());
    osg::Matrixd matrix;
    if (!node.scale.empty())
        matrix.postMultScale(osg::Vec3d(node.scale[0], node.scale[1], node.scale[2]));
    if (!node.rotation.empty())
        matrix.postMultRotate(osg::Quat(node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]));
    if (!node.translation.empty())
        matrix.postMultTranslate(osg::Vec3d(node.translation[0], node.translation[1], node.translation[2]));
    return matrix;
}

class SceneBuilder
{
public:
    SceneBuilder(const tinygltf::Model& model, const std::string& fileName, const osgDB::Options* options)
        : _model(model), _materials(model, fileName, options), _state(model.nodes.size(), State::Unvisited),
          _built(model.nodes.size())
    {
    }

    osg::ref_ptr<osg::Node> node(int nodeIndex, int parentIndex)
    {
        checkReference(parentIndex < 0 ? std::string("the scene") : "node " + std::to_string(parentIndex), "node",
                       nodeIndex, _model.nodes.size());
        const std::size_t i = std::size_t(nodeIndex);
        if (_state[i] == State::InProgress)
            throw GltfError("node " + std::to_string(nodeIndex) + " is its own ancestor (a cycle through node " +
                            std::to_string(parentIndex) + ")");
        if (_state[i] == State::Done)
            return _built[i];
        _state[i] = State::InProgress;
        const tinygltf::Node& source = _model.nodes[i];
        osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform(nodeMatrix(source, nodeIndex));
        transform->setName(source.name.empty() ? "node" + std::to_string(nodeIndex) : source.name);
        // The glTF node index, so that a renderer can name an object by its glTF node path whatever
        // the names are (apps/common/GltfIdentity.h, docs/visapi.md).
        transform->setUserValue(GltfNodeKey, nodeIndex);
        if (source.mesh >= 0)
            transform->addChild(mesh(source.mesh).get());
        for (int child : source.children)
            transform->addChild(node(child, nodeIndex).get());
        _state[i] = State::Done;
        _built[i] = transform;
        return transform;
    }

private:
    osg::ref_ptr<osg::Geode> mesh(int meshIndex)
    {
        osg::ref_ptr<osg::Geode>& cached = _meshes[meshIndex];
        if (!cached)
            cached = buildMesh(_model, meshIndex, _materials);
        return cached;
    }

    enum class State
    {
        Unvisited,
        InProgress,
        Done
    };
    const tinygltf::Model& _model;
    MaterialBuilder _materials;
    std::vector<State> _state;
    std::vector<osg::ref_ptr<osg::Node>> _built;
    std::map<int, osg::ref_ptr<osg::Geode>> _meshes;
};

// Nodes that are no node's child: the roots when the file has no scene.
std::vector<int> parentlessNodes(const tinygltf::Model& model)
{
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes)
        for (int child : node.children)
            if (child >= 0 && std::size_t(child) < model.nodes.size())
                isChild[std::size_t(child)] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (!isChild[i])
            roots.push_back(int(i));
    return roots;
}
} // namespace

osg::ref_ptr<osg::Group> buildScene(const tinygltf::Model& model, const std::string& fileName,
                                    const osgDB::Options* options)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    std::vector<int> roots;
    if (!model.scenes.empty() && model.defaultScene >= int(model.scenes.size()))
        throw GltfError("the default scene is " + std::to_string(model.defaultScene) + ", but there are " +
                        std::to_string(model.scenes.size()) + " scenes");
    if (!model.scenes.empty())
    {
        const tinygltf::Scene& scene = model.scenes[std::size_t(std::max(model.defaultScene, 0))];
        roots = scene.nodes;
        root->setName(scene.name.empty() ? fileName : scene.name);
    }
    else
    {
        roots = parentlessNodes(model);
        root->setName(fileName);
    }
    SceneBuilder builder(model, fileName, options);
    for (int node : roots)
        root->addChild(builder.node(node, -1).get());
    return root;
}
} // namespace osgVis::gltfplugin
