// SPDX-License-Identifier: MIT
#pragma once
// The node hierarchy of a glTF model as OSG nodes: the default scene (else scene 0, else every node
// that is no node's child), each glTF node an osg::MatrixTransform (its matrix or T·R·S) named
// after the node ("node<i>" when unnamed) and carrying its index as a user value (GltfNodeKey),
// meshes as shared Geodes (a mesh used by several nodes is one Geode with several parents). A node
// that is its own ancestor is an error.
#include <osg/Group>
#include <tiny_gltf.h>

#include <string>

namespace osgDB
{
class Options;
}

namespace osgVis::gltfplugin
{
// User value (int) on each node's MatrixTransform: the glTF node index. apps/common/GltfIdentity.cpp
// reads it under the same name.
inline constexpr const char* GltfNodeKey = "osgVis.gltf.node";

// The scene's root: a Group named after the scene (or `fileName`) holding the scene's root nodes.
osg::ref_ptr<osg::Group> buildScene(const tinygltf::Model& model, const std::string& fileName,
                                    const osgDB::Options* options);
} // namespace osgVis::gltfplugin
