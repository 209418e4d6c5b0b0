// SPDX-License-Identifier: MIT
#pragma once
// The canonical identity of an object of a glTF model read by osgVis's glTF plugin: the glTF node
// indices from the scene root down to the node holding the mesh, then the primitive index, e.g.
// "n0/n3/n12#p1". osgvisrawgl (which reads glTF itself, without OSG) computes the same string for the
// same (node instance path, primitive), so visible sets of the two renderers compare object by
// object (docs/visapi.md, "A renderer that is not OSG"). The indices come from the user values the
// plugin sets ("osgVis.gltf.node" on each node's MatrixTransform, "osgVis.gltf.primitive" on each
// Geometry), not from names, which glTF files need not make unique.
#include <osgVis/SceneExtractor>

#include <string>

namespace osgVis::apps
{
// The identity of `ref`, or "" when its path carries no glTF node index or its drawable no primitive
// index (a model that did not come from the glTF plugin).
std::string gltfIdentity(const ObjectRef& ref);
} // namespace osgVis::apps
