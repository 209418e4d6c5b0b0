// SPDX-License-Identifier: MIT
#pragma once
// A minimal glTF 2.0 writer for generated scenes, so that a renderer reading glTF itself
// (osgvisrawgl) and OSG reading it through osgVis's plugin can be compared on them
// (docs/visapi.md, "A renderer that is not OSG"). It keeps what culling needs: the node hierarchy
// (groups and transforms as glTF nodes with their matrices), each Geode a mesh (shared by every
// parent) and each of its Geometries one triangle primitive (positions and the triangles OSG draws,
// as 32-bit indices). Nothing else: no materials (glTF's default one), normals, colours, textures,
// or osgVis marker semantics (occluders, cells, portals), and inactive Switch/LOD children are
// left out. OSG's Z-up scene is rotated into glTF's Y-up, so the glTF plugin (which rotates back)
// gives the scene its old axes.
#include <osg/Node>

#include <string>

namespace osgVis::gen
{
// Writes `root` to `path` (.glb binary, otherwise .gltf JSON with the buffer embedded). Returns
// false with `error` set when nothing drawable was found or the file cannot be written.
bool writeGltf(osg::Node& root, const std::string& path, std::string& error);
} // namespace osgVis::gen
