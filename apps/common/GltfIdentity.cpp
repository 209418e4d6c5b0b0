// SPDX-License-Identifier: MIT
#include "GltfIdentity.h"

#include <osg/ValueObject>

namespace osgVis::apps
{
namespace
{
// note: the names plugins/gltf sets (GltfNodeKey in GltfScene.h, GltfPrimitiveKey in GltfMeshes.h).
constexpr const char* nodeKey = "osgVis.gltf.node";
constexpr const char* primitiveKey = "osgVis.gltf.primitive";
} // namespace

std::string gltfIdentity(const ObjectRef& ref)
{
    std::string identity;
    for (const osg::Node* node : ref.path)
    {
        int index = -1;
        if (node != ref.drawable.get() && node->getUserValue(nodeKey, index))
            identity += (identity.empty() ? "n" : "/n") + std::to_string(index);
    }
    int primitive = -1;
    if (identity.empty() || !ref.drawable || !ref.drawable->getUserValue(primitiveKey, primitive))
        return "";
    return identity + "#p" + std::to_string(primitive);
}
} // namespace osgVis::apps
