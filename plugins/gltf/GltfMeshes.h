// SPDX-License-Identifier: MIT
#pragma once
// A glTF mesh as an osg::Geode of one osg::Geometry per primitive: POSITION, NORMAL (smooth normals
// generated when absent for triangle modes), TEXCOORD_0, COLOR_0, indices or none, in any of the
// seven primitive modes. Names: the Geode takes the mesh's name ("mesh<i>" when unnamed), each
// Geometry "<geode name>#<primitive index>", so extracted objects have stable ids; each Geometry also
// carries its primitive index as a user value (GltfPrimitiveKey).
#include "GltfMaterials.h"

#include <osg/Geode>
#include <tiny_gltf.h>

namespace osgVis::gltfplugin
{
// User value (int) on each primitive's Geometry: its index in the mesh's primitive list.
// apps/common/GltfIdentity.cpp reads it under the same name.
inline constexpr const char* GltfPrimitiveKey = "osgVis.gltf.primitive";

osg::ref_ptr<osg::Geode> buildMesh(const tinygltf::Model& model, int meshIndex, MaterialBuilder& materials);
} // namespace osgVis::gltfplugin
